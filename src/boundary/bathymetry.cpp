// bathymetry.cpp - the "bathymetry" boundary: terrain below which all is solid, with the normal of the terrain.
// 2D: a piecewise-linear profile through points (x_k, h_k) (x strictly increasing), constant beyond its ends.
// 3D: a height field heights[j][i] at (origin[0] + i spacing[0], origin[1] + j spacing[1]), bilinearly
// interpolated and clamped at its edges. Scene keys: 2D points; 3D origin, spacing, heights; or, instead, "file"
// (a CSV profile in 2D, an ESRI ASCII grid in 3D, relative to the scene file; terrain/terrain_file.h) and
// "file_origin" (the point of the file that becomes the domain's origin, default zeros); "well_balanced" (bool,
// default true with the slip condition, which it needs): the water bodies fill a layer of the solid below the bed
// with fixed water particles (sim/bed_layer.h), and a particle that ends a step below the bed is put back on it
// (straight up) and loses the part of its velocity into the bed, v <- v - min(0, v.n) n (n the bed's unit normal;
// the separating condition of boundary.h, apply_condition): the bed stays impermeable to the particle. Without it a particle
// running up a slope kept the velocity that had taken it into the bed, was lifted for free, and climbed with the
// horizontal speed of the flat: a solitary wave's run-up on a 1:2.5 beach was 0.327 h, against 0.295 h with it and
// 0.279 h from Synolakis's exact linear theory (docs/validation.md#solitary-wave-run-up).
#include <algorithm>
#include <cmath>
#include <optional>

#include "boundary/mirror.h"
#include "terrain/height_field.h"
#include "terrain/terrain_file.h"

namespace cdmpm {
namespace {

// The terrain of a bathymetry given as a file ("file", "file_origin"), or nothing if it is given inline; the
// inline keys are refused beside "file".
std::optional<TerrainSurface> terrain_of(const SceneReader& r, const Node& n) {
  if (!n.has("file") && !n.has("file_origin")) return std::nullopt;
  for (const char* key : {"points", "origin", "spacing", "heights"})
    if (n.has(key)) r.fail(n.child(key), "not allowed together with \"file\" (give one or the other)");
  const int dim = r.dim();
  const auto o = n.has("file_origin") ? r.numbers(n["file_origin"], dim) : std::vector<double>(dim, 0.0);
  TerrainSurface t;
  bathymetry_from_file(t, terrain_path(r.file(), r.string(r.required(n, "file"))), o, r.domain(),
                       r.file() + ": " + n.child("file"));
  return t;
}

// The "well_balanced" key: default true with the slip condition, which the bed layer needs (sim/bed_layer.h).
bool well_balanced_of(const SceneReader& r, const Node& n, BoundaryCondition c) {
  const bool slip = c == BoundaryCondition::Slip;
  const bool wb = r.boolean(n, "well_balanced", slip);
  if (wb && !slip) r.expected(n["well_balanced"], "false unless \"condition\" is \"slip\" (the bed layer needs a slip bed)");
  return wb;
}

// Thickness of the bed layer (sim/bed_layer.h): 3 dx |n|_1 along the normal n. A quadratic B-spline stencil reaches
// 1.5 dx along each axis, 1.5 dx |n|_1 along n: the nodes that water particles read lie at most that far below the
// bed, and their own supports at most twice that, which the layer fills.
constexpr Real bed_layer_cells = 3;

// 2D bathymetry: solid below the piecewise-linear profile through (x_k, h_k); constant beyond its ends.
class Bathymetry2D final : public Boundary<2> {
 public:
  Bathymetry2D(const SceneReader& r, const Node& n, Real dx) : Boundary<2>(r, n, dx) {
    Strings keys = Boundary<2>::common_keys();
    keys.insert(keys.end(), {"points", "file", "file_origin", "well_balanced"});
    r.object(n, keys);
    well_balanced_ = well_balanced_of(r, n, condition_);
    reach_ = bed_layer_cells * dx;
    if (const auto t = terrain_of(r, n)) {
      pts_ = t->points;
      return;
    }
    Node points = r.required(n, "points");
    pts_ = r.pairs(points, 2);
    for (size_t i = 1; i < pts_.size(); ++i)
      if (!(pts_[i][0] > pts_[i - 1][0]))
        r.expected(points[i], "a point with x > " + format_number(pts_[i - 1][0]) + " (x strictly increasing)");
  }
  bool is_solid(const Vec<2>& x) const override {
    Real slope;
    return x[1] < height(x[0], slope);
  }
  void apply(const Vec<2>& x, Vec<2>& v) const override {
    Real slope;
    const Real h = height(x[0], slope);
    if (x[1] <= h + tol_) apply_condition<2>(condition_, friction_, Vec<2>(-slope, 1).normalized(), v);
  }
  bool in_bed_layer(const Vec<2>& x, Vec<2>& normal) const override {
    Real slope;
    const Real h = height(x[0], slope);
    normal = Vec<2>(-slope, 1).normalized();
    const Real depth = (h - x[1]) * normal[1];  // distance below the tangent plane at (x, h(x))
    return well_balanced_ && depth > 0 && depth < reach_ * normal.lpNorm<1>();
  }
  void keep_inside(Vec<2>& x, Vec<2>& v) const override {
    if (!well_balanced_) return;
    Real slope;
    const Real h = height(x[0], slope);
    if (x[1] >= h) return;
    x[1] = h;
    apply_condition<2>(BoundaryCondition::Separate, 0, Vec<2>(-slope, 1).normalized(), v);
  }

