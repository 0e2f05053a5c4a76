// energy.h - totals over particles: mass, kinetic energy sum 1/2 m |v|^2, gravitational energy
// sum -m g.x (zero at the origin), and stored elastic energy sum V0 psi (material/stress.h).
#pragma once

#include "core/particles.h"
#include "material/stress.h"
#include "parallel/reduction.h"

namespace cdmpm {

struct EnergyTotals {
  double mass = 0, kinetic = 0, gravitational = 0, elastic = 0;
  double total() const { return kinetic + gravitational + elastic; }
};

// material_index < 0: all particles; otherwise only that material's.
template <int dim>
EnergyTotals energy_totals(const Particles<dim>& p, const std::vector<Material>& materials, const Vec<dim>& gravity,
                           int material_index = -1) {
  double m = 0, ke = 0, ge = 0, ee = 0;
  const size_t n = p.size();
#pragma omp parallel for schedule(static) reduction(+ : m, ke, ge, ee)
  for (size_t q = 0; q < n; ++q) {
    if (material_index >= 0 && p.material[q] != material_index) continue;
    m += p.mass[q];
    ke += 0.5 * p.mass[q] * p.v[q].squaredNorm();
    ge -= p.mass[q] * gravity.dot(p.x[q]);
    ee += particle_elastic_energy(materials[p.material[q]], p, q);
  }
  return {global::sum(m), global::sum(ke), global::sum(ge), global::sum(ee)};
}

}  // namespace cdmpm
