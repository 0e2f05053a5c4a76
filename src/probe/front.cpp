// front.cpp - the "front" probe: the furthest extent of a material along an axis (the outermost particle
// plus half its particle spacing). Scene keys: material, axis (default 0), direction (+1: furthest along
// +axis, default; -1: along -axis).
#include <cmath>
#include <limits>

#include "parallel/reduction.h"
#include "probe/probe.h"

namespace cdmpm {
namespace {

template <int dim>
class Front final : public Probe<dim> {
 public:
  Front(const SceneReader& r, const Node& n, const Scene& scene) : Probe<dim>(r, n, scene, {"material", "axis", "direction"}) {
    if (n.has("axis")) axis_ = r.integer(n["axis"], {0, double(dim - 1)});
    if (n.has("direction")) {
      Node dir = n["direction"];
      if (!dir.j.is_number_integer() || std::abs(dir.j.get<double>()) != 1) r.expected(dir, "an integer 1 or -1");
      direction_ = dir.j.get<int>();
    }
  }
  void sample(const Simulation<dim>& sim, std::vector<double>& out) const override {
    const auto& P = sim.particles;
    const size_t n = P.size();
    const Real dir = static_cast<Real>(direction_);
    double best = -std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(max : best)
    for (size_t q = 0; q < n; ++q) {
      const Material& m = sim.materials[P.material[q]];
      if (this->selected(m, P.material[q])) best = std::max(best, static_cast<double>(dir * P.x[q][axis_] + m.half_spacing));
    }
    best = global::max(best);
    out.push_back(std::isinf(best) ? std::numeric_limits<double>::quiet_NaN() : direction_ * best);
  }

 private:
  int axis_ = 0, direction_ = 1;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_front, Front)

}  // namespace cdmpm
