// still_level_check.h - what in a scene would move its still water before any wave does, by more than dx / 20
// (the resolution at which its wave gauges and hazard map are read, probe/wave_bounds.h): the warnings that
// `cdmpm check` and `cdmpm run` print before anything runs.
//   - a liquid body seeded without its hydrostatic state (hydrostatic: false) settles under its own weight by
//     about rho0 g H^2 / (2 K) (H its depth, K its bulk modulus: the column's linear compression);
//   - a wave gauge or an absorbing layer whose still_level differs from the level of the liquid body under it
//     measures or relaxes towards a level that the water does not have (a gauge's still_level 0, the water's
//     absolute top, is what it asks for).
// (The liquid's top itself is seeded on its level, sim/seeding.cpp.)
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace cdmpm {

std::vector<std::string> still_level_warnings(const Scene& scene);

}  // namespace cdmpm
