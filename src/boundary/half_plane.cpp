// half_plane.cpp - the "half_plane" boundary: solid where (x - point) . normal < 0, the normal (normalised on
// reading) pointing into the material. Scene keys: point, normal (dim numbers each, normal nonzero), and
// optionally within = {min, max}: the plane acts only inside that box (a bounded support plane: the failure
// plane behind a sliding wedge, which must not cut the water in front of the face).
#include <cmath>

#include "boundary/mirror.h"

namespace cdmpm {
namespace {

template <int dim>
class HalfPlane final : public Boundary<dim> {
 public:
  HalfPlane(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx) : Boundary<dim>(r, n, ctx.dx) {
    Strings keys = Boundary<dim>::common_keys();
    keys.insert(keys.end(), {"point", "normal", "within"});
    r.object(n, keys);
    point_ = to_vec<dim>(r.numbers(r.required(n, "point"), dim));
    std::vector<double> normal = r.numbers(r.required(n, "normal"), dim);
    double norm = 0;
    for (double c : normal) norm += c * c;
    if (norm == 0) r.expected(n["normal"], "a nonzero vector");
    for (double& c : normal) c /= std::sqrt(norm);
    normal_ = to_vec<dim>(normal).normalized();
    bounded_ = n.has("within");
    if (bounded_) {
      const Node w = n["within"];
      r.object(w, {"min", "max"});
      std::vector<double> lo, hi;
      r.min_max(w, lo, hi);
      lo_ = to_vec<dim>(lo), hi_ = to_vec<dim>(hi);
    }
  }
  void apply(const Vec<dim>& x, Vec<dim>& v) const override {
    if (inside_box(x) && (x - point_).dot(normal_) <= this->tol_)
      apply_condition<dim>(this->condition_, this->friction_, normal_, v);
  }
  bool is_solid(const Vec<dim>& x) const override { return inside_box(x) && (x - point_).dot(normal_) < 0; }

 private:
  bool inside_box(const Vec<dim>& x) const {
    return !bounded_ || ((x.array() >= lo_.array()).all() && (x.array() <= hi_.array()).all());
  }
  Vec<dim> point_, normal_, lo_, hi_;  // lo_, hi_: the box `within`, if bounded_
  bool bounded_ = false;
};

}  // namespace

CDMPM_BOUNDARY_FACTORY(make_half_plane, HalfPlane)

}  // namespace cdmpm
