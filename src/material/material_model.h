// material_model.h - what every constitutive model provides: the C++20 concept the material registry
// (material/material.h) checks each model against, and the traits that let the rest of the engine ask
// a material what it is instead of which model it is.
//
// A model M (one file each: material/water.h, material/ice.h, material/rigid.h) provides
//   M::type                            its scene "type" name,
//   M::traits                          MaterialTraits (below),
//   M::parse(reader, node)             reads and validates its own scene keys (scene/scene_reader.h),
//   density()                          the reference density rho0 [kg/m^3] (V0 = m / rho0),
//   kirchhoff<dim>(p, q)               the Kirchhoff stress tau of particle q (used by p2g),
//   volume_ratio<dim>(p, q)            the J that turns tau into the Cauchy stress sigma = tau / J,
//   pressure<dim>(p, q)                the Cauchy pressure -tr(sigma)/dim,
//   energy_density<dim>(p, q)          stored energy per reference volume psi,
//   stiffening<dim>(p, q)              a scalar s of the particle's state such that the model's fastest wave
//                                      speed grows monotonically with s, and
//   wave_speed<dim>(s)                 that wave speed (the time step needs one evaluation per material),
//   stable_dt(dx, dim)                 any further explicit time-step limit of the model (+inf if none),
//   update<dim>(p, q, dt)              the per-particle constitutive update after g2p (the particle's new
//                                      velocity gradient is C_q),
//   initial_state<dim>(pressure, k)    the deformation state of a particle seeded at rest under the given
//                                      lithostatic / hydrostatic pressure: solids under the vertical stress
//                                      -pressure and the horizontal stress -k pressure (k the lateral stress
//                                      ratio, sim/seeding.h), fluids under the isotropic pressure (k unused),
//   field_names(), fields<dim>(p, q, out)  extra per-particle output fields for the frames.
#pragma once

#include <concepts>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/particles.h"
#include "core/types.h"
#include "scene/scene_reader.h"

namespace cdmpm {

struct MaterialTraits {
  bool fluid = false;        // free-surface liquid: wave gauges measure it by default
  bool solid_state = false;  // carries an elastic F and a hardening variable alpha (core/particles.h)
  bool rigid = false;        // its particles form one rigid body (sim/rigid_bodies.h), moved by the body
  bool breakable = false;    // carries damage: its intact connected parts are tracked as icebergs
};

// State of a particle seeded at rest: total volume ratio J and (solid_state models) elastic F, alpha and, in 2D,
// the out-of-plane elastic stretch Fz (core/particles.h).
template <int dim>
struct InitialState {
  Real J = 1;
  Mat<dim> F = Mat<dim>::Identity();
  Real alpha = 0;
  Real Fz = 1;
};

template <class M>
concept ConstitutiveModel = requires(const M m, const Particles<2>& p2, const Particles<3>& p3, Particles<2>& w2,
                                     Particles<3>& w3, const SceneReader& r, const Node& n, size_t q, Real s,
                                     float* out) {
  { M::type } -> std::convertible_to<std::string_view>;
  { M::traits } -> std::convertible_to<MaterialTraits>;
  { M::parse(r, n) } -> std::same_as<M>;
  { m.density() } -> std::same_as<Real>;
  { m.template kirchhoff<2>(p2, q) } -> std::same_as<Mat<2>>;
  { m.template kirchhoff<3>(p3, q) } -> std::same_as<Mat<3>>;
  { m.template volume_ratio<2>(p2, q) } -> std::same_as<Real>;
  { m.template pressure<3>(p3, q) } -> std::same_as<Real>;
  { m.template energy_density<2>(p2, q) } -> std::same_as<Real>;
  { m.template stiffening<3>(p3, q) } -> std::same_as<Real>;
  { m.template wave_speed<2>(s) } -> std::same_as<Real>;
  { m.stable_dt(s, 2) } -> std::same_as<Real>;
  m.template update<2>(w2, q, s);
  m.template update<3>(w3, q, s);
  { m.template initial_state<2>(s, s) } -> std::same_as<InitialState<2>>;
  { m.field_names() } -> std::convertible_to<std::vector<std::string>>;
  m.template fields<3>(p3, q, out);
};

inline constexpr Real no_time_step_limit = std::numeric_limits<Real>::max();

}  // namespace cdmpm
