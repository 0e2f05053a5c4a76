// stress.h - Kirchhoff stress of a particle, dispatched on its material (used by p2g), plus the
// per-material wave speed and stored energy used by the time step and the energy probes.
#pragma once

#include "core/particles.h"
#include "material/material.h"

namespace cdmpm {

template <int dim>
inline Mat<dim> kirchhoff_stress(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water: return m.water.kirchhoff<dim>(p.J[q], p.C[q]);
  }
  return Mat<dim>::Zero();
}

// Cauchy pressure p = -tr(sigma)/dim of particle q.
template <int dim>
inline Real particle_pressure(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water: return m.water.pressure(p.J[q]);
  }
  return 0;
}

// Stored (elastic) energy of particle q: V0 psi.
template <int dim>
inline Real particle_elastic_energy(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water: return p.volume0[q] * m.water.energy_density(p.J[q]);
  }
  return 0;
}

// Largest wave speed of particle q's material in its current state.
template <int dim>
inline Real particle_wave_speed(const Material& m, const Particles<dim>& p, size_t q) {
  switch (m.kind) {
    case MaterialKind::Water: return m.water.wave_speed(p.J[q]);
  }
  return 0;
}

}  // namespace cdmpm
