// probes.cpp - evaluation of the probes (definitions in probes.h).
#include "probe/probes.h"

#include <cmath>
#include <limits>

#include "core/bspline.h"
#include "probe/energy.h"

namespace cdmpm {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
bool selected(const ProbeSpec& p, const Material& m, int material) {
  if (p.material_index >= 0) return material == p.material_index;
  return p.type != "wave_gauge" || m.kind == MaterialKind::Water;
}
}  // namespace

template <int dim>
Probes<dim>::Probes(const Scene& scene, const Simulation<dim>& sim) : scene_(scene) {
  for (const ProbeSpec& p : scene.probes)
    still_levels.push_back(p.type != "wave_gauge" ? kNaN : p.still_level ? *p.still_level : surface_height(sim, p));
}

template <int dim>
std::string Probes<dim>::csv_header() const {
  std::string h = "time";
  for (const ProbeSpec& p : scene_.probes) {
    if (columns(p) == 1) h += "," + p.name;
    else
      for (int a = 0; a < dim; ++a) h += "," + p.name + "_" + "xyz"[a];
  }
  return h;
}

template <int dim>
double Probes<dim>::surface_height(const Simulation<dim>& sim, const ProbeSpec& pr) const {
  const auto& P = sim.particles;
  const Real half = Real(0.5) * sim.grid.dx;
  constexpr int up = vertical_axis<dim>;
  double top = -std::numeric_limits<double>::infinity();
  const size_t n = P.size();
#pragma omp parallel for schedule(static) reduction(max : top)
  for (size_t q = 0; q < n; ++q) {
    const Material& m = sim.materials[P.material[q]];
    if (!selected(pr, m, P.material[q])) continue;
    bool in = true;
    for (int a = 0; a < dim - 1 && in; ++a) in = std::abs(P.x[q][a] - static_cast<Real>(pr.position[a])) <= half;
    if (in) top = std::max(top, static_cast<double>(P.x[q][up] + m.half_spacing));
  }
  return std::isinf(top) ? kNaN : top;
}

template <int dim>
std::vector<double> Probes<dim>::sample(const Simulation<dim>& sim) const {
  const auto& P = sim.particles;
  const size_t n = P.size();
  std::vector<double> out;
  for (size_t i = 0; i < scene_.probes.size(); ++i) {
    const ProbeSpec& pr = scene_.probes[i];
    if (pr.type == "wave_gauge") {
      out.push_back(surface_height(sim, pr) - still_levels[i]);
    } else if (pr.type == "front") {
      const Real dir = static_cast<Real>(pr.direction);
      double best = -std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(max : best)
      for (size_t q = 0; q < n; ++q) {
        const Material& m = sim.materials[P.material[q]];
        if (selected(pr, m, P.material[q])) best = std::max(best, static_cast<double>(dir * P.x[q][pr.axis] + m.half_spacing));
      }
      out.push_back(std::isinf(best) ? kNaN : dir * best);
    } else if (pr.type.starts_with("rigid_")) {
      const RigidBody<dim>& b = sim.rigid.bodies[sim.rigid.index_of_material(pr.material_index)];
      if (pr.type == "rigid_angle") out.push_back(b.angle);
      for (int a = 0; a < dim && pr.type == "rigid_position"; ++a) out.push_back(b.centre[a]);
      for (int a = 0; a < dim && pr.type == "rigid_velocity"; ++a) out.push_back(b.velocity[a]);
    } else if (pr.type == "pressure") {
      Vec<dim> x;
      for (int a = 0; a < dim; ++a) x[a] = static_cast<Real>(pr.position[a]);
      double sw = 0, swp = 0;
#pragma omp parallel for schedule(static) reduction(+ : sw, swp)
      for (size_t q = 0; q < n; ++q) {
        const Material& m = sim.materials[P.material[q]];
        if (!selected(pr, m, P.material[q])) continue;
        Real w = 1;
        for (int a = 0; a < dim && w > 0; ++a) w *= bspline_kernel((P.x[q][a] - x[a]) * sim.grid.inv_dx);
        if (w > 0) {
          sw += w;
          swp += w * particle_pressure(m, P, q);
        }
      }
      out.push_back(sw > 0 ? swp / sw : 0.0);
    } else {
      const EnergyTotals e = energy_totals(P, sim.materials, sim.gravity, pr.material_index);
      out.push_back(pr.type == "kinetic_energy"         ? e.kinetic
                    : pr.type == "gravitational_energy" ? e.gravitational
                    : pr.type == "elastic_energy"       ? e.elastic
                    : pr.type == "total_energy"         ? e.total()
                                                        : e.mass);
    }
  }
  return out;
}

template class Probes<2>;
template class Probes<3>;

}  // namespace cdmpm
