// prism.h - the "prism" shape (3D only): a polygon in the x-z plane (`vertices`, [x, z] pairs, as the 2D
// polygon) extruded along y over `y` = [y_min, y_max]: the 3D form of a 2D section, such as a wedge of a calving
// front or a notch across part of it. Containment: y in range and the polygon's even-odd test on (x, z).
#pragma once

#include <array>
#include <vector>

#include "scene/scene_reader.h"
#include "shape/polygon.h"

namespace cdmpm {

struct PrismShape {
  static constexpr std::string_view type = "prism";
  static constexpr int only_dim = 3;
  PolygonShape section;       // in (x, z)
  std::array<double, 2> y{};  // [y_min, y_max]

  static PrismShape parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "vertices", "y"});
    PrismShape p;
    p.section.vertices = PolygonShape::read_vertices(r, n);
    const Node yn = r.required(n, "y");
    const std::vector<double> y = r.numbers(yn, 2);
    if (!(y[0] < y[1])) r.expected(yn, "[y_min, y_max] with y_min < y_max");
    p.y = {y[0], y[1]};
    return p;
  }
  void bounds(std::vector<double>& lo, std::vector<double>& hi) const {
    std::vector<double> l2, h2;
    section.bounds(l2, h2);
    lo = {l2[0], y[0], l2[1]}, hi = {h2[0], y[1], h2[1]};
  }
  template <class P>
  bool contains(const P& x) const {
    if constexpr (requires { P::SizeAtCompileTime; })
      if constexpr (P::SizeAtCompileTime != 3) return false;  // never built in 2D (only_dim)
    if (x[1] < y[0] || x[1] > y[1]) return false;
    return section.contains(std::array<double, 2>{x[0], x[2]});
  }
};

}  // namespace cdmpm
