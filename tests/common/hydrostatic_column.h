// hydrostatic_column.h - the pressure and density at depth d in a column of Tait water at rest, as the tests expect it of the
// seeded state (sim/seeding.cpp). The particles carry the compressed density rho0 / J(p), with
// J(p) = (1 + gamma p / K)^(-1/gamma) (the Tait law p = K/gamma (J^-gamma - 1)), so the column's weight gives
//   dp/dd = rho0 g (1 + gamma p / K)^(1/gamma),  p(0) = 0,
//   p(d)  = K/gamma [(1 + (gamma - 1) rho0 g d / K)^(gamma/(gamma-1)) - 1]  (about rho0 g d (1 + rho0 g d / (2K))).
#pragma once

#include <cmath>

namespace cdmpm::testing {

inline double tait_column_pressure(double rho0, double g, double depth, double K, double gamma = 7) {
  return K / gamma * (std::pow(1 + (gamma - 1) * rho0 * g * depth / K, gamma / (gamma - 1)) - 1);
}

// The density of that water at depth d, rho0 / J(p(d)).
inline double tait_column_density(double rho0, double g, double depth, double K, double gamma = 7) {
  return rho0 * std::pow(1 + gamma * tait_column_pressure(rho0, g, depth, K, gamma) / K, 1 / gamma);
}

}  // namespace cdmpm::testing
