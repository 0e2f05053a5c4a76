// heightfield.h - the "heightfield" shape (3D only): the material between two height fields, a glacier between
// its bed and its surface. Keys: "bottom" and "top", ESRI ASCII grids (terrain/terrain_file.h, paths relative to
// the scene file) in the same coordinates, "file_origin" (easting, northing, elevation of the domain's origin in
// the files; default zeros), "footprint" (optional: {"vertices": [[x, y], ...]}, a polygon in domain coordinates, the body's extent, e.g.
// the ice behind its calving front; default the whole domain). Containment: (x, y) inside the footprint and
// bottom(x, y) <= z < top(x, y), both bilinear (terrain/height_field.h). Both grids must cover the domain with no
// NODATA where interpolated (as a bathymetry file), and the top must lie above the bottom somewhere in the
// footprint.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "scene/scene_reader.h"
#include "shape/polygon.h"
#include "terrain/height_field.h"
#include "terrain/terrain_file.h"

namespace cdmpm {

struct HeightfieldShape {
  static constexpr std::string_view type = "heightfield";
  static constexpr int only_dim = 3;
  std::shared_ptr<const HeightField> bottom, top;  // shared: a Shape is copied with its body
  std::optional<PolygonShape> footprint;
  std::vector<double> lo, hi;                      // bounding box

  static HeightfieldShape parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "bottom", "top", "file_origin", "footprint"});
    HeightfieldShape s;
    const std::vector<double> origin = n.has("file_origin") ? r.numbers(n["file_origin"], 3) : std::vector<double>(3, 0.0);
    auto read = [&](const char* key) {
      TerrainSurface t;
      bathymetry_from_file(t, terrain_path(r.file(), r.string(r.required(n, key))), origin, r.domain(),
                           r.file() + ": " + n.child(key));
      return std::make_shared<const HeightField>(HeightField{t.origin[0], t.origin[1], t.spacing[0], t.spacing[1], t.heights});
    };
    s.bottom = read("bottom");
    s.top = read("top");
    const std::vector<double>& size = r.domain();
    s.lo = {0, 0, size[2]}, s.hi = {size[0], size[1], 0};
    if (n.has("footprint")) {
      r.object(n["footprint"], {"vertices"});
      s.footprint = PolygonShape{PolygonShape::read_vertices(r, n["footprint"])};
      std::vector<double> l, h;
      s.footprint->bounds(l, h);
      s.lo[0] = l[0], s.lo[1] = l[1], s.hi[0] = h[0], s.hi[1] = h[1];
    }
    // The vertical extent over the nodes of both grids; the body must be thicker than nothing somewhere.
    bool thick = false;
    for (size_t j = 0; j < s.top->h.size(); ++j)
      for (size_t i = 0; i < s.top->h[j].size(); ++i) {
        const double x = s.top->ox + double(i) * s.top->sx, y = s.top->oy + double(j) * s.top->sy;
        const double b = s.bottom->at(x, y), t = s.top->h[j][i];
        if (t > b && (!s.footprint || s.footprint->contains(std::array<double, 2>{x, y}))) {
          thick = true;
          s.lo[2] = std::min(s.lo[2], b), s.hi[2] = std::max(s.hi[2], t);
        }
      }
    if (!thick)
      r.fail(n.child("top"), "expected a top above the bottom somewhere inside the footprint (the body would be empty)");
    s.lo[2] = std::max(s.lo[2], 0.0), s.hi[2] = std::min(s.hi[2], size[2]);
    return s;
  }
  void bounds(std::vector<double>& l, std::vector<double>& h) const { l = lo, h = hi; }
  template <class P>
  bool contains(const P& x) const {
    if constexpr (requires { P::SizeAtCompileTime; })
      if constexpr (P::SizeAtCompileTime != 3) return false;  // never built in 2D (only_dim)
    if (footprint && !footprint->contains(std::array<double, 2>{double(x[0]), double(x[1])})) return false;
    const double z = x[2];
    return z >= bottom->at(x[0], x[1]) && z < top->at(x[0], x[1]);
  }
};

}  // namespace cdmpm
