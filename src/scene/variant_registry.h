// variant_registry.h - a registry that is a std::variant: its alternatives are the registered types, each with
// a static `type` name and a static `parse(reader, node)`. Used for the material models (material/material.h)
// and the shapes (shape/shape.h), whose hot-path dispatch is a switch on the variant's index.
#pragma once

#include <string>
#include <variant>

#include "scene/scene_reader.h"

namespace cdmpm {

// The type names of the registry's alternatives for which allowed(A) holds (by default all), in order.
template <class Variant, class Allowed>
Strings registered_types(Allowed&& allowed) {
  Strings out;
  [&]<class... A>(std::variant<A...>*) {
    ((allowed(static_cast<A*>(nullptr)) ? out.push_back(std::string(A::type)) : void()), ...);
  }(static_cast<Variant*>(nullptr));
  return out;
}

// The alternative named `type` (one of registered_types) reads the node.
template <class Variant>
Variant parse_registered(const std::string& type, const SceneReader& r, const Node& n) {
  Variant out;
  [&]<class... A>(std::variant<A...>*) {
    (void)((type == A::type ? (out = A::parse(r, n), true) : false) || ...);
  }(static_cast<Variant*>(nullptr));
  return out;
}

}  // namespace cdmpm
