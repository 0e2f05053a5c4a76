// stress.h - Kirchhoff stress of a particle, dispatched on its material (used by p2g), plus the
// per-material wave speed and stored energy used by the time step and the energy probes.
//   Water: tau = -J p(J) I + viscous part (material/weakly_compressible_water.h).
//   Ice:   tau(F_elastic) of the split Neo-Hookean energy (material/neo_hookean_split.h).
//   Rigid: the pressure of its equation of state, as water (material/material.h); its sum over a body is an
//          internal force that the rigid projection (sim/rigid_bodies.h) cancels, so it acts only on the water.
// Only ice particles have an F (core/particles.h: solids first), so F[q] is read in the Ice cases only.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/particles.h"
#include "material/material.h"

namespace cdmpm {

template <int dim>
inline Mat<dim> kirchhoff_stress(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water:
    case MaterialKind::Rigid: return m.water.kirchhoff<dim>(p.J[q], p.C[q]);
    case MaterialKind::Ice: return m.ice.elastic.kirchhoff<dim>(p.F[q]);
  }
  return Mat<dim>::Zero();
}

// Volume ratio J of particle q that turns its Kirchhoff stress into the Cauchy stress: det of the elastic F
// for ice, the tracked J for water and rigid bodies.
template <int dim>
inline Real particle_volume_ratio(const Material& m, const Particles<dim>& p, size_t q) {
  return m.kind == MaterialKind::Ice ? p.F[q].determinant() : p.J[q];
}

// Cauchy stress sigma = tau / J of particle q (written to the frames).
template <int dim>
inline Mat<dim> cauchy_stress(const Material& m, const Particles<dim>& p, size_t q) {
  return kirchhoff_stress(m, p, q) / particle_volume_ratio(m, p, q);
}

// Cauchy pressure p = -tr(sigma)/dim of particle q (sigma = tau / J, J the elastic volume ratio for ice).
template <int dim>
inline Real particle_pressure(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water:
    case MaterialKind::Rigid: return m.water.pressure(p.J[q]);
    case MaterialKind::Ice: {
      const Real Je = particle_volume_ratio(m, p, q);
      return m.ice.elastic.pressure_of_J(Je) / Je;
    }
  }
  return 0;
}

// Stored (elastic) energy of particle q: V0 psi.
template <int dim>
inline Real particle_elastic_energy(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water:
    case MaterialKind::Rigid: return reference_volume(m, p.mass[q]) * m.water.energy_density(p.J[q]);
    case MaterialKind::Ice: return reference_volume(m, p.mass[q]) * m.ice.elastic.energy_density<dim>(p.F[q]);
  }
  return 0;
}

// Wave speeds. Ice: P-wave speed sqrt(M_p / rho) with the small-strain modulus M_p = kappa + 2 mu (1 - 1/d),
// raised by the current density ratio J >= 1 (the volumetric tangent kappa/2 (J^2 + 1) J-scaled grows like
// J^2 in tension). Water: the acoustic speed c(J), which grows as J falls.
// Both grow monotonically with a scalar "stiffening" state s of the particle (ice: max(det F, 1); water: 1/J),
// so the fastest wave of a material is the wave speed at the largest s of its particles: the time step
// needs one wave-speed evaluation per material, not per particle.
template <int dim>
inline Real particle_stiffening(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water:
    case MaterialKind::Rigid: return Real(1) / p.J[q];
    case MaterialKind::Ice: return std::max(p.F[q].determinant(), Real(1));
  }
  return 0;
}
template <int dim>
inline Real wave_speed_at_stiffening(const Material& m, Real s) {
  switch (m.kind) {
    case MaterialKind::Water:
    case MaterialKind::Rigid: return m.water.wave_speed(Real(1) / s);  // a rigid body's contact pressure law
    case MaterialKind::Ice: return s * std::sqrt(m.ice.elastic.p_wave_modulus<dim>() / m.density);
  }
  return 0;
}

}  // namespace cdmpm
