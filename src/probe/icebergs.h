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
//   volume   = sum V_p (area in 2D),        centroid = sum V_p x_p / sum V_p (the box centre if volume is 0),
//   lo, hi   = bounding box of the x_p,     length = (hi - lo)[flow_axis] + spacing,
//   height   = (hi - lo)[vertical] + spacing,
// so a row of n particles at spacing h has extent n h. Bodies are sorted by decreasing volume (ties: by
// centroid along flow_axis ascending, then by lowest order key: the particle index in one process) and numbered
// 0 (the glacier), 1, 2...
//
// Cost: O(particles + cells of the bounding box of the ice). Cell lookup is a dense array (one int32 per
// cell) over the bounding box of the occupied cells, which is at most the simulation grid; positions may
// be anywhere, including negative. Labeling is union-find over occupied cells.
// Same bits for any split of the work. A cell's mean damage is summed in order-key order (the one-process
// particle order); the bodies' volumes and moments are exact sums (math/exact_sum.h), their boxes minima and
// maxima. So the result does not depend on the thread count, nor on how a distributed run splits the ice: each rank
// finds the components of the cells it is home to (an IcePart), and merge_ice_parts joins them across the rims
// (parallel/rank_icebergs.h). One process is the case of one part with no rim.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/types.h"
#include "math/exact_sum.h"

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

// One part of the detection: the components of intact ice among the particles one process holds (all of them in one
// process; in a distributed run every ice particle of the cells this rank is home to, parallel/rank_icebergs.h),
// with what the merge needs of each component, and the rim: its intact cells that share a face with a cell homed
// on another rank, through which its components may continue there.
template <int dim>
struct IceComponent {
  uint64_t particles = 0;
  uint64_t first = std::numeric_limits<uint64_t>::max();  // lowest order key of its particles
  ExactSum volume;                                         // exact sums: the same bits however the ice is split
  std::array<ExactSum, dim> moment;                        // sum V_p x_p
  Eigen::Matrix<double, dim, 1> lo = Eigen::Matrix<double, dim, 1>::Constant(std::numeric_limits<double>::infinity());
  Eigen::Matrix<double, dim, 1> hi = -lo;
  bool rim = false;  // it has a cell on the rim
};

template <int dim>
struct IcePart {
  using Cell = Eigen::Matrix<int64_t, dim, 1>;
  std::vector<IceComponent<dim>> components;
  std::vector<std::pair<Cell, int32_t>> rim;  // (cell, component) of every intact cell on the rim
  std::vector<int32_t> component;             // per input particle: its component, or -1
};

// The steps of the detection on one part's particles, one method each, on the state they share.
//  x, volume, damage, is_ice: per-particle arrays; key: per-particle order keys (the one-process index, so that a
//  cell's damage is summed in the one-process order), or null for the index itself.
template <int dim>
class IceBodyFinder {
 public:
  using Cell = Eigen::Matrix<int64_t, dim, 1>;

  IceBodyFinder(const std::vector<Vec<dim>>& x, const std::vector<Real>& volume, const std::vector<Real>& damage,
                const std::vector<uint8_t>& is_ice, const std::vector<uint64_t>* key, Real dx, Real damage_threshold)
      : x_(x), volume_(volume), damage_(damage), is_ice_(is_ice), key_(key), dx_(dx), threshold_(damage_threshold),
        n_(x.size()) {}

