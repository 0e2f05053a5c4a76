// linear_wave_report.h - a run's wave gauges against linear water-wave theory (validation/linear_dispersion.h):
// for each pair of consecutive gauges along x (waves.csv), the record of the first is carried to the second by
// linear theory in the still-water depth h, and the first crest of that prediction (probe/wave_analysis.h, the
// same definition as the run's) is set beside the simulated one. Its celerity, (x_2 - x_1) / (t_lin - t_1), is
// what linear theory gives for the crest that the simulation measured at the first gauge: sqrt(g h) for a long
// wave, less for a crest that follows a leading trough or a dispersive front. The comparison is valid for a
// constant depth between the gauges and waves small against h (the crest speed grows by about a / (2 h) from
// nonlinearity), with a fully reflecting wall at wall_x if given (a tank's end wall).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace cdmpm {

struct LinearWaveOptions {
  double depth = 0;             // still-water depth h [m], > 0
  double gravity = 9.81;        // g [m/s^2]
  std::optional<double> wall_x; // position of a reflecting end wall beyond the gauges [m]
  struct Box {
    double height = 0, half_width = 0;  // a, w [m]
  };
  std::optional<Box> box;       // the run released a box of water a high over 0 <= x < w (the wall at x = 0)
};

// Reads out_dir/waves.csv and out_dir/probes.csv, writes out_dir/linear_waves.csv (from, to, x_from, x_to,
// arrival_from, arrival_to, linear_arrival_to, amplitude_to, linear_amplitude_to, celerity, linear_celerity; nan
// where a crest is missing) and returns {"pairs": the same rows}. With a box, the run is a Cauchy-Poisson problem
// (validation/linear_dispersion.h): every gauge's first crest is also set beside that of the linear solution
// (plus its image in the end wall, if any), in out_dir/cauchy_poisson.csv (gauge, x, arrival_time, amplitude,
// linear_arrival_time, linear_amplitude) and under "cauchy_poisson". Throws std::runtime_error naming the file for
// missing or malformed outputs (no gauges, a non-uniform sampling interval, a wall inside the gauges).
nlohmann::json linear_wave_report(const std::string& out_dir, const LinearWaveOptions& options);

}  // namespace cdmpm
