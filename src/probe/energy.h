// energy.h - totals over particles: mass, kinetic energy sum 1/2 m |v|^2, gravitational energy
// sum -m g.x (zero at the origin), and stored elastic energy sum V0 psi (material/stress.h). Exact sums
// (math/exact_sum.h): the same bits for any number of threads and processes.
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
  std::vector<ExactSum> s = exact_sums(4, p.size(), [&](size_t q, ExactSum* acc) {
    if (material_index >= 0 && p.material[q] != material_index) return;
    acc[0].add(p.mass[q]);
    acc[1].add(0.5 * p.mass[q] * p.v[q].squaredNorm());
    acc[2].add(-(p.mass[q] * gravity.dot(p.x[q])));
    acc[3].add(particle_elastic_energy(materials[p.material[q]], p, q));
  });
  global::sum(s);
  return {s[0].value(), s[1].value(), s[2].value(), s[3].value()};
}

}  // namespace cdmpm
