// boundary.h - boundary conditions on grid nodes: the interface every boundary type implements, and the
// registry that builds them (one file per type: boundary/walls.cpp, half_plane.cpp, box_obstacle.cpp,
// bathymetry.cpp, absorbing_layer.cpp; the list in boundary/registry.cpp).
//
// Every boundary is a solid region with an outward normal n (pointing from the solid into the material).
// A grid node inside the solid gets one of three conditions (Stomakhin et al. 2013, sec. 6; Jiang et al.
// 2016 course notes, sec. 10):
//   sticky:   v = 0
//   slip:     v <- v - (v.n) n                   (no flow through the wall either way)
//   separate: v <- v - min(v.n, 0) n             (material may leave the wall, not enter it)
// with optional Coulomb friction for slip and separate: where the wall pushed (v.n < 0), the tangential
// speed |v_t| is reduced by mu |v.n|, and set to zero if it is smaller than that.
// The solid's normal for walls is the face normal; for obstacles it comes from the shape.
// A moving obstacle (a box with a velocity u: a pusher, a gate, a grip) applies the same conditions to the
// node velocity relative to it, v - u, so a sticky moving box drags the material with velocity u. Its
// position is that at the start of the step (move_to(t) before the grid update).
//
// Mirror symmetry at slip domain walls that lie on a grid plane (a slip wall is a symmetry plane): after
// p2g, the mass and momentum scattered to ghost nodes beyond the wall are added to their mirror nodes
// inside, with the normal momentum reversed (the contribution of the material's mirror image). Without
// this, the nodes next to a wall miss the stress of the particle rows that would lie beyond it, and the
// particles next to the wall carry ~10 % more pressure than the hydrostatic value, an error that does not
// shrink with dx. After the grid update, each ghost node takes its mirror node's velocity, reflected, so
// that g2p reads the same symmetric field: folding without unfolding makes the two transfers non-adjoint,
// and the scheme injects energy (a dam break blows up).
// The same mirror applies at the faces of static slip box obstacles that lie on grid planes (faces on the
// domain boundary excepted; there the box continues into the wall's ghost layers so the corner of a box
// and a wall is mirrored consistently). Ghosts are unfolded in the reverse order of folding.
// A node counts as inside a solid when it lies within node_tolerance(dx) = 1e-3 dx of it, so a face placed on
// a grid plane holds the nodes on that plane whichever way the rounding of i dx and of the face coordinate goes
// (a face at x = 9 H with dx = H / 12 lies at 900 m, node 108 at 900.0000000000001 m: without the tolerance the
// node would be free, and water would flow into the face's cell). The same tolerance decides whether a face
// lies on a grid plane for the mirror treatment, so a face that holds a plane's nodes is also mirrored there.
// A sloping slip bathymetry is well balanced instead by a layer of fixed water particles inside it (in_bed_layer;
// sim/bed_layer.h), which completes the kernel support of the water above it.
// After advection, a particle that crossed any domain wall is put back on the wall plane (the grid velocity
// there has no normal component; the crossing is an interpolation overshoot of O(dt v)). The mirror picture
// needs every particle on the material side of the wall. On the sparse grid (grid/grid.h) a pair is folded
// only when both its nodes are active; with every particle on the material side, a stencil that reaches a
// ghost node also reaches its mirror, so no pair with mass is skipped.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/types.h"
#include "grid/grid.h"
#include "scene/scene.h"
#include "scene/scene_reader.h"

namespace cdmpm {

template <int dim>
class Simulation;

// Distance, in cells, within which a grid node counts as on a face (see above).
inline constexpr Real node_tolerance_cells = Real(1e-3);

// Applies a boundary condition with outward normal n to node velocity v.
template <int dim>
inline void apply_condition(BoundaryCondition c, Real friction, const Vec<dim>& n, Vec<dim>& v) {
  if (c == BoundaryCondition::Sticky) {
    v.setZero();
    return;
  }
  const Real vn = v.dot(n);
  if (c == BoundaryCondition::Separate && vn >= 0) return;
  v -= vn * n;
  if (friction > 0 && vn < 0) {
    const Real vt = v.norm();
    if (vt <= -friction * vn) v.setZero();
    else v *= Real(1) + friction * vn / vt;
  }
}

template <int dim>
class Boundary;

// What a boundary is built with besides its own scene keys: the domain extent, the grid spacing and, in a
// simulation, all of its boundaries (built in order; a boundary may look at the others once the run starts, e.g.
// a box's face against another solid is no face of the material).
template <int dim>
struct BoundaryContext {
  Vec<dim> domain_size;
  Real dx;
  const std::vector<std::unique_ptr<Boundary<dim>>>* all = nullptr;
};

template <int dim>
class Boundary {
 public:
  // Reads the keys every boundary has: "condition" (sticky, slip, separate; default separate) and "friction"
  // (Coulomb coefficient, default 0); the type's own keys are read by the derived class.
  Boundary(const SceneReader& r, const Node& n, Real dx);
  virtual ~Boundary() = default;
  // Applies the condition to velocity v of the node at position x if x is inside the solid.
  virtual void apply(const Vec<dim>& x, Vec<dim>& v) const = 0;
  // True if point x lies inside the solid at t = 0: seeding leaves such points empty (a moving box, which may
  // grip the material inside it, answers false).
  virtual bool is_solid(const Vec<dim>& x) const = 0;
  // Moves the solid to its position at time t (moving obstacles only).
  virtual void move_to(double) {}
  // Reads what the boundary needs from the state before the grid update of a step of length dt (absorbing layers:
  // the free surface in their columns). Called after move_to, before apply.
  virtual void prepare(const Simulation<dim>&, Real) {}
  // Outlets the boundary adds to the scene's sinks (absorbing layers: the spillway at their face).
  virtual std::vector<SinkSpec> sinks() const { return {}; }
  // The domain faces ("x-", ...) the boundary closes (walls), and the face it lies in front of and needs closed
  // by another boundary ("" if none; absorbing layers): the loader checks every such face is closed.
  virtual Strings closed_faces() const { return {}; }
  virtual std::string needs_closed_face() const { return ""; }
  // Adds ghost-node mass and momentum to mirror nodes (slip walls and static slip boxes; see above).
  virtual void fold_ghosts(Grid<dim>&) const {}
  // Sets ghost-node velocities to the reflected velocities of their mirror nodes (after grid_update).
  virtual void unfold_ghosts(Grid<dim>&) const {}
  // The (ghost, mirror) node pairs that fold_ghosts and unfold_ghosts combine, for boundaries inside the domain
  // (static slip boxes; the domain walls' pairs are shared between ranks by parallel/mirror_zone.h): a
  // distributed run keeps the blocks of each pair on one rank, so the fold and unfold see the one-process sums.
  virtual std::vector<std::array<IVec<dim>, 2>> mirror_node_pairs(const Grid<dim>&) const { return {}; }
  // Keeps a particle position (and, for a bathymetry, its velocity) on the material side of the boundary (walls,
  // static slip boxes and well-balanced bathymetry; see above).
  virtual void keep_inside(Vec<dim>&, Vec<dim>&) const {}
  // The well-balanced bed (sim/bed_layer.h): true if point x lies in the solid's bed layer, the part of the solid
  // within reach of its surface where fixed water particles complete the kernel support of the water above;
  // sets the surface's unit normal there (pointing into the material).
  virtual bool in_bed_layer(const Vec<dim>&, Vec<dim>&) const { return false; }
  // True for a condition that relaxes the velocity towards a target rather than constraining it (absorbing
  // layers): it acts once per node and step, and is left out of the repeated solid conditions (apply_conditions).
  virtual bool relaxes() const { return false; }

