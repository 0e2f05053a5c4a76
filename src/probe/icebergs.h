// icebergs.h - iceberg detection: the connected bodies of intact ice, the largest being the glacier.
//
// Definition. Ice particles are binned into grid cells of size dx: particle p is in cell c with
// c[a] = floor(x_p[a] / dx) on each axis (computed in Real arithmetic, see ice_cell_coord), so cell c
// covers [c dx, (c+1) dx) and a position exactly on a face (x / dx an integer in floating point) goes to
// the cell above it; the same position always goes to the same cell. A cell is "intact ice" if it holds at
// least one ice particle and the mean damage of its ice particles is below damage_threshold. Intact cells
// sharing a face (4-neighbourhood in 2D, 6 in 3D; touching only at an edge or a corner is no contact) form
// components. An ice particle belongs to its cell's component if its own damage is below damage_threshold;
// damaged particles, and particles of non-intact cells, belong to none. Non-ice particles (e.g. water) are
// ignored entirely: they neither occupy cells nor connect them. Components with fewer than min_particles
// particles are dropped as debris. Each remaining component is an IceBody with
//   volume   = sum V_p (area in 2D),        centroid = sum V_p x_p / sum V_p (mean position if volume is 0),
//   lo, hi   = bounding box of the x_p,     length = (hi - lo)[flow_axis] + spacing,
//   height   = (hi - lo)[vertical] + spacing,
// so a row of n particles at spacing h has extent n h. Bodies are sorted by decreasing volume (ties: by
// centroid along flow_axis ascending, then by lowest particle index) and numbered 0 (the glacier), 1, 2...
//
// Cost: O(particles + cells of the bounding box of the ice). Cell lookup is a dense array (one int32 per
// cell) over the bounding box of the occupied cells, which is at most the simulation grid; positions may
// be anywhere, including negative. Labeling is union-find over occupied cells. The result is computed in
// a fixed order (occupied cells numbered by their first particle; sums in particle index order, in double)
// so it does not depend on the thread count; only the per-particle binning runs in parallel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/types.h"

