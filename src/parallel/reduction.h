// reduction.h - the one interface through which every global quantity is combined across processes: the
// largest speed and wave speed (time step), the stability check, probe values, energies and mass, and the
// rigid-body sums, the hazard record's per-column extremes. Each caller first reduces over its own particles (OpenMP, in a fixed order where the result
// must not depend on the thread count), then passes its partial result here.
//
// One process (this build): every function is the identity. A distributed build (docs/architecture.md) makes
// them collective: max/min are exact in any order; sums are combined in rank order of a partition that
// follows the global block order, so a result does not depend on how the work was split within a rank.
// Not routed through it yet: iceberg detection (probe/icebergs.h), which needs every ice cell of the domain, a
// gather rather than a reduction.
#pragma once

#include <vector>

namespace cdmpm::global {

inline double sum(double local) { return local; }
inline double max(double local) { return local; }
inline double min(double local) { return local; }
template <class T>
void sum(std::vector<T>&) {}
template <class T>
void max(std::vector<T>&) {}
template <class T>
void min(std::vector<T>&) {}

}  // namespace cdmpm::global
