// frame_writer.h - one particle frame of a simulation as a .vtu file (io/vtu_writer.h) for ParaView: position,
// velocity [m/s], material (index into the scene's materials, whose names the file's field data
// `material_names` lists), pressure [Pa], J, the Cauchy stress tensor `stress` [Pa] (3x3 row-major, zero-padded
// in 2D, material/stress.h), the 64-bit particle `id`, `mass` [kg] and current `volume` [m^3; m^2 in 2D], then
// the extra fields of the materials present (material_model.h field_names; ice: damage, alpha, p0), NaN on
// particles of materials without them (water is not intact ice). The frame's time is field data TimeValue [s]. zlib-compressed unless
// the scene's output.compress is false; positions in single precision with output.positions = "float32".
#pragma once

#include <string>
#include <vector>

#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
void write_frame(const std::string& path, const Simulation<dim>& sim);

// One rank's piece of a distributed run's frame: this rank's particles, as write_frame writes them, to `piece`;
// and, if `pvtu` is not empty (rank 0), the .pvtu joining the pieces `pieces` (file names; io/vtu_writer.h).
template <int dim>
void write_frame_piece(const std::string& piece, const Simulation<dim>& sim, const std::string& pvtu,
                       const std::vector<std::string>& pieces);

}  // namespace cdmpm
