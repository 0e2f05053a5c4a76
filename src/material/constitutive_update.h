// constitutive_update.h - per-particle update of the deformation state after grid-to-particle, then
// advection of the particle positions x_p += dt v_p.
//
// Water: J <- J (1 + dt tr C_p), the discrete continuity equation dJ/dt = J div v
// (material/weakly_compressible_water.h).
#pragma once

#include <vector>

#include "core/particles.h"
#include "material/material.h"

namespace cdmpm {

template <int dim>
void constitutive_update(Particles<dim>& p, const std::vector<Material>& materials, Real dt) {
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q) {
    const Material& m = materials[p.material[q]];
    switch (m.kind) {
      case MaterialKind::Water: p.J[q] = m.water.update_J<dim>(p.J[q], p.C[q], dt); break;
    }
    p.x[q] += dt * p.v[q];
  }
}

}  // namespace cdmpm
