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
// (docs/validation.md, buoyancy). The contact is node by node, so the result does not depend on the thread count.
// One process only (refused under mpirun, sim/simulation.cpp: the halo exchange carries one field); a rigid body in
// contact beside it is refused by the scene loader (its contact meets the shared field only).
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
#include "material/material.h"
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

  // The field's grid update, then the contact with the shared field (velocities in both, after grid_update).
  void update(Grid<dim>& shared, const Vec<dim>& gravity, Real dt, const std::vector<std::unique_ptr<Boundary<dim>>>& bcs) {
    grid_update(field, gravity, dt, bcs);
    const Real inv_2dx = Real(0.5) * field.inv_dx;
    field.for_each_node([&](size_t k, const IVec<dim>& i) {
      const Real ms = field.mass[k], mo = shared.mass[k];
      if (ms <= 0 || mo <= 0) return;
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
      Vec<dim>& vo = shared.momentum[k];
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

  Grid<dim> field;  // the solids' grid field (mass; momentum, then velocity after update())

 private:
  Real node_mass(const IVec<dim>& i) const {
    const size_t k = field.find(i);
    return k == Grid<dim>::npos ? Real(0) : field.mass[k];
  }

  std::vector<uint8_t> in_field_;  // per material: in the field
  Real full_node_mass_ = 1;
  bool any_ = false;
};

}  // namespace cdmpm
