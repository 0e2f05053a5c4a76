// shape.h - geometric shapes that bodies are filled with: box, ball, and (2D) polygon.
// Each answers point containment and its axis-aligned bounding box.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "scene/scene.h"

namespace cdmpm {

template <int dim>
class Shape {
 public:
  using P = Eigen::Matrix<double, dim, 1>;
  explicit Shape(const ShapeSpec& s) : s_(s) {
    for (int a = 0; a < dim; ++a) {
      if (s.type == "box") { lo_[a] = s.min[a]; hi_[a] = s.max[a]; }
      else if (s.type == "ball") { lo_[a] = s.center[a] - s.radius; hi_[a] = s.center[a] + s.radius; }
      else {
        lo_[a] = std::numeric_limits<double>::max();
        hi_[a] = std::numeric_limits<double>::lowest();
        for (const auto& v : s.vertices) { lo_[a] = std::min(lo_[a], v[a]); hi_[a] = std::max(hi_[a], v[a]); }
      }
    }
  }
  double lower(int a) const { return lo_[a]; }
  double upper(int a) const { return hi_[a]; }

  bool contains(const P& x) const {
    if (s_.type == "box") {
      for (int a = 0; a < dim; ++a)
        if (x[a] < s_.min[a] || x[a] > s_.max[a]) return false;
      return true;
    }
    if (s_.type == "ball") {
      double r2 = 0;
      for (int a = 0; a < dim; ++a) r2 += (x[a] - s_.center[a]) * (x[a] - s_.center[a]);
      return r2 <= s_.radius * s_.radius;
    }
    // Polygon (2D): even-odd ray casting along +x.
    bool inside = false;
    const auto& v = s_.vertices;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      if ((v[i][1] > x[1]) != (v[j][1] > x[1]) &&
          x[0] < (v[j][0] - v[i][0]) * (x[1] - v[i][1]) / (v[j][1] - v[i][1]) + v[i][0])
        inside = !inside;
    }
    return inside;
  }

 private:
  ShapeSpec s_;
  double lo_[dim], hi_[dim];
};

}  // namespace cdmpm
