// wave_report.cpp - waves.csv and the summary's wave values from probes.csv (see wave_report.h).
#include "probe/wave_report.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "io/csv_table.h"
#include "probe/wave_analysis.h"

namespace cdmpm {

nlohmann::json wave_report(const Scene& scene, const std::string& probes_csv, const std::string& waves_csv) {
  nlohmann::json out = nlohmann::json::object();
  std::vector<const ProbeSpec*> gauges;
  for (const ProbeSpec& p : scene.probes)
    if (p.type == "wave_gauge") gauges.push_back(&p);
  if (gauges.empty()) return out;

  const CsvTable probes = read_csv_table(probes_csv);
  const std::vector<double> t = probes.numbers("time");

  struct Row {
    std::string name;
    double x;
    std::optional<Crest> crest;
  };
  std::vector<Row> rows;
  for (const ProbeSpec* g : gauges) rows.push_back({g->name, g->json.at("position").at(0).get<double>(), first_crest(t, probes.numbers(g->name))});
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.x < b.x; });

  std::ofstream csv(waves_csv, std::ios::trunc);
  if (!csv) throw std::runtime_error(waves_csv + ": cannot write");
  csv.precision(10);
  csv << "gauge,x,amplitude,arrival_time\n";
  std::vector<double> xs, ts;
  double max_amplitude = 0;
  nlohmann::json pairs = nlohmann::json::array();
  const Row* prev = nullptr;
  for (const Row& r : rows) {
    csv << r.name << ',' << r.x << ',';
    if (!r.crest) {
      csv << "nan,nan\n";
      continue;
    }
    csv << r.crest->amplitude << ',' << r.crest->time << '\n';
    xs.push_back(r.x);
    ts.push_back(r.crest->time);
    max_amplitude = std::max(max_amplitude, r.crest->amplitude);
    if (prev && r.crest->time > prev->crest->time)
      pairs.push_back({{"from", prev->name}, {"to", r.name}, {"x_from", prev->x}, {"x_to", r.x},
                       {"celerity", (r.x - prev->x) / (r.crest->time - prev->crest->time)}});
    prev = &r;
  }
  const auto c = celerity_fit(xs, ts);
  out["max_amplitude"] = xs.empty() ? nlohmann::json(nullptr) : nlohmann::json(max_amplitude);
  out["celerity"] = c ? nlohmann::json(*c) : nlohmann::json(nullptr);
  out["celerity_pairs"] = pairs;
  return out;
}

}  // namespace cdmpm
