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
// The columns are measured by probe/column_sampler.h (deterministic for any thread count and number of processes).
#include <cmath>
#include <optional>
#include <vector>

#include "probe/column_sampler.h"
#include "probe/probe.h"

namespace cdmpm {
namespace {

template <int dim>
class Section final : public Probe<dim> {
  static constexpr int H = dim - 1;  // horizontal axes 0 .. H-1; the vertical axis is H
  using Sampler = ColumnSampler<dim>;
  using Point = typename Sampler::Point;
  using Column = typename Sampler::Column;

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
    sampler_.emplace(Sampler::line(stations_));
    if (n.has("still_level")) {
      still_.assign(stations_.size(), r.number(n["still_level"], {}, " (a height [m])"));
      given_ = true;
    } else {
      still_.assign(stations_.size(), kNaN);
    }
  }
  Strings columns() const override {
    Strings out;
    for (const Station& s : stations())
      for (const auto& v : s.variables) out.push_back(v.second);
    return out;
  }
  std::vector<Station> stations() const override {
    static const Strings kFields = dim == 2 ? Strings{"eta", "d", "u", "q"} : Strings{"eta", "d", "u", "v", "qx", "qy"};
    std::vector<Station> out;
    for (size_t k = 0; k < stations_.size(); ++k) {
      Station& s = out.emplace_back();
      // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on name + "_" + ...
      s.name = this->name_;
      if (dim == 3) s.name.append("_").append(std::to_string(k));
      s.position.assign(stations_[k].data(), stations_[k].data() + H);
      s.still_level = still_[k];
      for (const std::string& f : kFields) s.variables.emplace_back(f, std::string(s.name).append("_").append(f));
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
  std::vector<Column> measure(const Simulation<dim>& sim) const {
    return sampler_->measure(sim, [this](const Material& m, int material) { return this->selected(m, material); });
  }

  std::vector<Point> stations_;  // horizontal coordinates of each station
  std::vector<double> still_;    // still level at each station
  bool given_ = false;
  std::optional<Sampler> sampler_;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_section, Section)

}  // namespace cdmpm
