// wave_gauge.cpp - the "wave_gauge" probe: free-surface elevation above still water at a horizontal position:
// the highest particle (plus half its particle spacing) in the grid column of width dx around the position,
// minus the still level (scene key still_level, by default the level measured there at t = 0, which the gauge
// keeps in checkpoints). Scene keys: position (dim - 1 horizontal coordinates), still_level, material (default:
// the fluids).
#include <cmath>
#include <limits>

#include "parallel/reduction.h"
#include "probe/probe.h"

namespace cdmpm {
namespace {

template <int dim>
class WaveGauge final : public Probe<dim> {
 public:
  WaveGauge(const SceneReader& r, const Node& n, const Scene& scene)
      : Probe<dim>(r, n, scene, {"position", "still_level", "material"}) {
    this->fluids_only_ = true;
    Node pos = r.required(n, "position");
    position_ = r.numbers(pos, dim - 1);
    r.inside(pos, position_, position_, "a position");
    if (n.has("still_level")) still_level_ = r.number(n["still_level"]), given_ = true;
  }
  std::vector<Station> stations() const override {
    return {{this->name_, position_, still_level_, {{"eta", this->name_}}}};
  }
  void init(const Simulation<dim>& sim) override {
    if (!given_) still_level_ = surface_height(sim);
  }
  void sample(const Simulation<dim>& sim, std::vector<double>& out) const override {
    out.push_back(surface_height(sim) - still_level_);
  }
  std::vector<double> save_state() const override { return {still_level_}; }
  bool load_state(const std::vector<double>& s) override {
    if (s.size() != 1) return false;
    still_level_ = s[0];
    return true;
  }

 private:
  double surface_height(const Simulation<dim>& sim) const {
    const auto& P = sim.particles;
    const Real half = Real(0.5) * sim.grid.dx;
    constexpr int up = vertical_axis<dim>;
    double top = -std::numeric_limits<double>::infinity();
    const size_t n = P.size();
#pragma omp parallel for schedule(static) reduction(max : top)
    for (size_t q = 0; q < n; ++q) {
      const Material& m = sim.materials[P.material[q]];
      if (!this->selected(m, P.material[q])) continue;
      bool in = true;
      for (int a = 0; a < dim - 1 && in; ++a) in = std::abs(P.x[q][a] - static_cast<Real>(position_[a])) <= half;
      if (in) top = std::max(top, static_cast<double>(P.x[q][up] + m.half_spacing));
    }
    top = global::max(top);
    return std::isinf(top) ? kNaN : top;
  }
  std::vector<double> position_;
  double still_level_ = kNaN;
  bool given_ = false;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_wave_gauge, WaveGauge)

}  // namespace cdmpm
