// walls.cpp - the "walls" boundary: the faces of the domain box; a node on or beyond face (axis, side) is in the
// wall, with the face's inward normal. Slip walls on grid planes are mirrored (boundary.h). Scene key: faces
// (any of "x-", "x+", "y-", "y+", "z-", "z+"; default all).
#include "boundary/mirror.h"

#include <algorithm>

namespace cdmpm {
namespace {

template <int dim>
class Walls final : public Boundary<dim> {
 public:
  Walls(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx)
      : Boundary<dim>(r, n, ctx.dx), size_(ctx.domain_size) {
    Strings keys = Boundary<dim>::common_keys();
    keys.push_back("faces");
    r.object(n, keys);
    Strings all = {"x-", "x+", "y-", "y+"};
    if (dim == 3) all.insert(all.end(), {"z-", "z+"});
    Strings faces = n.has("faces") ? Strings{} : all;
    if (n.has("faces")) {
      Node fs = n["faces"];
      for (size_t i = 0, count = r.array(fs, 1, "a non-empty array of faces"); i < count; ++i) {
        std::string face = r.string(fs[i], all);
        if (contains(faces, face)) r.expected(fs[i], "a face not listed before");
        faces.push_back(face);
      }
    }
    faces_ = faces;
    static const char* names[3] = {"x", "y", "z"};
    for (int a = 0; a < dim; ++a)
      for (int side = 0; side < 2; ++side) on_[a][side] = contains(faces, std::string(names[a]) + (side ? "+" : "-"));
  }
  // Calls f(src, dst, axis) for every active ghost node src beyond a slip face and its mirror node dst inside
  // (when active: with the material on its side of the wall, the stencil that reaches src also reaches dst),
  // axis by axis (forward or reverse). Faces that do not lie on a grid plane are skipped.
  template <class F>
  void for_each_mirror_pair(const Grid<dim>& g, bool reverse, F&& f) const {
    if (this->condition_ != BoundaryCondition::Slip) return;
    for (int step = 0; step < dim; ++step) {
      const int a = reverse ? dim - 1 - step : step;
      int top = 0;
      const bool top_on_grid = on_grid_plane(size_[a] * g.inv_dx, top);
      for (int side = 0; side < 2; ++side) {
        if (!on_[a][side]) continue;
        if (side == 1 && !top_on_grid) continue;
        const int face = side ? top : 0, out = side ? 1 : -1;
        for (int k = 1; k <= Grid<dim>::ghost; ++k)
          g.for_each_node_on_plane(a, face + out * k, [&](size_t src, IVec<dim> i) {
            i[a] = face - out * k;
            const size_t dst = g.find(i);
            if (dst != Grid<dim>::npos) f(src, dst, a);
          });
      }
    }
  }
  Strings closed_faces() const override { return faces_; }
  void fold_ghosts(Grid<dim>& g) const override {
    for_each_mirror_pair(g, false, [&](size_t s, size_t d, int a) { fold_pair(g, s, d, a); });
  }
  void unfold_ghosts(Grid<dim>& g) const override {
    for_each_mirror_pair(g, true, [&](size_t s, size_t d, int a) { unfold_pair(g, s, d, a); });
  }
  void keep_inside(Vec<dim>& x, Vec<dim>& /*v*/) const override {
    for (int a = 0; a < dim; ++a) {
      if (on_[a][0] && x[a] < 0) x[a] = 0;
      if (on_[a][1] && x[a] > size_[a]) x[a] = size_[a];
    }
  }
  void apply(const Vec<dim>& x, Vec<dim>& v) const override {
    for (int a = 0; a < dim; ++a) {
      if (on_[a][0] && x[a] <= this->tol_) apply_condition<dim>(this->condition_, this->friction_, Vec<dim>::Unit(a), v);
      if (on_[a][1] && x[a] >= size_[a] - this->tol_) apply_condition<dim>(this->condition_, this->friction_, -Vec<dim>::Unit(a), v);
    }
  }
  bool is_solid(const Vec<dim>& x) const override {
    for (int a = 0; a < dim; ++a)
      if ((on_[a][0] && x[a] < 0) || (on_[a][1] && x[a] > size_[a])) return true;
    return false;
  }

 private:
  Vec<dim> size_;
  Strings faces_;
  std::array<std::array<bool, 2>, 3> on_{};
};

}  // namespace

CDMPM_BOUNDARY_FACTORY(make_walls, Walls)

}  // namespace cdmpm
