// field_contact.h - frictionless contact between deformable solids (ice with the key `contact`) and the other
// materials (water): multi-velocity-field MPM contact (Bardenhagen, Brackbill & Sulsky 2000, "The material-point
// method for granular materials", CMAME 187, eq. 21-27; Nairn 2013 for the normals from the mass gradient).
//
// The solids scatter mass, momentum and their stress impulse into a grid field of their own (transfer/p2g.h,
// Field::solid), the others into the shared field, and each field is updated by itself (grid/grid_update.h,
// boundaries included). At a node i holding both (solid m_s, v_s; other m_o, v_o), with n_i the solid's outward
// normal (its mass gradient points into it: n_i = -grad m_s / |grad m_s|, the gradient by central differences of
// the field's node masses), the two approach when
//   lambda_i = (v_s - v_o) . n_i > 0,
// and then both normal velocities become the centre of mass's, the tangential ones are left alone (no friction):
//   v_s -= c_i lambda_i m_o / (m_s + m_o) n_i,   v_o += c_i lambda_i m_s / (m_s + m_o) n_i,
// which conserves the node's momentum (m_s dv_s + m_o dv_o = 0). Nodes that separate keep their velocities. The
// boundaries' conditions are applied again to both velocities afterwards. c_i is the node's share of the contact,
// 0 to 1 as the solid's node mass goes from 0.05 to 0.2 of a full node's (rho dx^dim): the rigid bodies' ramp
// (RigidContact::share, sim/rigid_contact.h: a node the solid's kernel barely reaches would otherwise stop the
// water a cell outside the surface). The solids' particles then read their own field (transfer/g2p.h, `only`).
// Why: in the one shared field the nodes beside an elastic block carry both the block and the water that sinks
// past it, and the block's shear passes that drag into the whole block: an elastic ice block of density 920
// released in water rose at 69 % of the potential-flow acceleration at D/16 with J-bar and FLIP on the water
// (docs/changelog.md, "Buoyancy coupling"). The contact is node by node, so the result does not depend on the thread count.
// One process only (refused under mpirun, sim/simulation.cpp: the halo exchange carries one field); a rigid body in
// contact beside it is refused by the scene loader (its contact meets the shared field only).
// With the scene key time.multi_rate the field sub-steps at its own stable step inside the water's (subcycle).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "boundary/boundary.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/grid_update.h"
#include "grid/particle_bins.h"
#include "material/constitutive_update.h"
#include "material/material.h"
#include "sim/advect.h"
#include "sim/rigid_contact.h"
#include "transfer/g2p.h"
#include "transfer/p2g.h"

namespace cdmpm {

template <int dim>
class FieldContact {
 public:
  // The materials that have the field (deformable, with `contact`); none: the class does nothing. The field is
  // a grid of the shared one's lattice.
  void configure(const std::vector<Material>& materials, const Grid<dim>& shared) {
    in_field_.assign(materials.size(), 0);
    Real rho = 0;
    for (size_t mi = 0; mi < materials.size(); ++mi) {
      in_field_[mi] = scatters_into(materials[mi], Field::solid);
      if (in_field_[mi]) rho = rho == 0 ? materials[mi].density() : std::min(rho, materials[mi].density());
    }
    full_node_mass_ = rho * std::pow(shared.dx, dim);
    any_ = std::find(in_field_.begin(), in_field_.end(), 1) != in_field_.end();
    if (any_) field = shared;
  }
  bool any() const { return any_; }

  // The field takes the shared grid's active blocks (the same slots), cleared.
  void activate(const std::vector<uint32_t>& blocks) { field.activate(blocks); }

  // The solids' mass, momentum and stress impulse (p2g into the field).
  void scatter(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins, Real dt) {
    p2g(p, materials, bins, field, dt, [](int) {}, Field::solid);
  }

