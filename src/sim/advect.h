// advect.h - the advection phase: x_p <- x_p + dt v_p for every particle but the rigid ones (their bodies move
// them rigidly, sim/rigid_bodies.h), then every particle is returned inside the walls (boundary.h,
// keep_inside: a crossing is an interpolation overshoot of O(dt v); a bathymetry also takes away the velocity into
// its bed).
#pragma once

#include <memory>
#include <vector>

#include "boundary/boundary.h"
#include "core/particles.h"

namespace cdmpm {

template <int dim>
void advect(Particles<dim>& p, const std::vector<uint8_t>& rigid_material, Real dt) {
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q)
    if (!rigid_material[p.material[q]]) p.x[q] += dt * p.v[q];
}

template <int dim>
void keep_inside(Particles<dim>& p, const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries) {
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q)
    for (const auto& b : boundaries) b->keep_inside(p.x[q], p.v[q]);
}

}  // namespace cdmpm
