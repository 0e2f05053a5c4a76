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
// The steps of find_ice_bodies, one method each, on the state they share.
template <int dim>
class IceBodyFinder {
 public:
  using Cell = Eigen::Matrix<int64_t, dim, 1>;
  using DVec = Eigen::Matrix<double, dim, 1>;

  IceBodyFinder(const std::vector<Vec<dim>>& x, const std::vector<Real>& volume, const std::vector<Real>& damage,
                const std::vector<uint8_t>& is_ice, Real dx, Real damage_threshold)
      : x_(x), volume_(volume), damage_(damage), is_ice_(is_ice), dx_(dx), threshold_(damage_threshold), n_(x.size()) {}

  // 1. Cell of every ice particle (parallel, order-free) and the bounding box of those cells; false if no ice.
  bool bin_cells() {
    cell_.resize(n_);
    cmin_ = Cell::Constant(std::numeric_limits<int64_t>::max());
    cmax_ = Cell::Constant(std::numeric_limits<int64_t>::min());
    bool finite = true;
#pragma omp parallel
    {
      Cell tmin = cmin_, tmax = cmax_;
      bool tfinite = true;
#pragma omp for schedule(static)
      for (size_t p = 0; p < n_; ++p) {
        if (!is_ice_[p]) continue;
        if (!x_[p].allFinite()) {
          tfinite = false;
          continue;
        }
        for (int a = 0; a < dim; ++a) cell_[p][a] = ice_cell_coord(x_[p][a], dx_);
        tmin = tmin.cwiseMin(cell_[p]);
        tmax = tmax.cwiseMax(cell_[p]);
      }
#pragma omp critical(cdmpm_icebergs_bbox)
      {
        cmin_ = cmin_.cwiseMin(tmin);
        cmax_ = cmax_.cwiseMax(tmax);
        finite = finite && tfinite;
      }
    }
    if (!finite) throw std::invalid_argument("find_ice_bodies: non-finite ice particle position");
    return cmin_[0] <= cmax_[0];
  }

  // 2. Dense slot array over the box (last axis fastest): cell -> occupied-cell number, or -1; each occupied
  // cell numbered by its first particle, intact if its mean damage is below the threshold.
  void occupy() {
    extent_ = cmax_ - cmin_ + Cell::Ones();
    size_t box = 1;
    for (int a = dim - 1; a >= 0; --a) {
      stride_[a] = static_cast<int64_t>(box);
      if (static_cast<double>(box) * static_cast<double>(extent_[a]) > double(std::numeric_limits<int32_t>::max()))
        throw std::invalid_argument("find_ice_bodies: the ice spans more than 2^31 cells of size dx");
      box *= static_cast<size_t>(extent_[a]);
    }
    slot_.assign(box, -1);
    std::vector<double> damage_sum;
    std::vector<size_t> count;
    for (size_t p = 0; p < n_; ++p) {
      if (!is_ice_[p]) continue;
      const size_t c = linear(cell_[p]);
      if (slot_[c] < 0) {
        slot_[c] = static_cast<int32_t>(occupied_.size());
        occupied_.push_back(c);
        damage_sum.push_back(0);
        count.push_back(0);
      }
      damage_sum[slot_[c]] += damage_[p];
      ++count[slot_[c]];
    }
    intact_.resize(occupied_.size());
    for (size_t o = 0; o < occupied_.size(); ++o) intact_[o] = damage_sum[o] / double(count[o]) < double(threshold_);
  }

  // 3. Union-find over intact cells through faces; the root is always the lowest occupied-cell number.
  void unite() {
    const size_t m = occupied_.size();
    parent_.resize(m);
    std::iota(parent_.begin(), parent_.end(), 0);
    for (size_t o = 0; o < m; ++o) {
      if (!intact_[o]) continue;
      size_t rest = occupied_[o];
      for (int a = 0; a < dim; ++a) {
        const int64_t coord = static_cast<int64_t>(rest) / stride_[a];
        rest -= static_cast<size_t>(coord * stride_[a]);
        if (coord + 1 >= extent_[a]) continue;
        const int32_t nb = slot_[occupied_[o] + static_cast<size_t>(stride_[a])];
        if (nb < 0 || !intact_[nb]) continue;
        const int32_t r1 = find(static_cast<int32_t>(o)), r2 = find(nb);
        if (r1 != r2) parent_[std::max(r1, r2)] = std::min(r1, r2);
      }
    }
  }