  // 1. Cell of every ice particle (parallel, order-free) and the bounding box of those cells; false if no ice.
  //    Non-finite ice positions are counted (nonfinite()), not binned.
  bool bin_cells() {
    cell_.resize(n_);
    cmin_ = Cell::Constant(std::numeric_limits<int64_t>::max());
    cmax_ = Cell::Constant(std::numeric_limits<int64_t>::min());
#pragma omp parallel
    {
      Cell tmin = cmin_, tmax = cmax_;
      size_t tbad = 0;
#pragma omp for schedule(static)
      for (size_t p = 0; p < n_; ++p) {
        if (!is_ice_[p]) continue;
        if (!x_[p].allFinite()) {
          ++tbad;
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
        nonfinite_ += tbad;
      }
    }
    return nonfinite_ == 0 && cmin_[0] <= cmax_[0];
  }
  size_t nonfinite() const { return nonfinite_; }

  // 2. Dense slot array over the box (last axis fastest): cell -> occupied-cell number, or -1. A cell is intact if
  // the mean damage of its ice particles, summed in order-key order, is below the threshold.
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
    std::vector<size_t> order;
    for (size_t p = 0; p < n_; ++p)
      if (is_ice_[p]) order.push_back(p);
    if (key_ && !std::is_sorted(order.begin(), order.end(), [&](size_t i, size_t j) { return (*key_)[i] < (*key_)[j]; }))
      std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return (*key_)[i] < (*key_)[j]; });
    std::vector<double> damage_sum;
    std::vector<size_t> count;
    for (size_t p : order) {
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
      const Cell c = coords(occupied_[o]) - cmin_;
      for (int a = 0; a < dim; ++a) {
        if (c[a] + 1 >= extent_[a]) continue;
        const int32_t nb = slot_[occupied_[o] + static_cast<size_t>(stride_[a])];
        if (nb < 0 || !intact_[nb]) continue;
        const int32_t r1 = find(static_cast<int32_t>(o)), r2 = find(nb);
        if (r1 != r2) parent_[std::max(r1, r2)] = std::min(r1, r2);
      }
    }
  }

  // 4. The part: per component the sums over the particles that belong (any order: exact), the rim cells (those with
  // a face neighbour c for which elsewhere(c); none if elsewhere is null), and components off the rim with fewer than
  // min_particles particles dropped as debris (they cannot grow).
  template <class Elsewhere>
  IcePart<dim> part(size_t min_particles, const Elsewhere* elsewhere) {
    IcePart<dim> out;
    std::vector<int32_t> comp_of_root(occupied_.size(), -1);
    out.component.assign(n_, -1);
    for (size_t p = 0; p < n_; ++p) {
      if (!is_ice_[p] || !(damage_[p] < threshold_)) continue;
      const int32_t o = slot_[linear(cell_[p])];
      if (!intact_[o]) continue;
      const int32_t r = find(o);
      if (comp_of_root[r] < 0) {
        comp_of_root[r] = static_cast<int32_t>(out.components.size());
        out.components.emplace_back();
      }
      IceComponent<dim>& a = out.components[comp_of_root[r]];
      out.component[p] = comp_of_root[r];
      const Eigen::Matrix<double, dim, 1> xp = x_[p].template cast<double>();
      ++a.particles;
      a.first = std::min(a.first, key_ ? (*key_)[p] : uint64_t(p));
      a.volume.add(double(volume_[p]));
      for (int d = 0; d < dim; ++d) a.moment[d].add(double(volume_[p]) * xp[d]);
      a.lo = a.lo.cwiseMin(xp);
      a.hi = a.hi.cwiseMax(xp);
    }
    if (elsewhere)
      for (size_t o = 0; o < occupied_.size(); ++o) {
        const int32_t k = intact_[o] ? comp_of_root[find(static_cast<int32_t>(o))] : -1;
        if (k < 0) continue;  // not intact, or no particle of it belongs
        const Cell c = coords(occupied_[o]);
        bool rim = false;
        for (int a = 0; a < dim && !rim; ++a)
          for (int s = -1; s <= 1 && !rim; s += 2) rim = (*elsewhere)(Cell(c + s * Cell::Unit(a)));
        if (!rim) continue;
        out.rim.emplace_back(c, k);
        out.components[k].rim = true;
      }
    // Debris off the rim: dropped here, renumbered.
    std::vector<int32_t> renumber(out.components.size(), -1);
    size_t kept = 0;
    for (size_t k = 0; k < out.components.size(); ++k)
      if (out.components[k].rim || out.components[k].particles >= min_particles) {
        renumber[k] = static_cast<int32_t>(kept);
        if (kept != k) out.components[kept] = out.components[k];
        ++kept;
      }
    out.components.resize(kept);
    for (int32_t& k : out.component)
      if (k >= 0) k = renumber[k];
    for (auto& r : out.rim) r.second = renumber[r.second];
    return out;
  }

 private:
  size_t linear(const Cell& c) const { return static_cast<size_t>((c - cmin_).dot(stride_)); }
  Cell coords(size_t lin) const {
    Cell c;
    for (int a = 0; a < dim; ++a) {
      c[a] = static_cast<int64_t>(lin) / stride_[a];
      lin -= static_cast<size_t>(c[a] * stride_[a]);
    }
    return c + cmin_;
  }
  int32_t find(int32_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }

  const std::vector<Vec<dim>>& x_;
  const std::vector<Real>& volume_;
  const std::vector<Real>& damage_;
  const std::vector<uint8_t>& is_ice_;
  const std::vector<uint64_t>* key_;
  Real dx_, threshold_;
  size_t n_, nonfinite_ = 0;
  std::vector<Cell> cell_;
  Cell cmin_, cmax_, extent_, stride_;
  std::vector<int32_t> slot_, parent_;
  std::vector<size_t> occupied_;  // linear cell index of each occupied cell, by first particle in key order
  std::vector<uint8_t> intact_;
};

