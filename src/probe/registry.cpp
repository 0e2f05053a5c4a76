// registry.cpp - the probe registry: the scene "type" of each probe and the function that builds it (one file
// per type). Adding a probe type: its file, and one line in kRegistry below (and docs/scenes.md).
#include "probe/probe.h"

namespace cdmpm {

template <int dim>
using ProbeFactory = std::unique_ptr<Probe<dim>> (*)(const SceneReader&, const Node&, const Scene&);

#define CDMPM_DECLARE(f) template <int dim> std::unique_ptr<Probe<dim>> f(const SceneReader&, const Node&, const Scene&);
CDMPM_DECLARE(make_wave_gauge)
CDMPM_DECLARE(make_section)
CDMPM_DECLARE(make_front)
CDMPM_DECLARE(make_pressure_probe)
CDMPM_DECLARE(make_kinetic_energy)
CDMPM_DECLARE(make_gravitational_energy)
CDMPM_DECLARE(make_elastic_energy)
CDMPM_DECLARE(make_total_energy)
CDMPM_DECLARE(make_mass)
CDMPM_DECLARE(make_rigid_position)
CDMPM_DECLARE(make_rigid_velocity)
CDMPM_DECLARE(make_rigid_angle)
#undef CDMPM_DECLARE

namespace {

struct Entry {
  const char* type;
  ProbeFactory<2> make2;
  ProbeFactory<3> make3;
};
#define CDMPM_PROBE(name, factory) Entry{name, factory<2>, factory<3>}
const Entry kRegistry[] = {
    CDMPM_PROBE("wave_gauge", make_wave_gauge),
    CDMPM_PROBE("section", make_section),
    CDMPM_PROBE("front", make_front),
    CDMPM_PROBE("pressure", make_pressure_probe),
    CDMPM_PROBE("kinetic_energy", make_kinetic_energy),
    CDMPM_PROBE("gravitational_energy", make_gravitational_energy),
    CDMPM_PROBE("elastic_energy", make_elastic_energy),
    CDMPM_PROBE("total_energy", make_total_energy),
    CDMPM_PROBE("mass", make_mass),
    CDMPM_PROBE("rigid_position", make_rigid_position),
    CDMPM_PROBE("rigid_velocity", make_rigid_velocity),
    CDMPM_PROBE("rigid_angle", make_rigid_angle),
};
#undef CDMPM_PROBE

}  // namespace

Strings probe_types() {
  Strings out;
  for (const Entry& e : kRegistry) out.push_back(e.type);
  return out;
}

template <int dim>
Probe<dim>::Probe(const SceneReader& r, const Node& n, const Scene& scene, Strings keys, bool takes_material) {
  keys.insert(keys.end(), {"name", "type"});
  r.object(n, keys);
  Node name = r.required(n, "name");
  name_ = r.string(name);
  if (!is_identifier(name_) || name_ == "time")
    r.expected(name, "a non-empty name of letters, digits and '_', other than \"time\"");
  for (const auto& other : scene.probes)
    if (other.name == name_) r.expected(name, "a unique probe name");
  if (takes_material && n.has("material")) {
    material_index_ = scene.material_index(r.string(n["material"]));
    if (material_index_ < 0) {
      Strings names;
      for (const auto& m : scene.materials) names.push_back(m.name);
      r.expected(n["material"], "the name of a material (" + join(names, true) + ")");
    }
  }
}

template <int dim>
std::unique_ptr<Probe<dim>> make_probe(const SceneReader& r, const Node& n, const Scene& scene) {
  if (!n.j.is_object()) r.expected(n, "an object");
  const std::string type = r.string(r.required(n, "type"), probe_types());
  for (const Entry& e : kRegistry)
    if (type == e.type) {
      if constexpr (dim == 2) return e.make2(r, n, scene);
      else return e.make3(r, n, scene);
    }
  r.expected(n["type"], "a registered probe type");  // not reached: string() checked the choice
}

template <int dim>
std::vector<std::unique_ptr<Probe<dim>>> make_probes(const Scene& scene) {
  SceneReader r(scene.path, dim);
  r.set_domain(scene.domain.size);
  Scene before = scene;  // the probes before each one, for its unique-name check
  before.probes.clear();
  std::vector<std::unique_ptr<Probe<dim>>> out;
  for (const ProbeSpec& p : scene.probes) {
    out.push_back(make_probe<dim>(r, Node{p.json, p.path}, before));
    before.probes.push_back(p);
  }
  return out;
}

template class Probe<2>;
template class Probe<3>;
template std::unique_ptr<Probe<2>> make_probe<2>(const SceneReader&, const Node&, const Scene&);
template std::unique_ptr<Probe<3>> make_probe<3>(const SceneReader&, const Node&, const Scene&);
template std::vector<std::unique_ptr<Probe<2>>> make_probes<2>(const Scene&);
template std::vector<std::unique_ptr<Probe<3>>> make_probes<3>(const Scene&);

}  // namespace cdmpm