 private:
  // The profile's height at x and its slope there.
  Real height(Real x0, Real& slope) const {
    Real h;
    slope = 0;
    if (x0 <= pts_.front()[0]) h = static_cast<Real>(pts_.front()[1]);
    else if (x0 >= pts_.back()[0]) h = static_cast<Real>(pts_.back()[1]);
    else {
      const auto it = std::upper_bound(pts_.begin(), pts_.end(), static_cast<double>(x0),
                                       [](double xv, const std::array<double, 2>& p) { return xv < p[0]; });
      const auto& b = *it;
      const auto& a = *(it - 1);
      slope = static_cast<Real>((b[1] - a[1]) / (b[0] - a[0]));
      h = static_cast<Real>(a[1]) + slope * (x0 - static_cast<Real>(a[0]));
    }
    return h;
  }
  std::vector<std::array<double, 2>> pts_;
  bool well_balanced_ = false;
  Real reach_ = 0;  // bed_layer_cells dx
};

// 3D bathymetry: solid below a bilinearly interpolated height field z = h(x, y), clamped at its edges.
class HeightField3D final : public Boundary<3> {
 public:
  HeightField3D(const SceneReader& r, const Node& n, Real dx) : Boundary<3>(r, n, dx) {
    Strings keys = Boundary<3>::common_keys();
    keys.insert(keys.end(), {"origin", "spacing", "heights", "file", "file_origin", "well_balanced"});
    r.object(n, keys);
    well_balanced_ = well_balanced_of(r, n, condition_);
    reach_ = bed_layer_cells * dx;
    if (const auto t = terrain_of(r, n)) {
      field_ = {t->origin[0], t->origin[1], t->spacing[0], t->spacing[1], t->heights};
      return;
    }
    const std::vector<double> origin = r.numbers(r.required(n, "origin"), 2);
    const std::vector<double> spacing = r.numbers(r.required(n, "spacing"), 2, gt(0));
    field_ = {origin[0], origin[1], spacing[0], spacing[1], {}};
    Node heights = r.required(n, "heights");
    size_t rows = r.array(heights, 2, "an array of at least 2 rows of heights");
    size_t cols = r.array(heights[0], 2, "an array of at least 2 heights");
    for (size_t row = 0; row < rows; ++row) field_.h.push_back(r.numbers(heights[row], cols));
  }
  bool is_solid(const Vec<3>& x) const override {
    double dhdx, dhdy;
    return x[2] < height(x, dhdx, dhdy);
  }
  void apply(const Vec<3>& x, Vec<3>& v) const override {
    double dhdx, dhdy;
    const double h = height(x, dhdx, dhdy);
    if (x[2] > h + tol_) return;
    apply_condition<3>(condition_, friction_, Vec<3>(Real(-dhdx), Real(-dhdy), 1).normalized(), v);
  }
  bool in_bed_layer(const Vec<3>& x, Vec<3>& normal) const override {
    double dhdx, dhdy;
    const Real h = static_cast<Real>(height(x, dhdx, dhdy));
    normal = Vec<3>(Real(-dhdx), Real(-dhdy), 1).normalized();
    const Real depth = (h - x[2]) * normal[2];  // distance below the tangent plane at (x, y, h(x, y))
    return well_balanced_ && depth > 0 && depth < reach_ * normal.lpNorm<1>();
  }
  void keep_inside(Vec<3>& x, Vec<3>& v) const override {
    if (!well_balanced_) return;
    double dhdx, dhdy;
    const Real h = static_cast<Real>(height(x, dhdx, dhdy));
    if (x[2] >= h) return;
    x[2] = h;
    apply_condition<3>(BoundaryCondition::Separate, 0, Vec<3>(Real(-dhdx), Real(-dhdy), 1).normalized(), v);
  }

 private:
  // Bilinear height at (x, y) and its gradient (terrain/height_field.h).
  double height(const Vec<3>& x, double& dhdx, double& dhdy) const { return field_.at(x[0], x[1], dhdx, dhdy); }
  HeightField field_;
  bool well_balanced_ = false;
  Real reach_ = 0;  // bed_layer_cells dx
};

}  // namespace

template <int dim>
std::unique_ptr<Boundary<dim>> make_bathymetry(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx) {
  if constexpr (dim == 2) return std::make_unique<Bathymetry2D>(r, n, ctx.dx);
  else return std::make_unique<HeightField3D>(r, n, ctx.dx);
}
template std::unique_ptr<Boundary<2>> make_bathymetry<2>(const SceneReader&, const Node&, const BoundaryContext<2>&);
template std::unique_ptr<Boundary<3>> make_bathymetry<3>(const SceneReader&, const Node&, const BoundaryContext<3>&);

}  // namespace cdmpm