// The bodies of the parts (one per process, in rank order): components joined across the rims (a rim cell and an
// intact face neighbour in another part), summed, debris (fewer than min_particles particles) dropped, sorted
// (volume down, then centroid along flow_axis, then lowest order key) and numbered. body_of[part][component] = the
// body id of each part's component, or -1.
template <int dim>
std::vector<IceBody<dim>> merge_ice_parts(const std::vector<IcePart<dim>>& parts, Real spacing, int flow_axis,
                                          size_t min_particles, std::vector<std::vector<int>>& body_of) {
  using Cell = typename IcePart<dim>::Cell;
  using DVec = Eigen::Matrix<double, dim, 1>;
  std::vector<size_t> offset(parts.size() + 1, 0);
  for (size_t r = 0; r < parts.size(); ++r) offset[r + 1] = offset[r] + parts[r].components.size();
  std::vector<size_t> parent(offset.back());
  std::iota(parent.begin(), parent.end(), size_t(0));
  const auto find = [&](size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  // The rims, sorted by cell; each cell is on one part's rim at most (its home).
  std::vector<std::pair<Cell, size_t>> rim;
  for (size_t r = 0; r < parts.size(); ++r)
    for (const auto& [c, k] : parts[r].rim) rim.emplace_back(c, offset[r] + static_cast<size_t>(k));
  const auto less = [](const Cell& a, const Cell& b) {
    return std::lexicographical_compare(a.data(), a.data() + dim, b.data(), b.data() + dim);
  };
  std::sort(rim.begin(), rim.end(), [&](const auto& a, const auto& b) { return less(a.first, b.first); });
  for (const auto& [c, g] : rim)
    for (int a = 0; a < dim; ++a) {  // the + neighbour on each axis: every face once
      const Cell nb = c + Cell::Unit(a);
      const auto it = std::lower_bound(rim.begin(), rim.end(), nb, [&](const auto& e, const Cell& v) { return less(e.first, v); });
      if (it == rim.end() || it->first != nb) continue;
      const size_t r1 = find(g), r2 = find(it->second);
      if (r1 != r2) parent[std::max(r1, r2)] = std::min(r1, r2);
    }
  // Totals per root, in part order (exact sums, min / max: the same for any split).
  std::vector<IceComponent<dim>> total(parent.size());
  for (size_t r = 0; r < parts.size(); ++r)
    for (size_t k = 0; k < parts[r].components.size(); ++k) {
      const IceComponent<dim>& c = parts[r].components[k];
      IceComponent<dim>& t = total[find(offset[r] + k)];
      t.particles += c.particles;
      t.first = std::min(t.first, c.first);
      t.volume += c.volume;
      for (int d = 0; d < dim; ++d) t.moment[d] += c.moment[d];
      t.lo = t.lo.cwiseMin(c.lo);
      t.hi = t.hi.cwiseMax(c.hi);
    }
  std::vector<size_t> roots;
  for (size_t g = 0; g < parent.size(); ++g)
    if (find(g) == g && total[g].particles >= min_particles) roots.push_back(g);
  std::vector<IceBody<dim>> bodies;
  for (size_t g : roots) {
    const IceComponent<dim>& t = total[g];
    IceBody<dim> b;
    b.particles = t.particles;
    const double volume = t.volume.value();
    DVec centroid = (t.lo + t.hi) / 2;
    if (volume > 0)
      for (int d = 0; d < dim; ++d) centroid[d] = t.moment[d].value() / volume;
    b.volume = static_cast<Real>(volume);
    b.centroid = centroid.template cast<Real>();
    b.lo = t.lo.template cast<Real>();
    b.hi = t.hi.template cast<Real>();
    b.length = static_cast<Real>(t.hi[flow_axis] - t.lo[flow_axis] + double(spacing));
    b.height = static_cast<Real>(t.hi[vertical_axis<dim>] - t.lo[vertical_axis<dim>] + double(spacing));
    bodies.push_back(b);
  }
  std::vector<size_t> order(bodies.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    if (bodies[i].volume != bodies[j].volume) return bodies[i].volume > bodies[j].volume;
    if (bodies[i].centroid[flow_axis] != bodies[j].centroid[flow_axis])
      return bodies[i].centroid[flow_axis] < bodies[j].centroid[flow_axis];
    return total[roots[i]].first < total[roots[j]].first;
  });
  std::vector<IceBody<dim>> sorted;
  std::vector<int> id_of_root(parent.size(), -1);
  for (size_t r = 0; r < order.size(); ++r) {
    sorted.push_back(bodies[order[r]]);
    sorted.back().id = static_cast<int>(r);
    id_of_root[roots[order[r]]] = static_cast<int>(r);
  }
  body_of.assign(parts.size(), {});
  for (size_t r = 0; r < parts.size(); ++r)
    for (size_t k = 0; k < parts[r].components.size(); ++k) body_of[r].push_back(id_of_root[find(offset[r] + k)]);
  return sorted;
}

