// shape.h - the shape registry: the regions that bodies are filled with and holes cut from (one file per
// shape: shape/box.h, shape/ball.h, shape/polygon.h, shape/prism.h, shape/heightfield.h). A Shape answers point containment and its
// axis-aligned bounding box; the loader reads it (parse_shape), checks it lies inside the domain, and can build
// no shape of an unregistered type. Adding a shape: its file and one entry in the variant below.
#pragma once

#include <variant>
#include <vector>

#include "scene/scene_reader.h"
#include "shape/ball.h"
#include "shape/box.h"
#include "shape/heightfield.h"
#include "shape/polygon.h"
#include "shape/prism.h"

namespace cdmpm {

// The registry.
using ShapeModel = std::variant<BoxShape, BallShape, PolygonShape, PrismShape, HeightfieldShape>;

class Shape {
 public:
  Shape() = default;
  explicit Shape(ShapeModel m) : model_(std::move(m)) {
    std::visit([&](const auto& s) { s.bounds(lo_, hi_); }, model_);
  }
  double lower(int a) const { return lo_[a]; }
  double upper(int a) const { return hi_[a]; }
  const std::vector<double>& lower() const { return lo_; }
  const std::vector<double>& upper() const { return hi_; }
  template <class P>
  bool contains(const P& x) const {
    return std::visit([&](const auto& s) { return s.contains(x); }, model_);
  }
  const ShapeModel& model() const { return model_; }

 private:
  ShapeModel model_;
  std::vector<double> lo_, hi_;
};

// Reads a shape of a registered type (checked inside the domain).
Shape parse_shape(const SceneReader& reader, const Node& node);

}  // namespace cdmpm
