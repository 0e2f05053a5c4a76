// energy_probe.cpp - the totals probes (probe/energy.h): "kinetic_energy" sum 1/2 m |v|^2, "gravitational_energy"
// sum -m g.x, "elastic_energy" sum V0 psi, "total_energy" their sum, and "mass" sum m, over all particles or one
// material's. Scene key: material.
#include "probe/energy.h"
#include "probe/probe.h"

namespace cdmpm {
namespace {

enum class Total { Kinetic, Gravitational, Elastic, Energy, Mass };

template <int dim>
class EnergyProbe final : public Probe<dim> {
 public:
  EnergyProbe(const SceneReader& r, const Node& n, const Scene& scene, Total which)
      : Probe<dim>(r, n, scene, {"material"}), which_(which) {}
  void sample(const Simulation<dim>& sim, std::vector<double>& out) const override {
    const EnergyTotals e = energy_totals(sim.particles, sim.materials, sim.gravity, this->material_index_);
    out.push_back(which_ == Total::Kinetic         ? e.kinetic
                  : which_ == Total::Gravitational ? e.gravitational
                  : which_ == Total::Elastic       ? e.elastic
                  : which_ == Total::Energy        ? e.total()
                                                   : e.mass);
  }

 private:
  Total which_;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_kinetic_energy, EnergyProbe, Total::Kinetic)
CDMPM_PROBE_FACTORY(make_gravitational_energy, EnergyProbe, Total::Gravitational)
CDMPM_PROBE_FACTORY(make_elastic_energy, EnergyProbe, Total::Elastic)
CDMPM_PROBE_FACTORY(make_total_energy, EnergyProbe, Total::Energy)
CDMPM_PROBE_FACTORY(make_mass, EnergyProbe, Total::Mass)

}  // namespace cdmpm
