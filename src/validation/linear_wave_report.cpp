// linear_wave_report.cpp - gauge pairs against linear theory (see linear_wave_report.h).
#include "validation/linear_wave_report.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/csv_table.h"
#include "probe/wave_analysis.h"
#include "validation/linear_dispersion.h"

namespace cdmpm {

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
  auto record = [&](const std::string& gauge) {
    std::vector<double> r = probes.numbers(gauge);
    r.resize(n);
    return r;
  };

  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto value = [&](const std::optional<Crest>& c, double Crest::*m) { return c ? (*c).*m : nan; };
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json rows = nlohmann::json::array();
  std::ostringstream csv;  // written to the file only once every pair is done
  csv.precision(10);
  csv << "from,to,x_from,x_to,arrival_from,arrival_to,linear_arrival_to,amplitude_to,linear_amplitude_to,celerity,"
         "linear_celerity\n";
  for (size_t i = 0; i + 1 < names.size(); ++i) {
    const std::vector<double> up = record(names[i]), down = record(names[i + 1]);
    const auto c_up = first_crest(t, up), c_down = first_crest(t, down);
    std::optional<Crest> c_lin;
    bool wet = true;
    for (double v : up) wet = wet && std::isfinite(v);
    if (wet) {
      std::optional<double> reflected;
      if (options.wall_x) reflected = 2 * *options.wall_x - xs[i] - xs[i + 1];
      c_lin = first_crest(t, propagate_linear(up, dt, xs[i + 1] - xs[i], options.gravity, options.depth, reflected));
    }
    const double dx = xs[i + 1] - xs[i];
    const double c_sim = c_up && c_down ? dx / (c_down->time - c_up->time) : nan;
    const double c_linear = c_up && c_lin ? dx / (c_lin->time - c_up->time) : nan;
    csv << names[i] << ',' << names[i + 1] << ',' << xs[i] << ',' << xs[i + 1] << ',' << value(c_up, &Crest::time)
        << ',' << value(c_down, &Crest::time) << ',' << value(c_lin, &Crest::time) << ','
        << value(c_down, &Crest::amplitude) << ',' << value(c_lin, &Crest::amplitude) << ',' << c_sim << ','
        << c_linear << '\n';
    rows.push_back(nlohmann::json{{"from", names[i]}, {"to", names[i + 1]}, {"x_from", xs[i]}, {"x_to", xs[i + 1]},
                    {"arrival_from", num(value(c_up, &Crest::time))}, {"arrival_to", num(value(c_down, &Crest::time))},
                    {"linear_arrival_to", num(value(c_lin, &Crest::time))},
                    {"amplitude_to", num(value(c_down, &Crest::amplitude))},
                    {"linear_amplitude_to", num(value(c_lin, &Crest::amplitude))}, {"celerity", num(c_sim)},
                    {"linear_celerity", num(c_linear)}});
  }
  nlohmann::json report = {{"pairs", rows}};

  // The released box: every gauge against the Cauchy-Poisson solution (with the end wall's image).
  std::ostringstream box_csv;
  if (options.box) {
    box_csv.precision(10);
    box_csv << "gauge,x,arrival_time,amplitude,linear_arrival_time,linear_amplitude\n";
    report["cauchy_poisson"] = nlohmann::json::array();
    for (size_t i = 0; i < names.size(); ++i) {
      const auto sim = first_crest(t, record(names[i]));
      std::vector<double> eta =
          cauchy_poisson_box(xs[i], t, options.box->height, options.box->half_width, options.gravity, options.depth);
      if (options.wall_x) {
        const auto image = cauchy_poisson_box(2 * *options.wall_x - xs[i], t, options.box->height,
                                              options.box->half_width, options.gravity, options.depth);
        for (size_t j = 0; j < eta.size(); ++j) eta[j] += image[j];
      }
      const auto lin = first_crest(t, eta);
      box_csv << names[i] << ',' << xs[i] << ',' << value(sim, &Crest::time) << ',' << value(sim, &Crest::amplitude)
              << ',' << value(lin, &Crest::time) << ',' << value(lin, &Crest::amplitude) << '\n';
      report["cauchy_poisson"].push_back(nlohmann::json{
          {"gauge", names[i]}, {"x", xs[i]}, {"arrival_time", num(value(sim, &Crest::time))},
          {"amplitude", num(value(sim, &Crest::amplitude))}, {"linear_arrival_time", num(value(lin, &Crest::time))},
          {"linear_amplitude", num(value(lin, &Crest::amplitude))}});
    }
  }
  std::ofstream file(out_dir + "/linear_waves.csv", std::ios::trunc);
  file << csv.str();
  if (!file) throw std::runtime_error(out_dir + "/linear_waves.csv: cannot write");
  if (options.box) {
    std::ofstream f(out_dir + "/cauchy_poisson.csv", std::ios::trunc);
    f << box_csv.str();
    if (!f) throw std::runtime_error(out_dir + "/cauchy_poisson.csv: cannot write");
  }
  return report;
}

}  // namespace cdmpm