  // Distance within which a grid node counts as on a face (see above).
  static Real node_tolerance(Real dx) { return node_tolerance_cells * dx; }
  // The keys every boundary takes (the type's own keys are added to these).
  static Strings common_keys() { return {"type", "condition", "friction"}; }

 protected:
  BoundaryCondition condition_;
  Real friction_;
  Real tol_;  // node_tolerance(dx)
};

// Whether the solid of any of the boundaries holds point x (Boundary::is_solid).
template <int dim>
bool any_solid(const std::vector<std::unique_ptr<Boundary<dim>>>& bcs, const Vec<dim>& x) {
  for (const auto& b : bcs)
    if (b->is_solid(x)) return true;
  return false;
}

// Every boundary's condition on the velocity v of the grid node at x, in the scene's order (Boundary::apply).
// Where two solids meet at a node whose normals are not orthogonal (a cliff's box face on a sloping bed), each
// slip condition is a projection onto its tangent plane, and one pass of each leaves the earlier one violated:
// the water ran down the cliff face into the bed, and a lake at rest at the foot of the Eqip Sermia cliff rose
// 0.69 m in 20 s at dx = 40 m (0.08 m, away from the cliff, with the conditions met). Alternating projections
// converge to their intersection (von Neumann 1950): after the pass in order, the solids' conditions are applied
// in turn again, from the one after the last that changed v, until a whole round of the others changes nothing
// (at most kConditionRounds rounds). A node where at most one solid acts keeps the bits of a single pass.
inline constexpr int kConditionRounds = 64;

template <int dim>
void apply_conditions(const std::vector<std::unique_ptr<Boundary<dim>>>& bcs, const Vec<dim>& x, Vec<dim>& v) {
  const int n = static_cast<int>(bcs.size());
  int last = -1;
  for (int k = 0; k < n; ++k) {
    const Vec<dim> before = v;
    bcs[k]->apply(x, v);
    if (!bcs[k]->relaxes() && v != before) last = k;
  }
  if (last < 0 || n < 2) return;
  for (int step = 0, k = (last + 1) % n; k != last && step < kConditionRounds * n; ++step, k = (k + 1) % n) {
    if (bcs[k]->relaxes()) continue;
    const Vec<dim> before = v;
    bcs[k]->apply(x, v);
    if (v != before) last = k;
  }
}

// Defines the registry's factory NAME<dim> (2D and 3D) building a CLASS<dim> from its scene object; each boundary
// file ends with one (boundary/registry.cpp lists them).
#define CDMPM_BOUNDARY_FACTORY(NAME, CLASS)                                                                    \
  template <int dim>                                                                                         \
  std::unique_ptr<Boundary<dim>> NAME(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx) { \
    return std::make_unique<CLASS<dim>>(r, n, ctx);                                                          \
  }                                                                                                          \
  template std::unique_ptr<Boundary<2>> NAME<2>(const SceneReader&, const Node&, const BoundaryContext<2>&); \
  template std::unique_ptr<Boundary<3>> NAME<3>(const SceneReader&, const Node&, const BoundaryContext<3>&);

// The boundary types of the registry (boundary/registry.cpp).
Strings boundary_types();

// Builds a boundary of a registered type from its scene object, reading and validating its keys: the loader
// calls it to check the scene (throws SceneError), the simulation to build the boundaries of a checked scene.
template <int dim>
std::unique_ptr<Boundary<dim>> make_boundary(const SceneReader& reader, const Node& node, const BoundaryContext<dim>& ctx);
// The same for a loaded scene's boundary.
template <int dim>
std::unique_ptr<Boundary<dim>> make_boundary(const Scene& scene, const BoundarySpec& spec, const BoundaryContext<dim>& ctx);

}  // namespace cdmpm
