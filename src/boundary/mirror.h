// mirror.h - the mirror treatment shared by slip domain walls and static slip boxes (boundary.h): grid-plane
// tests and the fold / unfold of one (ghost, mirror) node pair across a plane normal to an axis.
#pragma once

#include <cmath>

#include "boundary/boundary.h"

namespace cdmpm {

// The grid-plane index nearest to coordinate/dx `cells`, and whether the coordinate lies on that plane (within
// node_tolerance_cells, the tolerance with which a face holds its nodes): the mirror treatment needs faces on
// grid planes.
inline bool on_grid_plane(Real cells, int& index) {
  index = static_cast<int>(std::lround(cells));
  return std::abs(cells - Real(index)) <= node_tolerance_cells;
}

// Fold adds ghost node src's mass and reflected momentum to its mirror node dst.
template <int dim>
void fold_pair(Grid<dim>& g, size_t src, size_t dst, int axis) {
  if (g.mass[src] <= 0) return;
  Vec<dim> mv = g.momentum[src];
  mv[axis] = -mv[axis];
  g.mass[dst] += g.mass[src];
  g.momentum[dst] += mv;
}
// Unfold gives src the reflected velocity of dst.
template <int dim>
void unfold_pair(Grid<dim>& g, size_t src, size_t dst, int axis) {
  Vec<dim> v = g.momentum[dst];
  v[axis] = -v[axis];
  g.momentum[src] = v;
}

template <int dim>
Vec<dim> to_vec(const std::vector<double>& a) {
  Vec<dim> v;
  for (int i = 0; i < dim; ++i) v[i] = static_cast<Real>(a[i]);
  return v;
}

}  // namespace cdmpm
