// distributable.h - what a distributed run (MPI build, more than one rank) supports (docs/architecture.md): water
// and ice of any material model, domain walls, half planes, box obstacles (moving, or static with any condition:
// the mirror pairs of a static slip box are kept on one rank, parallel/partition.h), absorbing layers (their free
// surface is a maximum over the ranks), sinks (their removal drops the order keys with the particles), every probe
// (evaluated on the gathered state), iceberg detection (on the gathered state), the hazard record (maxima and
// minima through parallel/reduction.h), rigid bodies (their sums run over the body's particles gathered in the
// one-process order, sim/rigid_bodies.h). Anything else is refused up front (exit code 2) rather than run wrongly:
// the well-balanced bathymetry (its bed layer of fixed particles is not partitioned). Resuming works on any number
// of ranks (Simulation::restore partitions the loaded particles again).
#pragma once

#include <string>

#include "scene/scene.h"

namespace cdmpm {

// Empty if the scene can run distributed, else the first feature that cannot, named for the message.
inline std::string distributable(const Scene& s) {
  for (const BoundarySpec& b : s.boundaries)
    if (b.type == "bathymetry") return "the '" + b.type + "' boundary (" + b.path + ")";
  return "";
}

}  // namespace cdmpm
