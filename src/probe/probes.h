// probes.h - the scene's probes as one table: probes.csv's header and one row per sample, and the probes' own
// states (saved in checkpoints and restored on resume). The probe types are in probe/probe.h.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "probe/probe.h"

namespace cdmpm {

template <int dim>
class Probes {
 public:
  // Builds the scene's probes and lets each measure the initial state.
  Probes(const Scene& scene, const Simulation<dim>& sim);
  std::vector<double> sample(const Simulation<dim>& sim) const;
  std::string csv_header() const;
  // Every probe's stations, in probe order.
  std::vector<Station> stations() const;
  // Every probe's state: per probe its size, then its values.
  std::vector<double> save_state() const;
  // Restores what save_state wrote; false if it does not fit these probes.
  bool load_state(const std::vector<double>& state);

 private:
  std::vector<std::unique_ptr<Probe<dim>>> probes_;
};

}  // namespace cdmpm
