// box_obstacle.cpp - the "box" boundary: a solid box [min, max], static or moving (a pusher, a gate, a grip).
// Scene keys: min, max (dim numbers each), velocity (dim numbers, default at rest), ramp_time [s] (default 0).
#include <algorithm>
#include <cmath>
#include <limits>

#include "boundary/mirror.h"

namespace cdmpm {
namespace {

// Solid box [min, max] translated by d(t): the normal is that of the nearest face (all nearest faces on an
// edge or a corner). Its velocity u(t) ramps
// linearly from 0 to `velocity` U over the ramp time T (d = U t^2 / (2T) for t < T, U (t - T/2) after).
template <int dim>
class BoxObstacle final : public Boundary<dim> {
 public:
  BoxObstacle(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx)
      : Boundary<dim>(r, n, ctx.dx), all_(ctx.all), dx_(ctx.dx) {
    Strings keys = Boundary<dim>::common_keys();
    keys.insert(keys.end(), {"min", "max", "velocity", "ramp_time"});
    r.object(n, keys);
    std::vector<double> lo, hi;
    r.min_max(n, lo, hi);
    min0_ = min_ = to_vec<dim>(lo);
    max0_ = max_ = to_vec<dim>(hi);
    final_velocity_ = n.has("velocity") ? to_vec<dim>(r.numbers(n["velocity"], dim)) : Vec<dim>::Zero().eval();
    ramp_ = r.number(n, "ramp_time", ge(0), 0.0);
    velocity_ = ramp_ > 0 ? Vec<dim>::Zero().eval() : final_velocity_;
    const Vec<dim>& domain_size = ctx.domain_size;
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
  // Inside a static box (its faces excluded). A moving box is a pusher or a grip, which may hold the material
  // seeded inside it (the sliding block's pusher starts inside the end of the slab): nothing is solid for seeding.
  bool is_solid(const Vec<dim>& x) const override {
    if (!final_velocity_.isZero()) return false;
    for (int a = 0; a < dim; ++a)
      if (!(x[a] > min0_[a] && x[a] < max0_[a])) return false;
    return true;
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
  std::vector<std::array<IVec<dim>, 2>> mirror_node_pairs(const Grid<dim>& g) const override {
    std::vector<std::array<IVec<dim>, 2>> out;
    for (const MirrorPair& m : mirror_pairs(g)) out.push_back({m.src, m.dst});
    return out;
  }
  // A particle that advected into a static slip box is put back on its nearest open face (see Walls).
  void keep_inside(Vec<dim>& x, Vec<dim>& /*v*/) const override {
    if (!mirrored()) return;
    int axis = -1, side = 0;
    Real best = std::numeric_limits<Real>::max();
    for (int a = 0; a < dim; ++a) {
      const Real lo = x[a] - min_[a], hi = max_[a] - x[a];
      if (!(lo > 0 && hi > 0)) return;
      if (open_[a][0] && lo < best && !covered(x, a, 0)) best = lo, axis = a, side = 0;
      if (open_[a][1] && hi < best && !covered(x, a, 1)) best = hi, axis = a, side = 1;
    }
    if (axis >= 0) x[axis] = side ? max_[axis] : min_[axis];
  }

 private:
  struct MirrorPair {
    IVec<dim> src, dst;  // physical node indices
    int axis;
  };
  bool mirrored() const { return this->condition_ == BoundaryCondition::Slip && final_velocity_.isZero(); }

  // Whether the face (axis a, side) is against another static box where point x projects onto it (a quarter cell
  // outside the face): then it is no face of the material there (two boxes side by side: the cliff of a glacier
  // built from boxes), and a node behind it is mirrored for its nearest face that the material does touch. (A
  // bathymetry's solid does not cover a face: the water of its bed layer fills it, sim/bed_layer.h.)
  bool covered(const Vec<dim>& x, int a, int side) const {
    if (!all_) return false;
    Vec<dim> p = x;  // x's nearest point of the face, a quarter cell inside its edges, then a quarter cell out
    const Real q = Real(0.25) * dx_;
    for (int b = 0; b < dim; ++b)
      if (b != a) p[b] = std::clamp(p[b], min0_[b] + std::min(q, (max0_[b] - min0_[b]) / 2), max0_[b] - std::min(q, (max0_[b] - min0_[b]) / 2));
    p[a] = side ? max0_[a] + q : min0_[a] - q;
    for (const auto& b : *all_)
      if (b.get() != this && dynamic_cast<const BoxObstacle*>(b.get()) && b->is_solid(p)) return true;
    return false;
  }

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
    Vec<dim> x;
    for (int a = 0; a < dim; ++a) x[a] = static_cast<Real>(i[a]) * g.dx;
    for (int a = 0; a < dim && inside; ++a) {
      // Through a face on the domain boundary the box continues into the wall's ghost layers, so that
      // the nodes on and beyond that boundary are mirrored too (the corner of an obstacle and a wall).
      // A face against another solid bounds nothing: the node may lie on or beyond it.
      const bool open_lo = open_[a][0] && !covered(x, a, 0), open_hi = open_[a][1] && !covered(x, a, 1);
      const Real tol = node_tolerance_cells * g.dx;
      inside = (!open_lo || (on_grid[a][0] ? i[a] > lo[a] : x[a] > min0_[a] + tol)) &&
               (!open_hi || (on_grid[a][1] ? i[a] < hi[a] : x[a] < max0_[a] - tol));
      for (int sd = 0; sd < 2 && inside; ++sd) {
        if (!(sd ? open_hi : open_lo)) continue;
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

  const std::vector<std::unique_ptr<Boundary<dim>>>* all_;  // the simulation's boundaries (covered)
  Real dx_;
  Vec<dim> min0_, max0_, final_velocity_;
  double ramp_;
  Vec<dim> velocity_, min_, max_;
  std::array<std::array<bool, 2>, 3> open_{};
  mutable std::vector<MirrorPair> pairs_;
  mutable bool pairs_ready_ = false;
};

}  // namespace

CDMPM_BOUNDARY_FACTORY(make_box_obstacle, BoxObstacle)

}  // namespace cdmpm
