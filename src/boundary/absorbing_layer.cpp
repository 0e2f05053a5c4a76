// absorbing_layer.cpp - the "absorbing_layer" boundary: a layer of width W in front of a closed domain face that
// lets water waves leave the domain without reflecting them (docs/water.md#absorbing-layer).
//
// In the layer, the grid velocity u along the face's outward normal is relaxed towards the velocity of a long
// wave leaving through the face (Sommerfeld's radiation condition, as in Flather's open boundary):
//   du/dt = ... - sigma(s) (u - u*),   u* = sqrt(g / h) eta,   sigma(s) = sigma_max s^2,            (1)
// s in [0, 1] the distance into the layer over W (a smooth ramp: Israeli & Orszag 1981), eta the free-surface
// elevation above still_level in the node's grid column (the highest fluid particle plus half its spacing, as
// the wave gauges measure it), h the still depth. In Riemann variables of the shallow-water equations,
// R+- = u +- sqrt(g / h) eta, the term damps only R-, the wave travelling back into the domain: a long wave going
// out passes the layer unchanged, reaches the face (a closed slip wall of the scene's walls) and is reflected
// there, and its reflection is damped on its way back (by exp(-integral sigma dx / c) = exp(-sigma_max W / 3c)).
// The mass a wave carries out piles up against the face; a spillway (a sink over the last spill_width of the
// layer, above spill_level = still_level + dx / 4 by default: a removed particle stands for water up to half its
// spacing, dx / 4 at 4 particles per cell, below it) removes it, so the level there goes back to about the still
// level, and still water, whose surface lies below the spillway, is never drained. The relaxation is implicit, u <- (u + dt sigma u*) / (1 + dt sigma), stable for any sigma dt.
// Nodes on the face plane and beyond belong to the wall and are left alone. Scene keys: face, width,
// still_level, depth, strength (sigma_max [1/s], default 40 sqrt(g h) / W), spill_width (default W / 4),
// spill_level (docs/scenes.md#absorbing-layer, with the sizing rule).
#include <algorithm>
#include <cmath>
#include <limits>

#include "parallel/reduction.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

template <int dim>
class AbsorbingLayer final : public Boundary<dim> {
 public:
  AbsorbingLayer(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx)
      : Boundary<dim>(r, n, ctx.dx), size_(ctx.domain_size), dx_(ctx.dx) {
    // Not a solid: no condition or friction (its face is closed by the scene's walls).
    r.object(n, {"type", "face", "width", "still_level", "depth", "strength", "spill_width", "spill_level"});
    constexpr int up = vertical_axis<dim>;
    Strings faces = {"x-", "x+"};
    if (dim == 3) faces.insert(faces.end(), {"y-", "y+"});
    face_ = r.string(r.required(n, "face"), faces);
    axis_ = face_[0] - 'x';
    side_ = face_[1] == '+' ? 1 : 0;
    const double extent = size_[axis_];
    width_ = static_cast<Real>(r.number(r.required(n, "width"), {2 * dx_, extent},
                                        " (at least 2 dx and at most the domain's extent along the face normal)"));
    const double top = size_[up];
    still_level_ = static_cast<Real>(r.number(r.required(n, "still_level"), {0, top, true, true},
                                              " (a height inside the domain)"));
    depth_ = static_cast<Real>(r.number(r.required(n, "depth"), {0, still_level_, true, false},
                                        " (the still depth in the layer, 0 < depth <= still_level)"));
    if (n.has("strength")) strength_ = static_cast<Real>(r.number(n["strength"], gt(0), " [1/s]"));
    spill_ = static_cast<Real>(r.number(n, "spill_width", {0, width_, true, false}, width_ / 4));
    spill_level_ = static_cast<Real>(r.number(n, "spill_level", {still_level_, top}, still_level_ + dx_ / 4));
  }

  void prepare(const Simulation<dim>& sim, Real dt) override {
    const Real g = std::abs(sim.gravity[vertical_axis<dim>]);
    dt_ = dt;
    sqrt_g_over_h_ = std::sqrt(g / depth_);
    sigma_max_ = std::isnan(strength_) ? 40 * std::sqrt(g * depth_) / width_ : strength_;
    if (eta_.empty()) make_columns();
    measure_surface(sim);
  }