  // The field's grid update, then the contact with the shared field (velocities in both, after grid_update). The
  // shared field's node is looked up by its lattice index: the field may hold other blocks (subcycle).
  void update(Grid<dim>& shared, const Vec<dim>& gravity, Real dt, const std::vector<std::unique_ptr<Boundary<dim>>>& bcs) {
    grid_update(field, gravity, dt, bcs);
    const Real inv_2dx = Real(0.5) * field.inv_dx;
    field.for_each_node([&](size_t k, const IVec<dim>& i) {
      const Real ms = field.mass[k];
      if (ms <= 0) return;
      const size_t ko = shared.find(i);
      if (ko == Grid<dim>::npos) return;
      const Real mo = shared.mass[ko];
      if (mo <= 0) return;
      const Real c = RigidContact<dim>::share(ms / full_node_mass_);
      if (c == 0) return;
      Vec<dim> grad;
      for (int a = 0; a < dim; ++a) {
        IVec<dim> up = i, down = i;
        ++up[a], --down[a];
        grad[a] = (node_mass(up) - node_mass(down)) * inv_2dx;
      }
      const Real norm = grad.norm();
      if (!(norm > 0)) return;
      const Vec<dim> n = -grad / norm;
      Vec<dim>& vs = field.momentum[k];
      Vec<dim>& vo = shared.momentum[ko];
      const Real lambda = (vs - vo).dot(n);
      if (!(lambda > 0)) return;
      const Real inv_m = Real(1) / (ms + mo);
      vs -= (c * lambda * mo * inv_m) * n;
      vo += (c * lambda * ms * inv_m) * n;
      if (!bcs.empty()) {
        const Vec<dim> x = field.position(i);
        apply_conditions(bcs, x, vs);
        apply_conditions(bcs, x, vo);
      }
    });
  }

  // The solids' particles read their field (APIC g2p).
  void gather(Particles<dim>& p, const ParticleBins& bins) const { g2p(p, field, bins, {}, in_field_); }

  // Multi-rate stepping (scene key time.multi_rate): over a step dt of the others, the field's solids (`solids`,
  // extracted from the particles) take n steps of h = dt / n of their own: p2g into the field, its grid update and
  // the contact above, g2p, their constitutive update and advection. The shared field holds its velocity after the
  // step's grid update on entry; it restarts from v0, its velocity at the start of the step (p2g without force),
  // and takes (v - v0) / n before each sub-step, so that the contact meets the water's push spread over the step as
  // the water exerts it, and it ends at v plus the contact's corrections. Each sub-step conserves the momentum of
  // both fields as the contact does. Why: the ice's P-wave speed (1.2 km/s at E = 1 GPa) sets a step 40 times
  // shorter than the water's (docs/validation.md, "multi-rate"), and stepping the water at it costs that much and,
  // with XPIC's small loss per step, slows a rising block.
  void subcycle(Particles<dim>& solids, Grid<dim>& shared, const std::vector<Vec<dim>>& v0, int n, Real dt,
                const Vec<dim>& gravity, const std::vector<Material>& materials, const std::vector<uint8_t>& rigid_material,
                const std::vector<std::unique_ptr<Boundary<dim>>>& bcs) {
    const size_t nn = shared.node_count();
    increment_.resize(nn);
    const Real inv_n = Real(1) / Real(n);
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < nn; ++k) {
      increment_[k] = (shared.momentum[k] - v0[k]) * inv_n;
      shared.momentum[k] = v0[k];
    }
    const Real h = dt * inv_n;
    for (int s = 0; s < n; ++s) {
#pragma omp parallel for schedule(static)
      for (size_t k = 0; k < nn; ++k) shared.momentum[k] += increment_[k];
      bins_.build(solids, field);
      field.activate(bins_.blocks);
      scatter(solids, materials, bins_, h);
      for (const auto& b : bcs) b->fold_ghosts(field);
      update(shared, gravity, h, bcs);
      for (auto b = bcs.rbegin(); b != bcs.rend(); ++b) (*b)->unfold_ghosts(field);
      gather(solids, bins_);
      constitutive_update(solids, materials, h);
      advect(solids, rigid_material, h);
      keep_inside(solids, bcs);
    }
  }

  // Per material: whether its particles are in the field.
  const std::vector<uint8_t>& in_field() const { return in_field_; }

  Grid<dim> field;  // the solids' grid field (mass; momentum, then velocity after update())

 private:
  Real node_mass(const IVec<dim>& i) const {
    const size_t k = field.find(i);
    return k == Grid<dim>::npos ? Real(0) : field.mass[k];
  }

  std::vector<uint8_t> in_field_;  // per material: in the field
  std::vector<Vec<dim>> increment_;  // subcycle: the shared field's velocity change per sub-step
  ParticleBins bins_;                // subcycle: the solids' bins
  Real full_node_mass_ = 1;
  bool any_ = false;
};

}  // namespace cdmpm