  // 4. Per-component sums over the particles that belong, in particle index order.
  void accumulate() {
    std::vector<int32_t> comp_of_root(occupied_.size(), -1);
    comp_.assign(n_, -1);
    for (size_t p = 0; p < n_; ++p) {
      if (!is_ice_[p] || !(damage_[p] < threshold_)) continue;
      const int32_t o = slot_[linear(cell_[p])];
      if (!intact_[o]) continue;
      const int32_t r = find(o);
      const DVec xp = x_[p].template cast<double>();
      if (comp_of_root[r] < 0) {
        comp_of_root[r] = static_cast<int32_t>(acc_.size());
        acc_.push_back({0, p, 0, DVec::Zero(), DVec::Zero(), xp, xp});
      }
      Acc& a = acc_[comp_of_root[r]];
      comp_[p] = comp_of_root[r];
      ++a.particles;
      a.volume += double(volume_[p]);
      a.moment += double(volume_[p]) * xp;
      a.sum += xp;
      a.lo = a.lo.cwiseMin(xp);
      a.hi = a.hi.cwiseMax(xp);
    }
  }

  // 5. Drop debris, sort (volume down, then centroid along flow_axis, then first particle), number; relabel.
  std::vector<IceBody<dim>> bodies(Real spacing, int flow_axis, size_t min_particles, std::vector<int>* label) const {
    std::vector<int32_t> keep;
    for (size_t k = 0; k < acc_.size(); ++k)
      if (acc_[k].particles >= min_particles) keep.push_back(static_cast<int32_t>(k));
    std::vector<IceBody<dim>> bodies;
    for (int32_t k : keep) bodies.push_back(body(acc_[k], spacing, flow_axis));
    std::vector<size_t> order(bodies.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
      if (bodies[i].volume != bodies[j].volume) return bodies[i].volume > bodies[j].volume;
      if (bodies[i].centroid[flow_axis] != bodies[j].centroid[flow_axis])
        return bodies[i].centroid[flow_axis] < bodies[j].centroid[flow_axis];
      return acc_[keep[i]].first < acc_[keep[j]].first;
    });
    std::vector<IceBody<dim>> sorted;
    std::vector<int> id_of_comp(acc_.size(), -1);
    for (size_t r = 0; r < order.size(); ++r) {
      sorted.push_back(bodies[order[r]]);
      sorted.back().id = static_cast<int>(r);
      id_of_comp[keep[order[r]]] = static_cast<int>(r);
    }
    if (label)
      for (size_t p = 0; p < n_; ++p)
        if (comp_[p] >= 0) (*label)[p] = id_of_comp[comp_[p]];
    return sorted;
  }

 private:
  struct Acc {
    size_t particles = 0, first = 0;
    double volume = 0;
    DVec moment, sum, lo, hi;
  };
  static IceBody<dim> body(const Acc& a, Real spacing, int flow_axis) {
    IceBody<dim> b;
    b.particles = a.particles;
    b.volume = static_cast<Real>(a.volume);
    b.centroid = (a.volume > 0 ? DVec(a.moment / a.volume) : DVec(a.sum / double(a.particles))).template cast<Real>();
    b.lo = a.lo.template cast<Real>();
    b.hi = a.hi.template cast<Real>();
    b.length = static_cast<Real>(a.hi[flow_axis] - a.lo[flow_axis] + double(spacing));
    b.height = static_cast<Real>(a.hi[vertical_axis<dim>] - a.lo[vertical_axis<dim>] + double(spacing));
    return b;
  }
  size_t linear(const Cell& c) const { return static_cast<size_t>((c - cmin_).dot(stride_)); }
  int32_t find(int32_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }

  const std::vector<Vec<dim>>& x_;
  const std::vector<Real>& volume_;
  const std::vector<Real>& damage_;
  const std::vector<uint8_t>& is_ice_;
  Real dx_, threshold_;
  size_t n_;
  std::vector<Cell> cell_;
  Cell cmin_, cmax_, extent_, stride_;
  std::vector<int32_t> slot_, parent_, comp_;
  std::vector<size_t> occupied_;  // linear cell index of each occupied cell, by first particle
  std::vector<uint8_t> intact_;
  std::vector<Acc> acc_;
};

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
  IceBodyFinder<dim> finder(x, volume, damage, is_ice, dx, damage_threshold);
  if (!finder.bin_cells()) return {};  // no ice
  finder.occupy();
  finder.unite();
  finder.accumulate();
  return finder.bodies(spacing, flow_axis, min_particles, label);
}

}  // namespace cdmpm