  void apply(const Vec<dim>& x, Vec<dim>& v) const override {
    const Real into = side_ ? x[axis_] - (size_[axis_] - width_) : width_ - x[axis_];
    if (into <= 0 || into >= width_ - this->tol_) return;  // outside the layer, or on the face (the wall's)
    const Real s = into / width_;
    const Real sigma_dt = sigma_max_ * s * s * dt_;
    const Real target = (side_ ? 1 : -1) * sqrt_g_over_h_ * eta_[static_cast<size_t>(column_index(x))];
    v[axis_] = (v[axis_] + sigma_dt * target) / (1 + sigma_dt);
  }
  bool is_solid(const Vec<dim>&) const override { return false; }
  bool relaxes() const override { return true; }
  std::string needs_closed_face() const override { return face_; }

  std::vector<SinkSpec> sinks() const override {
    SinkSpec k;
    constexpr double big = std::numeric_limits<double>::max();
    k.min.assign(dim, 0);
    k.max.assign(dim, big);
    for (int a = 0; a < dim; ++a) k.max[a] = size_[a];
    k.min[axis_] = side_ ? size_[axis_] - spill_ : -big;
    k.max[axis_] = side_ ? big : spill_;
    k.min[vertical_axis<dim>] = spill_level_;
    k.max[vertical_axis<dim>] = big;
    if (dim == 3) k.min[other_axis()] = -big, k.max[other_axis()] = big;
    return {k};
  }

 private:
  // The grid columns of the layer: node indices [lo, hi] along the axis, times all nodes of the other horizontal
  // axis in 3D (made at the first step, once the loader has checked that the grid is not too large).
  void make_columns() {
    const Real inner = side_ ? size_[axis_] - width_ : width_;
    lo_ = side_ ? static_cast<int>(std::floor(inner / dx_)) : 0;
    hi_ = side_ ? static_cast<int>(std::lround(size_[axis_] / dx_)) : static_cast<int>(std::ceil(inner / dx_));
    across_ = dim == 3 ? static_cast<int>(std::lround(size_[other_axis()] / dx_)) + 1 : 1;
    eta_.assign(static_cast<size_t>((hi_ - lo_ + 1) * across_), 0);
  }
  int other_axis() const { return axis_ == 0 ? 1 : 0; }  // the horizontal axis along the face (3D)
  // Index of the grid column holding point x (the nearest node along the axis; along the face, the nearest node
  // inside the domain), or -1 outside the layer's columns.
  long column_index(const Vec<dim>& x) const {
    const long i = std::lround(x[axis_] / dx_);
    if (i < lo_ || i > hi_) return -1;
    long j = 0;
    if constexpr (dim == 3) j = std::clamp<long>(std::lround(x[other_axis()] / dx_), 0, across_ - 1);
    return (i - lo_) * across_ + j;
  }
  // eta of every column: the highest fluid particle in it plus half its spacing, minus still_level (0 in an
  // empty column). Maxima are exact in any order, so the result is the same on any number of threads, and, taken
  // over the ranks of a distributed run (global::max: every rank then holds every column), on any number of ranks.
  void measure_surface(const Simulation<dim>& sim) {
    const auto& P = sim.particles;
    constexpr Real none = -std::numeric_limits<Real>::infinity();
    std::vector<Real> top(eta_.size(), none);
    const size_t first = P.solid_count(), n = P.size();
#pragma omp parallel
    {
      std::vector<Real> mine(top.size(), none);
#pragma omp for schedule(static)
      for (size_t q = first; q < n; ++q) {
        const Material& m = sim.materials[P.material[q]];
        if (!m.traits().fluid) continue;
        const long c = column_index(P.x[q]);
        if (c >= 0) mine[c] = std::max(mine[c], P.x[q][vertical_axis<dim>] + m.half_spacing);
      }
#pragma omp critical(cdmpm_absorbing_layer)
      for (size_t c = 0; c < top.size(); ++c) top[c] = std::max(top[c], mine[c]);
    }
    global::max(top);
    for (size_t c = 0; c < top.size(); ++c) eta_[c] = top[c] == none ? 0 : top[c] - still_level_;
  }

  Vec<dim> size_;
  Real dx_;
  std::string face_;
  int axis_ = 0, side_ = 1;
  Real width_ = 0, still_level_ = 0, depth_ = 0, spill_ = 0, spill_level_ = 0;
  Real strength_ = std::numeric_limits<Real>::quiet_NaN();  // the scene's strength, NaN for the default
  // Set by prepare for the step: dt, sqrt(g / h) (u* = sqrt_g_over_h_ eta) and sigma_max.
  Real dt_ = 0, sqrt_g_over_h_ = 0, sigma_max_ = 0;
  int lo_ = 0, hi_ = 0, across_ = 1;
  std::vector<Real> eta_;
};

}  // namespace

CDMPM_BOUNDARY_FACTORY(make_absorbing_layer, AbsorbingLayer)

}  // namespace cdmpm