// The argument checks of find_ice_bodies.
template <int dim>
void check_ice_body_arguments(size_t n, const std::vector<Real>& volume, const std::vector<Real>& damage,
                              const std::vector<uint8_t>& is_ice, Real dx, int flow_axis) {
  if (volume.size() != n || damage.size() != n || is_ice.size() != n)
    throw std::invalid_argument("find_ice_bodies: x, volume, damage and is_ice must have the same size");
  if (!(dx > 0)) throw std::invalid_argument("find_ice_bodies: dx must be positive");
  if (flow_axis < 0 || flow_axis >= dim) throw std::invalid_argument("find_ice_bodies: flow_axis out of range");
}

// Connected bodies of intact ice (see the definition above), in one process.
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
  check_ice_body_arguments<dim>(n, volume, damage, is_ice, dx, flow_axis);
  if (label) label->assign(n, -1);
  IceBodyFinder<dim> finder(x, volume, damage, is_ice, nullptr, dx, damage_threshold);
  const bool ice = finder.bin_cells();
  if (finder.nonfinite()) throw std::invalid_argument("find_ice_bodies: non-finite ice particle position");
  if (!ice) return {};
  finder.occupy();
  finder.unite();
  using Never = bool (*)(const typename IceBodyFinder<dim>::Cell&);
  const std::vector<IcePart<dim>> parts{finder.template part<Never>(min_particles, nullptr)};
  std::vector<std::vector<int>> body_of;
  auto bodies = merge_ice_parts<dim>(parts, spacing, flow_axis, min_particles, body_of);
  if (label)
    for (size_t p = 0; p < n; ++p)
      if (parts[0].component[p] >= 0) (*label)[p] = body_of[0][parts[0].component[p]];
  return bodies;
}

}  // namespace cdmpm
