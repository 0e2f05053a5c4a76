// material.h - the material table: one constitutive model per named scene material.
//
// Each particle stores an index into this table. The constitutive update (after grid-to-particle) and the
// stress evaluation (in particle-to-grid) dispatch on Material::kind:
//   Water: weakly compressible fluid (material/weakly_compressible_water.h), state J;
//   Ice:   split Neo-Hookean elasticity (material/neo_hookean_split.h) with cohesive Cam-Clay plasticity
//          and softening (material/cohesive_cam_clay.h), state: elastic F and hardening variable alpha
//          (stored for ice particles only, core/particles.h);
//   Rigid: a particle of a rigid body (sim/rigid_bodies.h): after each grid-to-particle transfer its velocity is
//          projected onto its body's rigid motion. It carries the pressure of the Tait equation of state
//          (`water`, with the body's density and bulk modulus, no viscosity) of a volume ratio J that follows the
//          divergence of the grid velocity at the particle: the pressure that keeps other materials from
//          flowing into the body (without it the body, having no stress, would let water seep through it).
//          Stored with the fluids (no F or alpha).
#pragma once

#include <string>

#include "material/cohesive_cam_clay.h"
#include "material/neo_hookean_split.h"
#include "material/weakly_compressible_water.h"

namespace cdmpm {

enum class MaterialKind { Water, Ice, Rigid };

struct IceModel {
  NeoHookeanSplit elastic;
  CohesiveCamClay plastic;
  bool plasticity = true;   // false: purely elastic (no return mapping)
  Real p0_initial = 0;      // pre-consolidation pressure of intact ice [Pa]
  Real alpha_initial = 0;   // alpha giving p0_initial

  Real p0(Real alpha) const { return plastic.p0_of_alpha(alpha, elastic.kappa); }
  // Damage d = 1 - p0 / p0_initial in [0, 1]: 0 intact, 1 all cohesion lost (material/cohesive_cam_clay.h).
  Real damage(Real alpha) const { return plasticity ? CohesiveCamClay::damage(p0(alpha), p0_initial) : Real(0); }
};

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::Water;
  Real density = 1000;
  WeaklyCompressibleWater water;
  IceModel ice;
  Real half_spacing = 0;  // half the particle spacing of this material's bodies (for surface probes)
};

inline bool is_fluid(const Material& m) { return m.kind == MaterialKind::Water; }

// Reference (unstressed) volume V0 = m / rho0 of a particle of mass m (seeding sets m = rho0 V0).
inline Real reference_volume(const Material& m, Real mass) { return mass / m.density; }

}  // namespace cdmpm
