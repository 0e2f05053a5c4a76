// half_plane.cpp - the "half_plane" boundary: solid where (x - point) . normal < 0, the normal (normalised on
// reading) pointing into the material. Scene keys: point, normal (dim numbers each, normal nonzero).
#include <cmath>

#include "boundary/mirror.h"

namespace cdmpm {
namespace {

template <int dim>
class HalfPlane final : public Boundary<dim> {
 public:
  HalfPlane(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx) : Boundary<dim>(r, n, ctx.dx) {
    Strings keys = Boundary<dim>::common_keys();
    keys.insert(keys.end(), {"point", "normal"});
    r.object(n, keys);
    point_ = to_vec<dim>(r.numbers(r.required(n, "point"), dim));
    std::vector<double> normal = r.numbers(r.required(n, "normal"), dim);
    double norm = 0;
    for (double c : normal) norm += c * c;
    if (norm == 0) r.expected(n["normal"], "a nonzero vector");
    for (double& c : normal) c /= std::sqrt(norm);
    normal_ = to_vec<dim>(normal).normalized();
  }
  void apply(const Vec<dim>& x, Vec<dim>& v) const override {
    if ((x - point_).dot(normal_) <= this->tol_) apply_condition<dim>(this->condition_, this->friction_, normal_, v);
  }
  bool is_solid(const Vec<dim>& x) const override { return (x - point_).dot(normal_) < 0; }

 private:
  Vec<dim> point_, normal_;
};

}  // namespace

CDMPM_BOUNDARY_FACTORY(make_half_plane, HalfPlane)

}  // namespace cdmpm
