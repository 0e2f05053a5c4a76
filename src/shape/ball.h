// ball.h - the "ball" shape: the closed disc (2D) or ball (3D) |x - center| <= radius. Scene keys: center, radius.
#pragma once

#include <vector>

#include "scene/scene_reader.h"

namespace cdmpm {

struct BallShape {
  static constexpr std::string_view type = "ball";
  std::vector<double> center;
  double radius = 0;

  static BallShape parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "center", "radius"});
    BallShape b;
    b.center = r.numbers(r.required(n, "center"), r.dim());
    b.radius = r.number(r.required(n, "radius"), gt(0));
    return b;
  }
  void bounds(std::vector<double>& lo, std::vector<double>& hi) const {
    lo.clear(), hi.clear();
    for (double c : center) lo.push_back(c - radius), hi.push_back(c + radius);
  }
  template <class P>
  bool contains(const P& x) const {
    double r2 = 0;
    for (size_t a = 0; a < center.size(); ++a) r2 += (x[a] - center[a]) * (x[a] - center[a]);
    return r2 <= radius * radius;
  }
};

}  // namespace cdmpm
