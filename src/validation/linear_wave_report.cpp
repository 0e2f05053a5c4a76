// linear_wave_report.cpp - gauge pairs against linear theory (see linear_wave_report.h).
#include "validation/linear_wave_report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/csv_table.h"
#include "probe/wave_analysis.h"
#include "validation/linear_dispersion.h"

namespace cdmpm {
namespace {

// Rows of JSON objects as CSV with the given columns in that order; null (a missing crest) is written as nan.
void write_csv(const std::string& path, const std::vector<std::string>& columns, const nlohmann::json& rows) {
  std::ostringstream csv;
  csv.precision(10);
  for (size_t c = 0; c < columns.size(); ++c) csv << (c ? "," : "") << columns[c];
  csv << '\n';
  for (const auto& row : rows) {
    for (size_t c = 0; c < columns.size(); ++c) {
      const nlohmann::json& v = row.at(columns[c]);
      csv << (c ? "," : "");
      if (v.is_string())
        csv << v.get<std::string>();
      else if (v.is_null())
        csv << "nan";
      else
        csv << v.get<double>();
    }
    csv << '\n';
  }
  std::ofstream file(path, std::ios::trunc);
  file << csv.str();
  if (!file) throw std::runtime_error(path + ": cannot write");
}

nlohmann::json crest_time(const std::optional<Crest>& c) { return c ? nlohmann::json(c->time) : nlohmann::json(nullptr); }
nlohmann::json crest_height(const std::optional<Crest>& c) { return c ? nlohmann::json(c->amplitude) : nlohmann::json(nullptr); }

// Every gauge's simulated first crest beside the Cauchy-Poisson solution of the released box.
nlohmann::json cauchy_poisson_rows(const std::vector<std::string>& names, const std::vector<double>& xs,
                                   const std::vector<double>& t, const std::vector<std::optional<Crest>>& crests,
                                   const LinearWaveOptions& options) {
  nlohmann::json rows = nlohmann::json::array();
  for (size_t i = 0; i < names.size(); ++i) {
    std::vector<double> eta =
        cauchy_poisson_box(xs[i], t, options.box->height, options.box->half_width, options.gravity, options.depth);
    if (options.wall_x) {
      const auto image = cauchy_poisson_box(2 * *options.wall_x - xs[i], t, options.box->height,
                                            options.box->half_width, options.gravity, options.depth);
      for (size_t j = 0; j < eta.size(); ++j) eta[j] += image[j];
    }
    const auto lin = first_crest(t, eta);
    rows.push_back(nlohmann::json{{"gauge", names[i]}, {"x", xs[i]}, {"arrival_time", crest_time(crests[i])},
                                  {"amplitude", crest_height(crests[i])}, {"linear_arrival_time", crest_time(lin)},
                                  {"linear_amplitude", crest_height(lin)}});
  }
  return rows;
}

}  // namespace

nlohmann::json linear_wave_report(const std::string& out_dir, const LinearWaveOptions& options) {
  if (!(options.depth > 0)) throw std::runtime_error("linear wave report: the depth must be positive");
  const CsvTable waves = read_csv_table(out_dir + "/waves.csv");
  const CsvTable probes = read_csv_table(out_dir + "/probes.csv");
  const std::vector<std::string> names = waves.strings("gauge");
  const std::vector<double> xs = waves.numbers("x");
  if (names.size() < 2) throw std::runtime_error(waves.path + ": fewer than two gauges");
  for (size_t i = 0; i + 1 < xs.size(); ++i)
    if (!(xs[i + 1] > xs[i])) throw std::runtime_error(waves.path + ": gauges not in increasing x");
  if (options.wall_x && !(*options.wall_x >= xs.back()))
    throw std::runtime_error("linear wave report: the wall (x = " + std::to_string(*options.wall_x) +
                             " m) must lie beyond the last gauge (x = " + std::to_string(xs.back()) + " m)");

  // The record is sampled every probe interval, and once more at the run's end if that falls between two samples:
  // the linear propagation takes the evenly spaced samples.
  std::vector<double> t = probes.numbers("time");
  if (t.size() < 3) throw std::runtime_error(probes.path + ": fewer than three samples");
  const double dt = t[1] - t[0];
  size_t n = 1;
  while (n < t.size() && std::abs(t[n] - t[n - 1] - dt) <= 1e-3 * dt) ++n;
  if (n + 1 < t.size() || (n < t.size() && !(t[n] - t[n - 1] < dt)))
    throw std::runtime_error(probes.path + ": samples not evenly spaced in time (row " + std::to_string(n + 2) +
                             "); the linear propagation needs a uniform record");
  t.resize(n);
  // Each gauge's evenly spaced record and its simulated first crest, read and found once.
  std::vector<std::vector<double>> records;
  std::vector<std::optional<Crest>> crests;
  for (const std::string& name : names) {
    records.push_back(probes.numbers(name));
    records.back().resize(n);
    crests.push_back(first_crest(t, records.back()));
  }

  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  const auto time = crest_time;
  const auto height = crest_height;
  nlohmann::json pairs = nlohmann::json::array();
  for (size_t i = 0; i + 1 < names.size(); ++i) {
    const std::vector<double>& up = records[i];
    const auto &c_up = crests[i], &c_down = crests[i + 1];
    const double dx = xs[i + 1] - xs[i];
    std::optional<Crest> c_lin;
    if (std::all_of(up.begin(), up.end(), [](double v) { return std::isfinite(v); })) {
      std::optional<double> reflected;
      if (options.wall_x) reflected = 2 * *options.wall_x - xs[i] - xs[i + 1];
      c_lin = first_crest(t, propagate_linear(up, dt, dx, options.gravity, options.depth, reflected));
    }
    const double c_sim = c_up && c_down ? dx / (c_down->time - c_up->time) : NAN;
    const double c_linear = c_up && c_lin ? dx / (c_lin->time - c_up->time) : NAN;
    pairs.push_back(nlohmann::json{{"from", names[i]}, {"to", names[i + 1]}, {"x_from", xs[i]}, {"x_to", xs[i + 1]},
                                   {"arrival_from", time(c_up)}, {"arrival_to", time(c_down)},
                                   {"linear_arrival_to", time(c_lin)}, {"amplitude_to", height(c_down)},
                                   {"linear_amplitude_to", height(c_lin)}, {"celerity", num(c_sim)},
                                   {"linear_celerity", num(c_linear)}});
  }
  nlohmann::json report = {{"pairs", pairs}};

  // The released box: every gauge against the Cauchy-Poisson solution (with the end wall's image).
  if (options.box) report["cauchy_poisson"] = cauchy_poisson_rows(names, xs, t, crests, options);
  // Written once everything is computed, so an error leaves no half-written file.
  write_csv(out_dir + "/linear_waves.csv",
            {"from", "to", "x_from", "x_to", "arrival_from", "arrival_to", "linear_arrival_to", "amplitude_to",
             "linear_amplitude_to", "celerity", "linear_celerity"},
            report["pairs"]);
  if (options.box)
    write_csv(out_dir + "/cauchy_poisson.csv",
              {"gauge", "x", "arrival_time", "amplitude", "linear_arrival_time", "linear_amplitude"},
              report["cauchy_poisson"]);
  return report;
}

}  // namespace cdmpm
