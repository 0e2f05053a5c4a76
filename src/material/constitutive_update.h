// constitutive_update.h - per-particle update of the deformation state after grid-to-particle, then
// advection of the particle positions x_p += dt v_p.
//
// Every material: J <- J (1 + dt tr C_p), the discrete continuity equation dJ/dt = J div v, so J stays the
// total volume ratio V / V0 (the water state; for ice it tracks the total, elastic and plastic, volume).
// Ice additionally (Jiang et al. 2016 course notes, eq. 202; Wolper et al. 2019, sec. 4):
//   F_trial = (I + dt C_p) F_elastic,   then the Cohesive Cam Clay return mapping projects F_trial onto the
//   yield surface and updates the hardening variable alpha (material/cohesive_cam_clay.h).
// F and alpha exist for ice particles only (core/particles.h: solids first), so they are touched in the Ice
// case only. Rigid particles are not advected here: their body moves them rigidly (sim/rigid_bodies.h), so the
// body keeps its shape exactly; their J was updated by the projection from the grid's divergence (their C is
// skew afterwards, so the update here leaves it unchanged).
#pragma once

#include <vector>

#include "core/particles.h"
#include "material/material.h"

namespace cdmpm {

// Updates particle q's deformation state with its new velocity gradient C_q and advects it.
template <int dim>
inline void constitutive_update(Particles<dim>& p, const std::vector<Material>& materials, size_t q, Real dt) {
  const Material& m = materials[p.material[q]];
  p.J[q] *= Real(1) + dt * p.C[q].trace();
  if (m.kind == MaterialKind::Ice) {
    Mat<dim> F = (Mat<dim>::Identity() + dt * p.C[q]) * p.F[q];
    if (m.ice.plasticity) m.ice.plastic.return_mapping<dim>(F, p.alpha[q], m.ice.p0(p.alpha[q]), m.ice.elastic);
    p.F[q] = F;
  }
  p.x[q] += dt * p.v[q];
}

}  // namespace cdmpm
