// frame_writer.h - one particle frame of a simulation as a .vtu file (io/vtu_writer.h) for ParaView: position,
// velocity, material (index into the scene's materials), pressure [Pa], J, the Cauchy stress tensor `stress`
// [Pa] (3x3 row-major, zero-padded in 2D, material/stress.h), then the extra fields of the materials present
// (material_model.h field_names; ice: damage, alpha, p0), zero on particles of materials without them.
#pragma once

#include <string>

#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
void write_frame(const std::string& path, const Simulation<dim>& sim);

}  // namespace cdmpm
