// rise_reference.h - the potential-flow reference for the rise scenes (scenes/rigid_rise_2d.json, rigid_rise_contact_2d.json,
// ice_rise_contact_2d.json: a 0.4 m square block centred 1 m under still water): the potential-flow acceleration of a
// body released at rest,
//   a = (rho_w - rho_b) V g / (rho_b V + C_A rho_w pi D^2 / 4),   C_A = 1.51 for a square (DNV-RP-C205, table A-1),
// with rho_w the density of the scenes' water where the block is: Tait water of bulk modulus K is compressed by its own
// weight (hydrostatic_column.h), 1009.6 kg/m^3 at 1 m depth for the scenes' K = 1e6 Pa, so the displaced water weighs
// 1 % more than at rho0 = 1000 and the net buoyancy of a block of density 920 is 12 % larger: 0.415 m/s^2 instead of
// the 0.373 of rho_w = 1000 (docs/validation.md, "Buoyancy-driven motions"). A block of density rho_w(1 m) is
// neutrally buoyant: a = 0.
#pragma once

#include <numbers>
#include <string>

#include "hydrostatic_column.h"

namespace cdmpm::testing {

constexpr double rise_block_size = 0.4, rise_block_depth = 1.0, rise_water_rho0 = 1000, rise_g = 9.81;

// The scenes' water density at the block's centre for bulk modulus K.
inline double rise_water_density(double K) {
  return tait_column_density(rise_water_rho0, rise_g, rise_block_depth, K);
}

inline double potential_flow_rise(double rho_b, double K) {
  const double D = rise_block_size, V = D * D, C_A = 1.51, rho_w = rise_water_density(K);
  return (rho_w - rho_b) * V * rise_g / (rho_b * V + C_A * rho_w * std::numbers::pi * D * D / 4);
}

// The scenes' own block and water (their parameters block_density = 920 and K = 1e6 Pa): 0.415 m/s^2.
constexpr double rise_scene_block_density = 920, rise_scene_K = 1e6;
inline double scene_rise_reference() { return potential_flow_rise(rise_scene_block_density, rise_scene_K); }
// The scenes' --set that makes the block neutrally buoyant: its density that of the water where it is.
inline std::string neutral_block_density_set() {
  return "parameters.block_density=" + std::to_string(rise_water_density(rise_scene_K));
}

}  // namespace cdmpm::testing
