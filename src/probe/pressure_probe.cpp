// pressure_probe.cpp - the "pressure" probe: the B-spline weighted average of particle pressures around a point
// (kernel width 3 dx), p(x) = sum_p N(x_p - x) p_p / sum_p N(x_p - x); zero where no particle is near.
// Scene key: position (dim coordinates). The sums are exact (math/exact_sum.h): the same bits for any number of
// threads and processes.
#include "core/bspline.h"
#include "material/stress.h"
#include "parallel/reduction.h"
#include "probe/probe.h"

namespace cdmpm {
namespace {

template <int dim>
class PressureProbe final : public Probe<dim> {
 public:
  PressureProbe(const SceneReader& r, const Node& n, const Scene& scene) : Probe<dim>(r, n, scene, {"position"}, false) {
    Node pos = r.required(n, "position");
    const std::vector<double> p = r.numbers(pos, dim);
    r.inside(pos, p, p, "a position");
    for (int a = 0; a < dim; ++a) x_[a] = static_cast<Real>(p[a]);
  }
  void sample(const Simulation<dim>& sim, std::vector<double>& out) const override {
    const auto& P = sim.particles;
    const size_t n = P.size();
    std::vector<ExactSum> s = exact_sums(2, n, [&](size_t q, ExactSum* acc) {
      const Material& m = sim.materials[P.material[q]];
      if (!this->selected(m, P.material[q])) return;
      Real w = 1;
      for (int a = 0; a < dim && w > 0; ++a) w *= bspline_kernel((P.x[q][a] - x_[a]) * sim.grid.inv_dx);
      if (w > 0) {
        acc[0].add(w);
        acc[1].add(w * particle_pressure(m, P, q));
      }
    });
    global::sum(s);
    const double sw = s[0].value(), swp = s[1].value();
    out.push_back(sw > 0 ? swp / sw : 0.0);
  }

 private:
  Vec<dim> x_;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_pressure_probe, PressureProbe)

}  // namespace cdmpm