namespace cdmpm {

template <int dim>
struct IceBody {
  int id = -1;             // 0 = the glacier (largest volume), 1.. = icebergs by decreasing volume
  size_t particles = 0;    // number of intact particles in it
  Real volume = 0;         // sum of the particle volumes (area in 2D)
  Real length = 0;         // extent along flow_axis: max - min of particle positions + spacing
  Real height = 0;         // extent along the vertical axis (dim-1), same rule
  Vec<dim> centroid = Vec<dim>::Zero();  // volume-weighted mean position
  Vec<dim> lo = Vec<dim>::Zero(), hi = Vec<dim>::Zero();  // bounding box of the particle positions
};

// Cell coordinate of position component x: floor(x / dx). The single place the binning rule lives.
inline int64_t ice_cell_coord(Real x, Real dx) { return static_cast<int64_t>(std::floor(x / dx)); }

// Connected bodies of intact ice (see the definition above).
//  x, volume, damage: per-particle arrays (all particles of the simulation);
//  is_ice: per-particle flag selecting ice particles (others, e.g. water, are ignored);
//  dx: grid cell size; damage_threshold: e.g. 0.5; min_particles: smaller components are dropped;
//  spacing: particle spacing added to extents; flow_axis: axis of `length` and of the tie-break.
//  Returns bodies sorted by volume, largest first, ids 0,1,2...; fills `label` (if non-null) with each
//  particle's body id or -1. Throws std::invalid_argument on mismatched sizes, dx <= 0, a bad flow_axis or
//  a non-finite ice position.
template <int dim>
std::vector<IceBody<dim>> find_ice_bodies(const std::vector<Vec<dim>>& x, const std::vector<Real>& volume,
                                          const std::vector<Real>& damage, const std::vector<uint8_t>& is_ice,
                                          Real dx, Real spacing, int flow_axis, Real damage_threshold,
                                          size_t min_particles, std::vector<int>* label = nullptr) {
  const size_t n = x.size();
  if (volume.size() != n || damage.size() != n || is_ice.size() != n)
    throw std::invalid_argument("find_ice_bodies: x, volume, damage and is_ice must have the same size");
  if (!(dx > 0)) throw std::invalid_argument("find_ice_bodies: dx must be positive");
  if (flow_axis < 0 || flow_axis >= dim) throw std::invalid_argument("find_ice_bodies: flow_axis out of range");
  if (label) label->assign(n, -1);

  // 1. Cell of every ice particle (parallel, order-free) and the bounding box of those cells.
  using Cell = Eigen::Matrix<int64_t, dim, 1>;
  std::vector<Cell> cell(n);
  Cell cmin = Cell::Constant(std::numeric_limits<int64_t>::max());
  Cell cmax = Cell::Constant(std::numeric_limits<int64_t>::min());
  bool finite = true;
#pragma omp parallel
  {
    Cell tmin = cmin, tmax = cmax;
    bool tfinite = true;
#pragma omp for schedule(static)
    for (size_t p = 0; p < n; ++p) {
      if (!is_ice[p]) continue;
      if (!x[p].allFinite()) {
        tfinite = false;
        continue;
      }
      for (int a = 0; a < dim; ++a) cell[p][a] = ice_cell_coord(x[p][a], dx);
      tmin = tmin.cwiseMin(cell[p]);
      tmax = tmax.cwiseMax(cell[p]);
    }
#pragma omp critical(cdmpm_icebergs_bbox)
    {
      cmin = cmin.cwiseMin(tmin);
      cmax = cmax.cwiseMax(tmax);
      finite = finite && tfinite;
    }
  }
  if (!finite) throw std::invalid_argument("find_ice_bodies: non-finite ice particle position");
  if (cmin[0] > cmax[0]) return {};  // no ice

  // 2. Dense slot array over the box (last axis fastest): cell -> occupied-cell number, or -1.
  Cell extent = cmax - cmin + Cell::Ones(), stride;
  size_t box = 1;
  for (int a = dim - 1; a >= 0; --a) {
    stride[a] = static_cast<int64_t>(box);
    if (static_cast<double>(box) * static_cast<double>(extent[a]) > double(std::numeric_limits<int32_t>::max()))
      throw std::invalid_argument("find_ice_bodies: the ice spans more than 2^31 cells of size dx");
    box *= static_cast<size_t>(extent[a]);
  }
  const auto linear = [&](const Cell& c) { return static_cast<size_t>((c - cmin).dot(stride)); };
  std::vector<int32_t> slot(box, -1);
  std::vector<size_t> occupied;  // linear cell index of each occupied cell, by first particle
  std::vector<double> damage_sum;
  std::vector<size_t> count;
  for (size_t p = 0; p < n; ++p) {
    if (!is_ice[p]) continue;
    const size_t c = linear(cell[p]);
    if (slot[c] < 0) {
      slot[c] = static_cast<int32_t>(occupied.size());
      occupied.push_back(c);
      damage_sum.push_back(0);
      count.push_back(0);
    }
    damage_sum[slot[c]] += damage[p];
    ++count[slot[c]];
  }
  const size_t m = occupied.size();
  std::vector<uint8_t> intact(m);
  for (size_t o = 0; o < m; ++o) intact[o] = damage_sum[o] / double(count[o]) < double(damage_threshold);

  // 3. Union-find over intact cells through faces; the root is always the lowest occupied-cell number.
  std::vector<int32_t> parent(m);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (size_t o = 0; o < m; ++o) {
    if (!intact[o]) continue;
    size_t rest = occupied[o];
    for (int a = 0; a < dim; ++a) {
      const int64_t coord = static_cast<int64_t>(rest) / stride[a];
      rest -= static_cast<size_t>(coord * stride[a]);
      if (coord + 1 >= extent[a]) continue;
      const int32_t nb = slot[occupied[o] + static_cast<size_t>(stride[a])];
      if (nb < 0 || !intact[nb]) continue;
      const int32_t r1 = find(static_cast<int32_t>(o)), r2 = find(nb);
      if (r1 != r2) parent[std::max(r1, r2)] = std::min(r1, r2);
    }
  }

  // 4. Per-component sums over the particles that belong, in particle index order.
  struct Acc {
    size_t particles = 0, first = 0;
    double volume = 0;
    Eigen::Matrix<double, dim, 1> moment, sum, lo, hi;
  };
  std::vector<int32_t> comp_of_root(m, -1);
  std::vector<Acc> acc;
  std::vector<int32_t> comp(n, -1);
  for (size_t p = 0; p < n; ++p) {
    if (!is_ice[p] || !(damage[p] < damage_threshold)) continue;
    const int32_t o = slot[linear(cell[p])];
    if (!intact[o]) continue;
    const int32_t r = find(o);
    const Eigen::Matrix<double, dim, 1> xp = x[p].template cast<double>();
    if (comp_of_root[r] < 0) {
      comp_of_root[r] = static_cast<int32_t>(acc.size());
      Acc a;
      a.first = p;
      a.moment = a.sum = Eigen::Matrix<double, dim, 1>::Zero();
      a.lo = a.hi = xp;
      acc.push_back(a);
    }
    Acc& a = acc[comp_of_root[r]];
    comp[p] = comp_of_root[r];
    ++a.particles;
    a.volume += double(volume[p]);
    a.moment += double(volume[p]) * xp;
    a.sum += xp;
    a.lo = a.lo.cwiseMin(xp);
    a.hi = a.hi.cwiseMax(xp);
  }

  // 5. Drop debris, sort, number; relabel particles.
  std::vector<int32_t> keep;
  for (size_t k = 0; k < acc.size(); ++k)
    if (acc[k].particles >= min_particles) keep.push_back(static_cast<int32_t>(k));
  std::vector<IceBody<dim>> bodies;
  bodies.reserve(keep.size());
  for (int32_t k : keep) {
    const Acc& a = acc[k];
    IceBody<dim> b;
    b.particles = a.particles;
    b.volume = static_cast<Real>(a.volume);
    b.centroid = (a.volume > 0 ? Eigen::Matrix<double, dim, 1>(a.moment / a.volume)
                               : Eigen::Matrix<double, dim, 1>(a.sum / double(a.particles)))
                     .template cast<Real>();
    b.lo = a.lo.template cast<Real>();
    b.hi = a.hi.template cast<Real>();
    b.length = static_cast<Real>(a.hi[flow_axis] - a.lo[flow_axis] + double(spacing));
    b.height = static_cast<Real>(a.hi[vertical_axis<dim>] - a.lo[vertical_axis<dim>] + double(spacing));
    bodies.push_back(b);
  }
  std::vector<size_t> order(bodies.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    if (bodies[i].volume != bodies[j].volume) return bodies[i].volume > bodies[j].volume;
    if (bodies[i].centroid[flow_axis] != bodies[j].centroid[flow_axis])
      return bodies[i].centroid[flow_axis] < bodies[j].centroid[flow_axis];
    return acc[keep[i]].first < acc[keep[j]].first;
  });
  std::vector<IceBody<dim>> sorted;
  sorted.reserve(bodies.size());
  std::vector<int> id_of_comp(acc.size(), -1);
  for (size_t r = 0; r < order.size(); ++r) {
    sorted.push_back(bodies[order[r]]);
    sorted.back().id = static_cast<int>(r);
    id_of_comp[keep[order[r]]] = static_cast<int>(r);
  }
  if (label)
    for (size_t p = 0; p < n; ++p)
      if (comp[p] >= 0) (*label)[p] = id_of_comp[comp[p]];
  return sorted;
}

}  // namespace cdmpm
