// constitutive_update.h - the constitutive-update phase of a step: after g2p, each particle's deformation
// state follows its new velocity gradient C_p, by its material model's update (material/water.h: J;
// material/ice.h: J, F and the return mapping; material/rigid.h: nothing, the rigid projection advances its J).
#pragma once

#include <vector>

#include "core/particles.h"
#include "material/material.h"

namespace cdmpm {

// Dynamic chunks: the solids come first (core/particles.h) and cost far more (SVD, return mapping) than fluids,
// so equal static halves would leave one thread with all the ice. Each particle writes only its own state.
template <int dim>
void constitutive_update(Particles<dim>& p, const std::vector<Material>& materials, Real dt) {
  const size_t n = p.size();
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t q = 0; q < n; ++q)
    materials[p.material[q]].visit([&](const auto& model) { model.template update<dim>(p, q, dt); });
}

}  // namespace cdmpm
