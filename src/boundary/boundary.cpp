// boundary.cpp - the boundary shapes: domain walls, half-planes, boxes, bathymetry (2D polyline, 3D height
// field). Each decides whether a grid node lies in its solid and with which outward normal.
#include "boundary/boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cdmpm {
namespace {

template <int dim>
Vec<dim> to_vec(const std::vector<double>& a) {
  Vec<dim> v;
  for (int i = 0; i < dim; ++i) v[i] = static_cast<Real>(a[i]);
  return v;
}

// The grid-plane index nearest to coordinate/dx `cells`, and whether the coordinate lies on that plane (within
// node_tolerance_cells, the tolerance with which a face holds its nodes): the mirror treatment needs faces on
// grid planes.
inline bool on_grid_plane(Real cells, int& index) {
  index = static_cast<int>(std::lround(cells));
  return std::abs(cells - Real(index)) <= node_tolerance_cells;
}

// Mirror symmetry across a plane normal to `axis` (boundary.h): fold adds ghost node src's mass and
// reflected momentum to its mirror node dst; unfold gives src the reflected velocity of dst.
template <int dim>
void fold_pair(Grid<dim>& g, size_t src, size_t dst, int axis) {
  if (g.mass[src] <= 0) return;
  Vec<dim> mv = g.momentum[src];
  mv[axis] = -mv[axis];
  g.mass[dst] += g.mass[src];
  g.momentum[dst] += mv;
}
template <int dim>
void unfold_pair(Grid<dim>& g, size_t src, size_t dst, int axis) {
  Vec<dim> v = g.momentum[dst];
  v[axis] = -v[axis];
  g.momentum[src] = v;
}

// The faces of the domain box: a node on or beyond face (axis, side) is in the wall.
template <int dim>
class Walls final : public Boundary<dim> {
 public:
  Walls(const BoundarySpec& s, const Vec<dim>& size, Real dx) : Boundary<dim>(s.condition, s.friction, dx), size_(size) {
    static const char* names[3] = {"x", "y", "z"};
    for (int a = 0; a < dim; ++a)
      for (int side = 0; side < 2; ++side) {
        const std::string face = std::string(names[a]) + (side ? "+" : "-");
        on_[a][side] = s.faces.empty() || std::find(s.faces.begin(), s.faces.end(), face) != s.faces.end();
      }
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
  void fold_ghosts(Grid<dim>& g) const override {
    for_each_mirror_pair(g, false, [&](size_t s, size_t d, int a) { fold_pair(g, s, d, a); });
  }
  void unfold_ghosts(Grid<dim>& g) const override {
    for_each_mirror_pair(g, true, [&](size_t s, size_t d, int a) { unfold_pair(g, s, d, a); });
  }
  void keep_inside(Vec<dim>& x) const override {
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

 private:
  Vec<dim> size_;
  std::array<std::array<bool, 2>, 3> on_{};
};

template <int dim>
class HalfPlane final : public Boundary<dim> {
 public:
  HalfPlane(const BoundarySpec& s, Real dx)
      : Boundary<dim>(s.condition, s.friction, dx), point_(to_vec<dim>(s.point)), normal_(to_vec<dim>(s.normal).normalized()) {}
  void apply(const Vec<dim>& x, Vec<dim>& v) const override {
    if ((x - point_).dot(normal_) <= this->tol_) apply_condition<dim>(this->condition_, this->friction_, normal_, v);
  }

 private:
  Vec<dim> point_, normal_;
};

// Solid box [min, max] translated by d(t): the normal is that of the nearest face (all nearest faces on an
// edge or a corner). Its velocity u(t) ramps
// linearly from 0 to `velocity` U over the ramp time T (d = U t^2 / (2T) for t < T, U (t - T/2) after).
template <int dim>
class BoxObstacle final : public Boundary<dim> {
 public:
  BoxObstacle(const BoundarySpec& s, const Vec<dim>& domain_size, Real dx)
      : Boundary<dim>(s.condition, s.friction, dx), min0_(to_vec<dim>(s.min)), max0_(to_vec<dim>(s.max)),
        final_velocity_(s.velocity.empty() ? Vec<dim>::Zero().eval() : to_vec<dim>(s.velocity)), ramp_(s.ramp_time),
        velocity_(ramp_ > 0 ? Vec<dim>::Zero().eval() : final_velocity_), min_(min0_), max_(max0_) {
    // A face on or beyond the domain boundary has no material side: it is not a face of the obstacle.
    for (int a = 0; a < dim; ++a) {
      open_[a][0] = min0_[a] > Real(1e-9) * domain_size[a];
      open_[a][1] = max0_[a] < domain_size[a] * (Real(1) - Real(1e-9));
    }
  }
  void move_to(double t) override {
    const double d = t < ramp_ ? t * t / (2 * ramp_) : t - ramp_ / 2;
    velocity_ = static_cast<Real>(t < ramp_ ? t / ramp_ : 1.0) * final_velocity_;
    min_ = min0_ + static_cast<Real>(d) * final_velocity_;
    max_ = max0_ + static_cast<Real>(d) * final_velocity_;
  }
  void apply(const Vec<dim>& x, Vec<dim>& v) const override {
    Vec<dim> lo, hi;
    for (int a = 0; a < dim; ++a) {
      lo[a] = x[a] - min_[a];
      hi[a] = max_[a] - x[a];
      if (lo[a] < -this->tol_ || hi[a] < -this->tol_) return;
    }
    const Real best = std::min(lo.minCoeff(), hi.minCoeff());
    const Real tie = best + this->tol_;
    // The nearest face gives the normal; a node on an edge or corner (equally near several faces) gets the
    // condition of each, so a corner supports the material in both directions.
    Vec<dim> relative = v - velocity_;
    for (int a = 0; a < dim; ++a) {
      if (lo[a] <= tie) apply_condition<dim>(this->condition_, this->friction_, -Vec<dim>::Unit(a), relative);
      if (hi[a] <= tie) apply_condition<dim>(this->condition_, this->friction_, Vec<dim>::Unit(a), relative);
    }
    v = relative + velocity_;
  }

  // Mirror symmetry at the faces of a static slip box that lie on grid planes, as for slip domain walls:
  // each node inside the box at depth k = 1, 2 cells below exactly one nearest face is the image of the node
  // at height k outside it. fold_ghosts adds its mass and reflected momentum to that node; unfold_ghosts
  // gives it the reflected velocity of that node.
  // Pairs whose nodes are not both active are skipped (as for Walls).
  void fold_ghosts(Grid<dim>& g) const override {
    for_each_active_pair(g, [&](size_t src, size_t dst, int a) { fold_pair(g, src, dst, a); });
  }
  void unfold_ghosts(Grid<dim>& g) const override {
    for_each_active_pair(g, [&](size_t src, size_t dst, int a) { unfold_pair(g, src, dst, a); });
  }
  // A particle that advected into a static slip box is put back on its nearest open face (see Walls).
  void keep_inside(Vec<dim>& x) const override {
    if (!mirrored()) return;
    int axis = -1, side = 0;
    Real best = std::numeric_limits<Real>::max();
    for (int a = 0; a < dim; ++a) {
      const Real lo = x[a] - min_[a], hi = max_[a] - x[a];
      if (!(lo > 0 && hi > 0)) return;
      if (open_[a][0] && lo < best) best = lo, axis = a, side = 0;
      if (open_[a][1] && hi < best) best = hi, axis = a, side = 1;
    }
    if (axis >= 0) x[axis] = side ? max_[axis] : min_[axis];
  }

 private:
  struct MirrorPair {
    IVec<dim> src, dst;  // physical node indices
    int axis;
  };
  bool mirrored() const { return this->condition_ == BoundaryCondition::Slip && final_velocity_.isZero(); }

  template <class F>
  void for_each_active_pair(const Grid<dim>& g, F&& f) const {
    for (const auto& [src, dst, a] : mirror_pairs(g)) {
      const size_t s = g.find(src), d = g.find(dst);
      if (s != Grid<dim>::npos && d != Grid<dim>::npos) f(s, d, a);
    }
  }
  // The (ghost, mirror) node pairs on grid g's lattice, computed once (the box is static) over the nodes
  // within the ghost depth of the box.
  const std::vector<MirrorPair>& mirror_pairs(const Grid<dim>& g) const {
    if (pairs_ready_) return pairs_;
    pairs_ready_ = true;
    if (!mirrored()) return pairs_;
    IVec<dim> lo, hi;  // node indices of the box faces; a face off the grid planes gets no mirror
    std::array<std::array<bool, 2>, 3> on_grid{};
    for (int a = 0; a < dim; ++a) {
      on_grid[a][0] = on_grid_plane(min_[a] * g.inv_dx, lo[a]);
      on_grid[a][1] = on_grid_plane(max_[a] * g.inv_dx, hi[a]);
    }
    IVec<dim> first, last;  // node range to visit: the box and Grid::ghost nodes around it, on the lattice
    for (int a = 0; a < dim; ++a) {
      first[a] = std::max(-Grid<dim>::ghost, static_cast<int>(std::floor(min_[a] * g.inv_dx)) - Grid<dim>::ghost);
      last[a] = std::min(g.n_nodes[a] - 1 - Grid<dim>::ghost, static_cast<int>(std::ceil(max_[a] * g.inv_dx)) + Grid<dim>::ghost);
      if (first[a] > last[a]) return pairs_;
    }
    for (IVec<dim> i = first;;) {
      visit_node(g, i, lo, hi, on_grid);
      int a = dim - 1;
      for (; a >= 0; --a) {
        if (++i[a] <= last[a]) break;
        i[a] = first[a];
      }
      if (a < 0) break;
    }
    return pairs_;
  }
  // Adds node i's pair if i is a mirrored ghost of the box: inside it, at depth 1 or 2 below exactly one
  // nearest open face on a grid plane.
  void visit_node(const Grid<dim>& g, const IVec<dim>& i, const IVec<dim>& lo, const IVec<dim>& hi,
                  const std::array<std::array<bool, 2>, 3>& on_grid) const {
    int depth = std::numeric_limits<int>::max(), count = 0, axis = 0, side = 0;
    bool inside = true;
    for (int a = 0; a < dim && inside; ++a) {
      // Through a face on the domain boundary the box continues into the wall's ghost layers, so that
      // the nodes on and beyond that boundary are mirrored too (the corner of an obstacle and a wall).
      inside = (!open_[a][0] || i[a] > lo[a]) && (!open_[a][1] || i[a] < hi[a]);
      for (int sd = 0; sd < 2 && inside; ++sd) {
        if (!open_[a][sd]) continue;
        const int d = sd ? hi[a] - i[a] : i[a] - lo[a];
        if (d < depth) depth = d, count = 1, axis = a, side = sd;
        else if (d == depth) ++count;
      }
    }
    if (!inside || count != 1 || depth > 2 || !on_grid[axis][side]) return;
    IVec<dim> j = i;
    j[axis] = side ? 2 * hi[axis] - i[axis] : 2 * lo[axis] - i[axis];
    if (j[axis] < -Grid<dim>::ghost || j[axis] + Grid<dim>::ghost >= g.n_nodes[axis]) return;
    pairs_.push_back({i, j, axis});
  }

  Vec<dim> min0_, max0_, final_velocity_;
  double ramp_;
  Vec<dim> velocity_, min_, max_;
  std::array<std::array<bool, 2>, 3> open_{};
  mutable std::vector<MirrorPair> pairs_;
  mutable bool pairs_ready_ = false;
};

// 2D bathymetry: solid below the piecewise-linear profile through (x_k, h_k); constant beyond its ends.
class Bathymetry2D final : public Boundary<2> {
 public:
  Bathymetry2D(const BoundarySpec& s, Real dx) : Boundary<2>(s.condition, s.friction, dx), pts_(s.points) {}
  void apply(const Vec<2>& x, Vec<2>& v) const override {
    Real h, slope = 0;
    if (x[0] <= pts_.front()[0]) h = static_cast<Real>(pts_.front()[1]);
    else if (x[0] >= pts_.back()[0]) h = static_cast<Real>(pts_.back()[1]);
    else {
      const auto it = std::upper_bound(pts_.begin(), pts_.end(), static_cast<double>(x[0]),
                                       [](double xv, const std::array<double, 2>& p) { return xv < p[0]; });
      const auto& b = *it;
      const auto& a = *(it - 1);
      slope = static_cast<Real>((b[1] - a[1]) / (b[0] - a[0]));
      h = static_cast<Real>(a[1]) + slope * (x[0] - static_cast<Real>(a[0]));
    }
    if (x[1] <= h + tol_) apply_condition<2>(condition_, friction_, Vec<2>(-slope, 1).normalized(), v);
  }

 private:
  std::vector<std::array<double, 2>> pts_;
};

// 3D bathymetry: solid below a bilinearly interpolated height field z = h(x, y), clamped at its edges.
class HeightField3D final : public Boundary<3> {
 public:
  HeightField3D(const BoundarySpec& s, Real dx)
      : Boundary<3>(s.condition, s.friction, dx), ox_(s.origin[0]), oy_(s.origin[1]), sx_(s.spacing[0]), sy_(s.spacing[1]),
        h_(s.heights) {}
  void apply(const Vec<3>& x, Vec<3>& v) const override {
    const int nx = static_cast<int>(h_[0].size()), ny = static_cast<int>(h_.size());
    const double u = std::clamp((x[0] - ox_) / sx_, 0.0, nx - 1.0), w = std::clamp((x[1] - oy_) / sy_, 0.0, ny - 1.0);
    const int i = std::min(static_cast<int>(u), nx - 2), j = std::min(static_cast<int>(w), ny - 2);
    const double fu = u - i, fw = w - j;
    const double h00 = h_[j][i], h10 = h_[j][i + 1], h01 = h_[j + 1][i], h11 = h_[j + 1][i + 1];
    const double h = (1 - fw) * ((1 - fu) * h00 + fu * h10) + fw * ((1 - fu) * h01 + fu * h11);
    if (x[2] > h + tol_) return;
    const double dhdx = ((1 - fw) * (h10 - h00) + fw * (h11 - h01)) / sx_;
    const double dhdy = ((1 - fu) * (h01 - h00) + fu * (h11 - h10)) / sy_;
    apply_condition<3>(condition_, friction_, Vec<3>(Real(-dhdx), Real(-dhdy), 1).normalized(), v);
  }

 private:
  double ox_, oy_, sx_, sy_;
  std::vector<std::vector<double>> h_;
};

}  // namespace

template <int dim>
std::unique_ptr<Boundary<dim>> make_boundary(const BoundarySpec& s, const Vec<dim>& domain_size, Real dx) {
  if (s.type == "walls") return std::make_unique<Walls<dim>>(s, domain_size, dx);
  if (s.type == "half_plane") return std::make_unique<HalfPlane<dim>>(s, dx);
  if (s.type == "box") return std::make_unique<BoxObstacle<dim>>(s, domain_size, dx);
  if (s.type == "bathymetry") {
    if constexpr (dim == 2) return std::make_unique<Bathymetry2D>(s, dx);
    else return std::make_unique<HeightField3D>(s, dx);
  }
  throw std::invalid_argument("unknown boundary type '" + s.type + "'");
}

template std::unique_ptr<Boundary<2>> make_boundary<2>(const BoundarySpec&, const Vec<2>&, Real);
template std::unique_ptr<Boundary<3>> make_boundary<3>(const BoundarySpec&, const Vec<3>&, Real);

}  // namespace cdmpm
