// section.cpp - the "section" probe: the far-field hand-off to a shallow-water model. At a vertical section
// (2D: x = position) or at `points` stations equally spaced on a horizontal line from `start` to `end` (3D,
// ends included), it records per station and sample what a shallow-water code takes as a boundary condition:
//   eta   free-surface elevation above the still level [m]: the highest water particle (plus half its particle
//         spacing) in the grid column of width dx around the station, minus the still level (scene key
//         still_level, by default the level measured there at t = 0, kept in checkpoints), as the wave gauge;
//   d     total water depth [m]: that surface minus the lowest water particle (minus half its spacing) in the
//         column, i.e. the still depth + eta on a bed that the water covers (the bed is the lowest water, so
//         no bathymetry is needed and a sloping or moving bed is followed);
//   u, v  depth-averaged horizontal velocity [m/s], the mass-weighted mean of the particle velocities with the
//         quadratic B-spline weights of the transfer to the grid (horizontal directions only),
//           u_bar = sum_p N((x_p - X) / dx) m_p v_p / sum_p N((x_p - X) / dx) m_p,
//         which is the mass-weighted depth average of the velocity that p2g gives the column of grid nodes at
//         the station: for a velocity linear across the kernel it is exact at X (N is symmetric), and being a
//         ratio it does not jump when particles enter or leave the column, so q has no counting noise;
//   q     unit-width volume flux [m^2/s], q = d u_bar, the depth integral of the horizontal velocity
//         (the shallow-water continuity equation eta_t + div(d u_bar) = 0; Stoker 1957, Water Waves, part III).
// In 3D u, v and qx, qy are the components along the domain's x and y axes (global, as a shallow-water grid
// takes them; the flux normal to the line is (qx, qy) . n). A station with no water in its column gives
// eta = NaN and d = u = q = 0; one dry at t = 0 has no still level (eta always NaN) unless still_level is given.
//
// Deterministic for any thread count: a parallel pass only flags the particles near the line (a per-particle
// write), a serial pass lists them per station, then each station sums its particles serially in particle index
// order, in double; maxima and minima are exact in any order.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/bspline.h"
#include "parallel/reduction.h"
#include "probe/probe.h"

namespace cdmpm {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <int dim>
class Section final : public Probe<dim> {
  static constexpr int H = dim - 1;  // horizontal axes 0 .. H-1; the vertical axis is H
  using Point = Eigen::Matrix<double, H, 1>;

 public:
  Section(const SceneReader& r, const Node& n, const Scene& scene)
      : Probe<dim>(r, n, scene,
                   dim == 2 ? Strings{"position", "still_level", "material"}
                            : Strings{"start", "end", "points", "still_level", "material"}) {
    this->fluids_only_ = true;
    if constexpr (dim == 2) {
      Node pos = r.required(n, "position");
      const std::vector<double> p = r.numbers(pos, 1);
      r.inside(pos, p, p, "a position");
      stations_.push_back(Point(p[0]));
    } else {
      Node s = r.required(n, "start"), e = r.required(n, "end");
      const std::vector<double> a = r.numbers(s, 2), b = r.numbers(e, 2);
      r.inside(s, a, a, "a horizontal position (x, y)");
      r.inside(e, b, b, "a horizontal position (x, y)");
      if (a == b) r.expected(e, "an end different from start");
      const int points = r.integer(r.required(n, "points"), {2, 10000});
      for (int k = 0; k < points; ++k) {
        const double f = double(k) / (points - 1);
        stations_.push_back(Point((1 - f) * a[0] + f * b[0], (1 - f) * a[1] + f * b[1]));
      }
    }
    if (n.has("still_level")) {
      still_.assign(stations_.size(), r.number(n["still_level"], {}, " (a height [m])"));
      given_ = true;
    } else {
      still_.assign(stations_.size(), kNaN);
    }
  }
  Strings columns() const override {
    static const Strings kFields = dim == 2 ? Strings{"eta", "d", "u", "q"} : Strings{"eta", "d", "u", "v", "qx", "qy"};
    Strings out;
    for (size_t k = 0; k < stations_.size(); ++k) {
      // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on name + "_" + ...
      std::string prefix = this->name_;
      if (dim == 3) prefix.append("_").append(std::to_string(k));
      prefix.append("_");
      for (const std::string& f : kFields) out.push_back(std::string(prefix).append(f));
    }
    return out;
  }
  void init(const Simulation<dim>& sim) override {
    if (given_) return;
    const std::vector<Column> c = measure(sim);
    for (size_t k = 0; k < stations_.size(); ++k) still_[k] = std::isfinite(c[k].top) ? c[k].top : kNaN;
  }
  void sample(const Simulation<dim>& sim, std::vector<double>& out) const override {
    const std::vector<Column> c = measure(sim);
    for (size_t k = 0; k < stations_.size(); ++k) {
      const bool wet = std::isfinite(c[k].top);
      const double d = wet ? c[k].top - c[k].bottom : 0.0;
      out.push_back(wet ? c[k].top - still_[k] : kNaN);
      out.push_back(d);
      for (int a = 0; a < H; ++a) out.push_back(c[k].u[a]);
      for (int a = 0; a < H; ++a) out.push_back(d * c[k].u[a]);
    }
  }
  std::vector<double> save_state() const override { return still_; }
  bool load_state(const std::vector<double>& s) override {
    if (s.size() != stations_.size()) return false;
    still_ = s;
    return true;
  }

