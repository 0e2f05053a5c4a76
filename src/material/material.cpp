// material.cpp - building a material from its scene object through the registry (material.h).
#include "material/material.h"

#include "scene/variant_registry.h"

namespace cdmpm {

Material parse_material(const SceneReader& r, const Node& n, const std::string& name) {
  if (!n.j.is_object()) r.expected(n, "an object");
  const Strings types = registered_types<MaterialModel>([](auto*) { return true; });
  const std::string type = r.string(r.required(n, "type"), types);
  return {name, parse_registered<MaterialModel>(type, r, n)};
}

}  // namespace cdmpm
