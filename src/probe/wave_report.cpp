// wave_report.cpp - waves.csv and the summary's wave values from probes.csv (see wave_report.h).
#include "probe/wave_report.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "io/csv_table.h"
#include "probe/wave_analysis.h"
#include "probe/wave_bounds.h"

namespace cdmpm {

nlohmann::json wave_report(const Scene& scene, const std::string& probes_csv, const std::string& waves_csv) {
  nlohmann::json out = nlohmann::json::object();
  std::vector<const ProbeSpec*> gauges;
  for (const ProbeSpec& p : scene.probes)
    if (p.type == "wave_gauge") gauges.push_back(&p);
  if (gauges.empty()) return out;

  const WaveBounds bounds = wave_bounds(scene);
  const CsvTable probes = read_csv_table(probes_csv);
  const std::vector<double> t = probes.numbers("time");

  struct Row {
    std::string name;
    std::vector<double> where;
    double x;
    double earliest;
    GaugeReading reading;
  };
  std::vector<Row> rows;
  for (const ProbeSpec* g : gauges) {
    const std::vector<double> where = g->json.at("position").get<std::vector<double>>();
    const double earliest = bounds.earliest_arrival(where);
    rows.push_back({g->name, where, where.at(0), earliest, read_gauge(t, probes.numbers(g->name), earliest, bounds.floor)});
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.x < b.x; });

  std::ofstream csv(waves_csv, std::ios::trunc);
  if (!csv) throw std::runtime_error(waves_csv + ": cannot write");
  csv.precision(10);
  // Georeferenced: each gauge's map coordinates too (GeoreferenceSpec::map_point).
  const bool map = scene.georeference.given;
  csv << "gauge,x,amplitude,arrival_time,earliest_arrival,noise_floor," << (map ? "easting,northing," : "") << "reason\n";
  std::vector<double> xs, ts;
  double max_amplitude = 0;
  nlohmann::json pairs = nlohmann::json::array();
  const Row* prev = nullptr;
  for (const Row& r : rows) {
    const auto& crest = r.reading.crest;
    csv << r.name << ',' << r.x << ',';
    if (crest) csv << crest->amplitude << ',' << crest->time;
    else csv << ',';
    csv << ',' << r.earliest << ',' << r.reading.noise_floor << ',';
    if (map) {
      const std::array<double, 2> en = scene.georeference.map_point(r.where);
      csv << en[0] << ',' << en[1] << ',';
    }
    csv << (crest ? "" : "not arrived: " + r.reading.reason) << '\n';
    if (!crest) continue;
    xs.push_back(r.x);
    ts.push_back(crest->time);
    max_amplitude = std::max(max_amplitude, crest->amplitude);
    if (prev && crest->time > prev->reading.crest->time) {
      const double c = (r.x - prev->x) / (crest->time - prev->reading.crest->time);
      nlohmann::json pair = {{"from", prev->name}, {"to", r.name}, {"x_from", prev->x}, {"x_to", r.x}};
      if (bounds.possible_celerity(c)) pair["celerity"] = c;
      else pair.update({{"celerity", nullptr}, {"reason", "outside (0, 2 sqrt(g h_max)]"}});
      pairs.push_back(pair);
    }
    prev = &r;
  }
  const auto c = celerity_fit(xs, ts);
  out["max_amplitude"] = xs.empty() ? nlohmann::json(nullptr) : nlohmann::json(max_amplitude);
  out["celerity"] = c && bounds.possible_celerity(*c) ? nlohmann::json(*c) : nlohmann::json(nullptr);
  if (!c) out["celerity_reason"] = "fewer than two gauges with a crest";
  else if (!bounds.possible_celerity(*c)) out["celerity_reason"] = "outside (0, 2 sqrt(g h_max)]";
  out["celerity_pairs"] = pairs;
  out["wave_bounds"] = {{"h_max", bounds.h_max}, {"c_max", bounds.c_max}, {"noise_floor_min", bounds.floor},
                        {"bounded_source", bounds.bounded_source}};
  return out;
}

}  // namespace cdmpm