 private:
  struct Column {
    double top = -kInf, bottom = kInf;  // water surface and bed in the column of width dx
    double sw = 0;                      // sum of N m, and of N m v: the mass-weighted mean's terms
    Point swv = Point::Zero();
    Point u = Point::Zero();            // mass-weighted depth-averaged horizontal velocity
  };

  std::vector<Column> measure(const Simulation<dim>& sim) const {
    const auto& P = sim.particles;
    const double dx = sim.grid.dx;
    // Particles within the B-spline support (1.5 dx) of the line's bounding box, flagged in parallel.
    Point lo = stations_.front(), hi = stations_.front();
    for (const Point& s : stations_) lo = lo.cwiseMin(s), hi = hi.cwiseMax(s);
    lo.array() -= 1.5 * dx;
    hi.array() += 1.5 * dx;
    const size_t n = P.size();
    std::vector<uint8_t> near(n, 0);
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q) {
      bool in = this->selected(sim.materials[P.material[q]], P.material[q]);
      for (int a = 0; a < H && in; ++a) in = P.x[q][a] >= lo[a] && P.x[q][a] <= hi[a];
      near[q] = in;
    }
    // Each near particle goes to the list of every station whose support may hold it (the stations k/(S-1)
    // along the line whose parameter lies in the particle's interval, widened by one station and a relative
    // 1e-6 of the support for rounding: particles outside the support add zero), so a station visits only its
    // own particles, in index order.
    const std::vector<std::vector<uint32_t>> lists = station_lists(P, near, 1.5 * dx * (1 + 1e-6));

    std::vector<Column> out(stations_.size());
    // Per station: the exact sums (math/exact_sum.h) of N m and of N m v, the same bits for any split of the
    // particles over processes.
    std::vector<ExactSum> sums(stations_.size() * (1 + H));
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
    global::sum(sums);  // across processes, outside the threads
    for (size_t k = 0; k < out.size(); ++k) {
      Column& c = out[k];
      c.sw = sums[k * (1 + H)].value();
      for (int a = 0; a < H; ++a) c.swv[a] = sums[k * (1 + H) + 1 + a].value();
      c.top = global::max(c.top);
      c.bottom = global::min(c.bottom);
      if (c.sw > 0) c.u = c.swv / c.sw;
    }
    return out;
  }

  // The near particles (near[q] != 0) within `reach` of each station on every horizontal axis, or a few more.
  std::vector<std::vector<uint32_t>> station_lists(const Particles<dim>& P, const std::vector<uint8_t>& near,
                                                   double reach) const {
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

  std::vector<Point> stations_;  // horizontal coordinates of each station
  std::vector<double> still_;    // still level at each station
  bool given_ = false;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_section, Section)

}  // namespace cdmpm
