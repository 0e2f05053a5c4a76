// stress.h - a particle's stress, pressure, energy and wave speed, dispatched statically on its material's
// model (material/material.h; each model's formulas are in its own file):
//   kirchhoff_stress   tau (used by p2g),
//   cauchy_stress      sigma = tau / J (written to the frames), J = particle_volume_ratio,
//   particle_pressure  -tr(sigma)/dim,
//   particle_elastic_energy  V0 psi (energy probes),
//   particle_damage    damage of breakable materials (iceberg detection),
//   particle_stiffening, wave_speed_at_stiffening: the fastest wave of a material is the wave speed at the
//   largest "stiffening" state of its particles, so the time step needs one wave-speed evaluation per material.
#pragma once

#include "core/particles.h"
#include "material/material.h"

namespace cdmpm {

template <int dim>
inline Mat<dim> kirchhoff_stress(const Material& m, const Particles<dim>& p, size_t q) {
  return m.visit([&](const auto& model) { return model.template kirchhoff<dim>(p, q); });
}

template <int dim>
inline Real particle_volume_ratio(const Material& m, const Particles<dim>& p, size_t q) {
  return m.visit([&](const auto& model) { return model.template volume_ratio<dim>(p, q); });
}

template <int dim>
inline Mat<dim> cauchy_stress(const Material& m, const Particles<dim>& p, size_t q) {
  return kirchhoff_stress(m, p, q) / particle_volume_ratio(m, p, q);
}

template <int dim>
inline Real particle_pressure(const Material& m, const Particles<dim>& p, size_t q) {
  return m.visit([&](const auto& model) { return model.template pressure<dim>(p, q); });
}

template <int dim>
inline Real particle_elastic_energy(const Material& m, const Particles<dim>& p, size_t q) {
  return m.visit([&](const auto& model) { return reference_volume(m, p.mass[q]) * model.template energy_density<dim>(p, q); });
}

// Damage in [0, 1] of particle q: its model's damage for breakable materials (material/ice.h), 0 otherwise.
template <int dim>
inline Real particle_damage(const Material& m, const Particles<dim>& p, size_t q) {
  return m.visit([&](const auto& model) {
    if constexpr (requires { model.damage(p.alpha[q]); }) return model.damage(p.alpha[q]);
    else return Real(0);
  });
}

template <int dim>
inline Real particle_stiffening(const Material& m, const Particles<dim>& p, size_t q) {
  return m.visit([&](const auto& model) { return model.template stiffening<dim>(p, q); });
}

template <int dim>
inline Real wave_speed_at_stiffening(const Material& m, Real s) {
  return m.visit([&](const auto& model) { return model.template wave_speed<dim>(s); });
}

}  // namespace cdmpm
