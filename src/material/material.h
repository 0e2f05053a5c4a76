// material.h - the material table: one constitutive model per named scene material.
//
// Each particle stores an index into this table. The constitutive update (after grid-to-particle) and the
// stress evaluation (in particle-to-grid) dispatch on Material::kind.
#pragma once

#include <string>

#include "material/weakly_compressible_water.h"

namespace cdmpm {

enum class MaterialKind { Water };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::Water;
  Real density = 1000;
  WeaklyCompressibleWater water;
  Real half_spacing = 0;  // half the particle spacing of this material's bodies (for surface probes)
};

inline bool is_fluid(const Material& m) { return m.kind == MaterialKind::Water; }

}  // namespace cdmpm
