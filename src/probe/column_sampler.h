// column_sampler.h - the depth-averaged state of the water at horizontal stations, shared by the section probe
// (probe/section.cpp) and the gridded snapshots (run/snapshots.h). Per station X and sample:
//   top, bottom  the highest water particle plus half its spacing and the lowest minus half its spacing in the
//                grid column of width dx around X (the free surface and the bed the water covers);
//   u_bar        the mass-weighted depth-averaged horizontal velocity with the quadratic B-spline weights of the
//                transfer to the grid, u_bar = sum_p N((x_p - X) / dx) m_p v_p / sum_p N((x_p - X) / dx) m_p,
//                the mass-weighted depth average of the velocity that p2g gives the column of grid nodes at X
//                (exact at X for a velocity linear across the kernel; a ratio, so it does not jump when
//                particles enter or leave the column).
// The stations are either a line (k / (S - 1) of the way from the first to the last, any direction) or an
// axis-aligned grid (x fastest); each station visits only the particles within the B-spline support of it.
//
// Deterministic for any thread count and number of processes: a parallel pass only flags the particles near
// the stations (a per-particle write), a serial pass lists them per station in index order, each station sums
// its terms in exact sums (math/exact_sum.h) and takes maxima and minima, all exact in any order, then reduced
// over the processes (parallel/reduction.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/bspline.h"
#include "parallel/reduction.h"
#include "sim/simulation.h"

namespace cdmpm {

template <int dim>
class ColumnSampler {
 public:
  static constexpr int H = dim - 1;  // horizontal axes 0 .. H-1; the vertical axis is H
  using Point = Eigen::Matrix<double, H, 1>;
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  struct Column {
    double top = -kInf, bottom = kInf;  // water surface and bed in the column of width dx (infinite: no water)
    Point u = Point::Zero();            // mass-weighted depth-averaged horizontal velocity
    bool wet() const { return std::isfinite(top); }
  };

  // Stations on a line, from the first to the last.
  static ColumnSampler line(std::vector<Point> stations) { return ColumnSampler(std::move(stations), {}); }
  // Stations on an axis-aligned grid: start + i spacing on each horizontal axis, i < count[axis], x fastest.
  static ColumnSampler grid(const Point& start, double spacing, const std::vector<int>& count) {
    std::vector<Point> s;
    const int ny = H == 2 ? count[1] : 1;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < count[0]; ++i) {
        Point p = start;
        p[0] += i * spacing;
        if constexpr (H == 2) p[1] += j * spacing;
        s.push_back(p);
      }
    ColumnSampler c(std::move(s), count);
    c.spacing_ = spacing;
    return c;
  }

  const std::vector<Point>& stations() const { return stations_; }

  // The columns of the particles for which selected(material model, material index) holds. Collective in a
  // distributed run.
  template <class Selected>
  std::vector<Column> measure(const Simulation<dim>& sim, Selected&& selected) const {
    const auto& P = sim.particles;
    const double dx = sim.grid.dx;
    // Particles within the B-spline support (1.5 dx) of the stations' bounding box, flagged in parallel.
    Point lo = stations_.front(), hi = stations_.front();
    for (const Point& s : stations_) lo = lo.cwiseMin(s), hi = hi.cwiseMax(s);
    lo.array() -= 1.5 * dx;
    hi.array() += 1.5 * dx;
    const size_t n = P.size();
    std::vector<uint8_t> near(n, 0);
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q) {
      bool in = selected(sim.materials[P.material[q]], P.material[q]);
      for (int a = 0; a < H && in; ++a) in = P.x[q][a] >= lo[a] && P.x[q][a] <= hi[a];
      near[q] = in;
    }
    // Each near particle goes to the list of every station whose support may hold it (widened by a relative 1e-6
    // of the support for rounding: particles outside the support add zero), in index order.
    const double reach = 1.5 * dx * (1 + 1e-6);
    const std::vector<std::vector<uint32_t>> lists = count_.empty() ? line_lists(P, near, reach) : grid_lists(P, near, reach);

