// shape.cpp - reading a shape of a registered type (shape.h).
#include "shape/shape.h"

#include "scene/variant_registry.h"

namespace cdmpm {

Shape parse_shape(const SceneReader& r, const Node& n) {
  if (!n.j.is_object()) r.expected(n, "an object");
  // A shape with `only_dim` (the polygon in 2D, the prism in 3D) exists in that dimension only.
  const Strings types = registered_types<ShapeModel>([&]<class S>(S*) {
    if constexpr (requires { S::only_dim; }) return S::only_dim == r.dim();
    else return true;
  });
  const std::string type = r.string(r.required(n, "type"), types);
  Shape shape(parse_registered<ShapeModel>(type, r, n));
  r.inside(n, shape.lower(), shape.upper(), "a shape");
  return shape;
}

}  // namespace cdmpm
