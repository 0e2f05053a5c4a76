// mirror_zone.h - the blocks that the slip walls' fold and unfold join (boundary/walls.cpp, boundary/mirror.h), so
// that a distributed run may cut anywhere in the block order, also between a wall's ghost node and its mirror node
// (docs/architecture.md, "Distributed runs").
//
// Along axis a the mirror pairs of the lower face (ghost node -k, mirror node k, k = 1 .. ghost) lie in the block
// coordinates 0 .. 1, those of the upper face (top + k, top - k, top = the face's node) in the blocks of the nodes
// top - ghost .. top + ghost: the two zone ranges of the axis. Folds chain axis by axis (a corner ghost is folded
// along x onto a node that is itself a ghost along y, and so on), and the unfold runs the chain backwards, so the
// nodes of block c after fold, grid update and unfold depend on the nodes, after the halo sum, of the blocks
//   D(c) = S_0(c_0) x S_1(c_1) x ...,  S_a(c_a) = the zone range(s) of axis a holding c_a, or {c_a} if none does.
// D is symmetric (c' in D(c) exactly when c in D(c')). A rank that owns an active block c holds complete copies of
// the active blocks of D(c) (parallel/halo_exchange.h, step 3) and then folds, updates and unfolds them exactly as
// one process does. Every face is treated so whatever its boundary (at worst a few blocks are copied needlessly).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "grid/grid.h"

namespace cdmpm {

template <int dim>
class MirrorZone {
 public:
  MirrorZone() = default;
  MirrorZone(const Grid<dim>& g, const Vec<dim>& domain_size) {
    constexpr int ghost = Grid<dim>::ghost, shift = Grid<dim>::block_shift;
    for (int a = 0; a < dim; ++a) {
      const int top = static_cast<int>(std::lround(domain_size[a] * g.inv_dx));
      const int last = g.n_blocks[a] - 1;
      range_[a][0] = {0, std::min(1, last)};
      range_[a][1] = {std::clamp((top - ghost + ghost) >> shift, 0, last), std::clamp((top + ghost + ghost) >> shift, 0, last)};
    }
  }

  // The block coordinates S_a(c) along axis a (ascending, distinct).
  std::vector<int> along(int a, int c) const {
    std::vector<int> s;
    for (const auto& r : range_[a])
      if (r[0] <= c && c <= r[1])
        for (int k = r[0]; k <= r[1]; ++k) s.push_back(k);
    if (s.empty()) s.push_back(c);
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
  }

  // True if block b lies in a zone range along some axis (D(b) holds more than b).
  bool holds(const Grid<dim>& g, size_t b) const {
    const IVec<dim> c = g.block_coords(b);
    for (int a = 0; a < dim; ++a)
      for (const auto& r : range_[a])
        if (r[0] <= c[a] && c[a] <= r[1]) return true;
    return false;
  }

  // Calls f(block index) for every block of D(b), b included.
  template <class F>
  void for_each_dependency(const Grid<dim>& g, size_t b, F&& f) const {
    const IVec<dim> c = g.block_coords(b);
    std::array<std::vector<int>, dim> s;
    for (int a = 0; a < dim; ++a) s[a] = along(a, c[a]);
    std::array<size_t, dim> at{};
    while (true) {
      IVec<dim> d;
      for (int a = 0; a < dim; ++a) d[a] = s[a][at[a]];
      f(g.block_index(d));
      int a = dim - 1;
      for (; a >= 0; --a) {
        if (++at[a] < s[a].size()) break;
        at[a] = 0;
      }
      if (a < 0) return;
    }
  }

 private:
  std::array<std::array<std::array<int, 2>, 2>, dim> range_{};  // per axis: the lower and the upper face's [lo, hi]
};

}  // namespace cdmpm
