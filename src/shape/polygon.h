// polygon.h - the "polygon" shape (2D only): a simple polygon through `vertices` ([x, y] pairs, either
// orientation, at least 3, nonzero area); containment by even-odd ray casting along +x.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "scene/scene_reader.h"

namespace cdmpm {

struct PolygonShape {
  static constexpr std::string_view type = "polygon";
  static constexpr int only_dim = 2;
  std::vector<std::array<double, 2>> vertices;

  static PolygonShape parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "vertices"});
    return PolygonShape{read_vertices(r, n)};
  }
  // The key `vertices` of N: at least 3 pairs enclosing a nonzero area (twice the signed area by the shoelace
  // formula). The prism (shape/prism.h) reads its section with it.
  static std::vector<std::array<double, 2>> read_vertices(const SceneReader& r, const Node& n) {
    std::vector<std::array<double, 2>> v = r.pairs(r.required(n, "vertices"), 3);
    double area2 = 0;
    for (size_t i = 0; i < v.size(); ++i) {
      const auto &a = v[i], &b = v[(i + 1) % v.size()];
      area2 += a[0] * b[1] - b[0] * a[1];
    }
    if (area2 == 0) r.expected(n["vertices"], "a polygon with nonzero area");
    return v;
  }
  void bounds(std::vector<double>& lo, std::vector<double>& hi) const {
    lo = {Range::inf, Range::inf}, hi = {-Range::inf, -Range::inf};
    for (const auto& v : vertices)
      for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
  }
  template <class P>
  bool contains(const P& x) const {
    bool inside = false;
    const auto& v = vertices;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      if ((v[i][1] > x[1]) != (v[j][1] > x[1]) &&
          x[0] < (v[j][0] - v[i][0]) * (x[1] - v[i][1]) / (v[j][1] - v[i][1]) + v[i][0])
        inside = !inside;
    }
    return inside;
  }
};

}  // namespace cdmpm