    std::vector<Column> out(stations_.size());
    std::vector<ExactSum> sums(stations_.size() * (1 + H));  // per station: sum of N m, and of N m v
    const long ns = static_cast<long>(stations_.size());
#pragma omp parallel for schedule(dynamic)
    for (long k = 0; k < ns; ++k) {
      const Point& X = stations_[k];
      Column& c = out[k];
      ExactSum* s = &sums[k * (1 + H)];
      for (const uint32_t q : lists[k]) {
        double w = 1;
        bool column = true;
        for (int a = 0; a < H; ++a) {
          const double r = (P.x[q][a] - X[a]) / dx;
          w *= bspline_kernel(static_cast<Real>(r));
          column = column && std::abs(r) <= 0.5;
        }
        if (w > 0) {
          const double wm = w * P.mass[q];
          s[0].add(wm);
          for (int a = 0; a < H; ++a) s[1 + a].add(wm * P.v[q][a]);
        }
        if (column) {
          const double y = P.x[q][H], hs = sim.materials[P.material[q]].half_spacing;
          c.top = std::max(c.top, y + hs);
          c.bottom = std::min(c.bottom, y - hs);
        }
      }
    }
    // Across processes, outside the threads.
    global::sum(sums);
    std::vector<double> tops(out.size()), bottoms(out.size());
    for (size_t k = 0; k < out.size(); ++k) tops[k] = out[k].top, bottoms[k] = out[k].bottom;
    global::max(tops);
    global::min(bottoms);
    for (size_t k = 0; k < out.size(); ++k) {
      Column& c = out[k];
      c.top = tops[k], c.bottom = bottoms[k];
      const double sw = sums[k * (1 + H)].value();
      if (sw > 0)
        for (int a = 0; a < H; ++a) c.u[a] = sums[k * (1 + H) + 1 + a].value() / sw;
    }
    return out;
  }

 private:
  ColumnSampler(std::vector<Point> stations, std::vector<int> count) : stations_(std::move(stations)), count_(std::move(count)) {}

  // Line: the stations k / (S - 1) along the line whose parameter lies in the particle's interval, widened by one
  // station.
  std::vector<std::vector<uint32_t>> line_lists(const Particles<dim>& P, const std::vector<uint8_t>& near, double reach) const {
    const Point A = stations_.front(), D = stations_.back() - A;  // the line: A + f D, f in [0, 1]
    const int last = static_cast<int>(stations_.size()) - 1;
    std::vector<std::vector<uint32_t>> lists(stations_.size());
    for (size_t q = 0; q < near.size(); ++q) {
      if (!near[q]) continue;
      double f_lo = 0, f_hi = 1;
      for (int a = 0; a < H; ++a) {
        const double p = P.x[q][a] - A[a];
        if (D[a] == 0) {
          if (std::abs(p) > reach) f_lo = 2;  // off the line on this axis: no station
        } else {
          const double f1 = (p - reach) / D[a], f2 = (p + reach) / D[a];
          f_lo = std::max(f_lo, std::min(f1, f2));
          f_hi = std::min(f_hi, std::max(f1, f2));
        }
      }
      if (f_lo > f_hi) continue;
      const int k0 = std::max(0, static_cast<int>(std::floor(f_lo * last)) - 1);
      const int k1 = std::min(last, static_cast<int>(std::ceil(f_hi * last)) + 1);
      for (int k = k0; k <= k1; ++k) lists[k].push_back(static_cast<uint32_t>(q));
    }
    return lists;
  }

  // Grid: on each axis the indices whose station lies within reach of the particle, widened by one.
  std::vector<std::vector<uint32_t>> grid_lists(const Particles<dim>& P, const std::vector<uint8_t>& near, double reach) const {
    const Point A = stations_.front();
    std::vector<std::vector<uint32_t>> lists(stations_.size());
    for (size_t q = 0; q < near.size(); ++q) {
      if (!near[q]) continue;
      int i0[2] = {0, 0}, i1[2] = {0, 0};
      for (int a = 0; a < H; ++a) {
        const double p = P.x[q][a] - A[a];
        i0[a] = std::max(0, static_cast<int>(std::floor((p - reach) / spacing_)) - 1);
        i1[a] = std::min(count_[a] - 1, static_cast<int>(std::ceil((p + reach) / spacing_)) + 1);
      }
      for (int j = i0[1]; j <= i1[1]; ++j)
        for (int i = i0[0]; i <= i1[0]; ++i) lists[static_cast<size_t>(j) * count_[0] + i].push_back(static_cast<uint32_t>(q));
    }
    return lists;
  }

  std::vector<Point> stations_;
  std::vector<int> count_;  // grid: stations per horizontal axis; empty: a line
  double spacing_ = 0;
};

}  // namespace cdmpm
