// grid_update.h - grid velocity update: symplectic Euler on the grid, then boundary conditions.
//
//   v_i = (mv)_i / m_i + dt g      for every node with mass (the stress impulse is already in (mv)_i),
// then each boundary's condition on the nodes inside its solid (boundary/boundary.h).
// Nodes without mass are left as they are (p2g gave them zero momentum, so g2p reads v = 0 there).
#pragma once

#include <memory>
#include <vector>

#include "boundary/boundary.h"
#include "grid/grid.h"

namespace cdmpm {

template <int dim>
void grid_update(Grid<dim>& g, const Vec<dim>& gravity, Real dt, const std::vector<std::unique_ptr<Boundary<dim>>>& bcs) {
  g.for_each_node([&](size_t k, const IVec<dim>& i) {
    const Real m = g.mass[k];
    if (m <= 0) return;
    Vec<dim> v = g.momentum[k] / m + dt * gravity;
    if (!bcs.empty()) apply_conditions(bcs, g.position(i), v);
    g.momentum[k] = v;
  });
}

}  // namespace cdmpm
