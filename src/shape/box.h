// box.h - the "box" shape: the axis-aligned box [min, max] (dim coordinates each). Scene keys: min, max.
#pragma once

#include <vector>

#include "scene/scene_reader.h"

namespace cdmpm {

struct BoxShape {
  static constexpr std::string_view type = "box";
  std::vector<double> min, max;

  static BoxShape parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "min", "max"});
    BoxShape b;
    r.min_max(n, b.min, b.max);
    return b;
  }
  void bounds(std::vector<double>& lo, std::vector<double>& hi) const { lo = min, hi = max; }
  template <class P>
  bool contains(const P& x) const {
    for (size_t a = 0; a < min.size(); ++a)
      if (x[a] < min[a] || x[a] > max[a]) return false;
    return true;
  }
};

}  // namespace cdmpm
