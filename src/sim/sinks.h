// sinks.h - the sinks phase: removes the particles inside a sink (scene.h, SinkSpec), keeping the order of the
// others, so the result does not depend on the thread count. A distributed run removes the same particles on their
// ranks and drops their order keys with them (parallel/domain.h, keep): the survivors keep the one-process order.
#pragma once

#include <vector>

#include "core/particles.h"
#include "scene/scene.h"

namespace cdmpm {

// Returns true if any particle was removed; then `kept`, if given, lists the survivors' former indices.
template <int dim>
bool remove_sunk_particles(Particles<dim>& p, const std::vector<SinkSpec>& sinks, std::vector<uint32_t>* kept = nullptr) {
  if (sinks.empty()) return false;
  const size_t n = p.size();
  std::vector<uint8_t> sunk(n, 0);
  size_t count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (size_t q = 0; q < n; ++q) {
    for (const auto& s : sinks) {
      if (s.material_index >= 0 && p.material[q] != s.material_index) continue;
      bool in = true;
      for (int a = 0; a < dim && in; ++a) in = p.x[q][a] >= s.min[a] && p.x[q][a] <= s.max[a];
      if (in) {
        sunk[q] = 1;
        ++count;
        break;
      }
    }
  }
  if (count == 0) return false;
  std::vector<uint32_t> keep;
  keep.reserve(n - count);
  for (size_t q = 0; q < n; ++q)
    if (!sunk[q]) keep.push_back(static_cast<uint32_t>(q));
  if (kept) *kept = keep;
  p.permute(std::move(keep));
  return true;
}

}  // namespace cdmpm
