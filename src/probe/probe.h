// probe.h - a point or integral measurement sampled into probes.csv at a fixed interval: the interface every
// probe type implements, and the registry that builds them (one file per type: probe/wave_gauge.cpp,
// section.cpp, front.cpp, pressure_probe.cpp, energy_probe.cpp, rigid_probe.cpp; the list in probe/registry.cpp).
//
// A probe reads its own scene keys when it is built (so the loader can check a scene by building its probes
// once), may measure the initial state (init), writes one or more columns per sample, and saves and restores
// whatever state it keeps (a wave gauge's still-water level) itself, so checkpoints carry it as numbers.
// Every probe may be restricted to one material ("material"); wave gauges default to the fluids.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_reader.h"
#include "sim/simulation.h"

namespace cdmpm {

// A probe's value where it measures nothing (a dry gauge, a section without water): written as nan.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A place where a probe measures the water (a wave gauge, a station of a section): what the station file lists
// (io/station_file.h). Its variables name the quantity ("eta", "d", "u", "v", "q", "qx", "qy", probe/section.cpp)
// and the probes.csv column that holds it.
struct Station {
  std::string name;               // the probes.csv column prefix: the probe's name (with _k for a 3D section's station k)
  std::vector<double> position;   // dim - 1 horizontal coordinates [m]
  double still_level = kNaN;      // [m], NaN where none (dry at t = 0)
  std::vector<std::pair<std::string, std::string>> variables;  // (quantity, probes.csv column)
};

template <int dim>
class Probe {
 public:
  virtual ~Probe() = default;
  const std::string& name() const { return name_; }
  // Column names in probes.csv (default: the probe's name).
  virtual Strings columns() const { return {name_}; }
  // The stations where the probe measures the water (none for integral probes).
  virtual std::vector<Station> stations() const { return {}; }
  // Measures what the probe needs from the initial state.
  virtual void init(const Simulation<dim>&) {}
  // Appends one value per column.
  virtual void sample(const Simulation<dim>& sim, std::vector<double>& out) const = 0;
  // The probe's own state, for checkpoints; load_state returns false if `state` is not one it saved.
  virtual std::vector<double> save_state() const { return {}; }
  virtual bool load_state(const std::vector<double>& state) { return state.empty(); }

 protected:
  // Reads the keys every probe has ("name", "type"; "material" if the probe takes it) and checks that the
  // probe's object has no key outside `own_keys` and those.
  Probe(const SceneReader& r, const Node& n, const Scene& scene, Strings own_keys, bool takes_material = true);
  // Whether particle material `material` (of model m) counts for this probe.
  bool selected(const Material& m, int material) const {
    return material_index_ >= 0 ? material == material_index_ : !fluids_only_ || m.traits().fluid;
  }
  std::string name_;
  int material_index_ = -1;  // -1: all materials (wave gauges: all fluids)
  bool fluids_only_ = false;
};

// Defines the registry's factory NAME<dim> (2D and 3D) building a CLASS<dim> from its scene object, passing any
// further constructor arguments (a probe class serving several types); each probe file ends with its factories
// (probe/registry.cpp lists them).
#define CDMPM_PROBE_FACTORY(NAME, CLASS, ...)                                                            \
  template <int dim>                                                                                   \
  std::unique_ptr<Probe<dim>> NAME(const SceneReader& r, const Node& n, const Scene& scene) {          \
    return std::make_unique<CLASS<dim>>(r, n, scene __VA_OPT__(, ) __VA_ARGS__);                       \
  }                                                                                                    \
  template std::unique_ptr<Probe<2>> NAME<2>(const SceneReader&, const Node&, const Scene&);          \
  template std::unique_ptr<Probe<3>> NAME<3>(const SceneReader&, const Node&, const Scene&);

// The probe types of the registry.
Strings probe_types();

// Builds a probe of a registered type from its scene object (scene: the materials and bodies read so far, and
// the probes before it, for the unique-name check). Throws SceneError.
template <int dim>
std::unique_ptr<Probe<dim>> make_probe(const SceneReader& reader, const Node& node, const Scene& scene);

// The probes of a loaded scene, in order.
template <int dim>
std::vector<std::unique_ptr<Probe<dim>>> make_probes(const Scene& scene);

}  // namespace cdmpm
