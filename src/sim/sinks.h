// sinks.h - the sinks phase: removes the particles inside a sink (scene.h, SinkSpec), keeping the order of the
// others, so the result does not depend on the thread count.
#pragma once

#include <vector>

#include "core/particles.h"
#include "scene/scene.h"

namespace cdmpm {

template <int dim>
void remove_sunk_particles(Particles<dim>& p, const std::vector<SinkSpec>& sinks) {
  if (sinks.empty()) return;
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
  if (count == 0) return;
  std::vector<uint32_t> keep;
  keep.reserve(n - count);
  for (size_t q = 0; q < n; ++q)
    if (!sunk[q]) keep.push_back(static_cast<uint32_t>(q));
  p.permute(std::move(keep));
}

}  // namespace cdmpm
