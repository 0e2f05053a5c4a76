// distributable.h - what a distributed run (MPI build, more than one rank) supports in this first phase
// (docs/architecture.md): water and ice of any material model, domain walls, half planes, moving box obstacles,
// every probe (evaluated on the gathered state), iceberg detection (on the gathered state), the hazard record
// (maxima and minima through parallel/reduction.h). Anything else is refused up front (exit code 2) rather than
// run wrongly: rigid bodies (sums over a body's particles in particle order), the well-balanced bathymetry (its bed
// layer of fixed particles is not partitioned), absorbing layers (they measure the surface across ranks), static
// slip box obstacles (their mirror pairs can straddle two ranks) and sinks (their removal is not merged with the
// order keys). Resuming works on any number of ranks (Simulation::restore partitions the loaded particles again).
#pragma once

#include <string>

#include "material/material.h"
#include "scene/scene.h"

namespace cdmpm {

// Empty if the scene can run distributed, else the first feature that cannot, named for the message.
inline std::string distributable(const Scene& s) {
  for (const Material& m : s.materials)
    if (m.traits().rigid) return "rigid bodies (material '" + m.name + "')";
  for (const BoundarySpec& b : s.boundaries) {
    if (b.type == "bathymetry" || b.type == "absorbing_layer") return "the '" + b.type + "' boundary (" + b.path + ")";
    if (b.type == "box") {
      bool moving = false;
      if (b.json.contains("velocity"))
        for (const auto& v : b.json["velocity"]) moving = moving || v.get<double>() != 0;
      const bool slip = b.json.value("condition", std::string("separate")) == "slip";
      if (slip && !moving) return "a static slip box obstacle (" + b.path + ")";
    }
  }
  if (!s.sinks.empty()) return "sinks";
  return "";
}

}  // namespace cdmpm
