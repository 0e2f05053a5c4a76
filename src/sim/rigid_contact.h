// rigid_contact.h - frictionless contact between the rigid bodies and the other materials (water, ice) on the
// grid: the bodies have their own grid field (multi-field MPM contact, Bardenhagen et al. 2000), and the contact
// is solved implicitly for each body's rigid motion.
//
// The other materials scatter to the grid without the body's particles (transfer/p2g.h skips them) and update
// their velocities v_i as usual (grid/grid_update.h). The rigid particles scatter into the body field: at node i,
// with quadratic B-spline weights w_ip,
//   m^b_i = sum_p w_ip m_p,   g_i = sum_p m_p grad_i w_ip,   n_i = -g_i / |g_i|
// (n_i: the body's outward normal; its mass gradient points into it). A node holding both fields (water mass
// m_i > 0) is in contact when the body's rigid velocity there moves into the water faster than the water moves
// away: lambda_i = u_i . n_i - v_i . n_i > 0, u_i = V + omega x r_i the body's velocity at x_i (r_i = x_i - x_c,
// or x_i - o about a hinge o). The water's normal velocity then becomes the body's, its tangential velocity is
// left alone (no friction: the water slides along the body):  v_i += lambda_i n_i.
// The body takes the opposite impulse, so momentum is conserved:
//   M (V - V*) = -sum_i m_i lambda_i n_i,    I (omega - omega*) = -sum_i m_i lambda_i (r_i x n_i),
// V* = V + dt g and omega* = omega (hinged: omega* = omega + dt I_o^-1 (r_c x M g)) the motion without contact.
// With s = (V, omega) and the row J_i = (n_i, r_i x n_i), so that u_i . n_i = J_i s, this is the linear system
//   (diag(M, I) + sum_i m_i J_i^T J_i) s = diag(M, I) s* + sum_i m_i J_i^T (v_i . n_i)
// over the contact set, solved again until the set (lambda_i > 0) no longer changes; each node enters with the
// mass c_i m_i and takes c_i lambda_i, c_i its share of the contact (solve()). Being implicit, it is stable for
// any mass ratio (an explicit exchange node by node lets the water at the contact nodes, which keeps part of its
// push, creep into the body). A hinged body solves for omega only; a held body (time < hold_until) is a wall,
// s = 0, and a driven one (`motion`) turns at its prescribed rate.
// The boundaries hold the body the same way: at a body node where a boundary blocks a direction n_w (into its
// solid), a row J_w = (n_w, r x n_w) with the target 0 and the weight wall_weight m^b_i keeps u . n_w <= 0 (no
// friction; the body may leave). Without them nothing but the water would act on the body's motion, and the water
// pressing a body against a wall would push it through (the BF block: 16 mm into the wall in 0.5 s).
// Only the bodies of a rigid material with `contact` take part; the others share the water's field as before.
// The body's field velocity is then the rigid velocity at each node, the boundaries' conditions applied, which
// its particles read (APIC g2p, gather); sim/rigid_bodies.h projects them on the rigid motion as before.
// Why: with one shared velocity field (the coupling before this one) every node the body touched gave the
// water there the body's velocity, tangential components included, so a layer of water about a kernel width
// thick beside the body was dragged with it, and the body's pressure, a penalty on the volume change the grid
// imposed on it, carried the buoyancy with a lag: a submerged block of density 920 in water rose at a quarter to
// two thirds of the potential-flow acceleration (docs/changelog.md, "Buoyancy coupling"). With the contact and XPIC(4) on the
// water the block rises within 9 % at D/16. Known limits (docs/validation.md, "Buoyancy-driven motions"): a
// surfacing body keeps a film of water one cell deep on its top, which does not drain, so it floats that much too
// deep; and the part of a face's water pressure that the shares pass to the body depends on where the face lies
// between grid planes (0.755 to 0.995 of it, tools/contact_share_phi.py): over the second half of each cell a
// rising body's bottom face passes less and its top face more, and the rise at D/32 stalls there (0.18-0.26 s).
// Shares that pass the same part at every offset hold more water a cell out and rise slower (docs/validation.md,
// "What the share passes of the pressure").
// Sums over the contact nodes are exact (math/exact_sum.h), so they have the same bits for any order, thread
// count and number of ranks; a distributed run adds its own nodes only (`owned`) and sums the accumulators
// over the ranks, so every rank solves the same system; every rank holds every rigid particle (gathered in the
// one-process order), so the body field at each of its nodes, and its velocity there, are complete (the water's
// corrected velocities at halo nodes come from their owners, as every grid velocity).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "boundary/boundary.h"
#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "math/exact_sum.h"
#include "parallel/reduction.h"

namespace cdmpm {

template <int dim>
class RigidContact {
 public:
  static constexpr int rot = dim == 2 ? 1 : 3;
  static constexpr int ndof = dim + rot;
  using Dof = Eigen::Matrix<double, ndof, 1>;
  using DofMat = Eigen::Matrix<double, ndof, ndof>;

  // One rigid particle's inputs (in the one-process order on every rank: sim/rigid_bodies.h).
  struct Input {
    int body;
    Real mass;
    Vec<dim> x;
  };
  // One body's state for the contact: mass, inertia about its origin, centre of mass, origin (centre or hinge),
  // its motion s* without contact, and how it may move.
  struct Body {
    double mass = 0;
    Eigen::Matrix<double, rot, rot> inertia;
    Vec<dim> centre, origin;
    Dof s_star = Dof::Zero();
    bool hinged = false, fixed = false;  // fixed: held, driven or not in contact: s = s*
    Dof s = Dof::Zero();  // result: (V, omega) after the contact
  };

  // The body field on the grid's active nodes from every rigid particle, in the given order (serial: the same
  // sums in the same order on every rank and for any thread count). Nodes of two bodies belong to neither's
  // contact (bodies touching each other are not handled).
  void scatter(const std::vector<Input>& in, const Grid<dim>& g) {
    const size_t n = g.node_count();
    mass_.assign(n, Real(0));
    gradient_.assign(n, Vec<dim>::Zero());
    body_.assign(n, -1);
    nodes_.clear();
    for (const Input& q : in) {
      const BSplineStencil<dim> s(q.x * g.inv_dx);
      Real dw[dim][3];  // per-axis weight derivatives with respect to the node position: -d w / d x_p
      for (int a = 0; a < dim; ++a) {
        const Real f = s.fx[a];
        dw[a][0] = (Real(1.5) - f) * g.inv_dx;
        dw[a][1] = Real(2) * (f - Real(1)) * g.inv_dx;
        dw[a][2] = -(f - Real(0.5)) * g.inv_dx;
      }
      for_each_stencil_node<dim>([&](const IVec<dim>& o) {
        const size_t k = g.find(IVec<dim>(s.base + o));
        if (k == Grid<dim>::npos) return;
        Vec<dim> grad;
        for (int a = 0; a < dim; ++a) {
          Real r = dw[a][o[a]];
          for (int b = 0; b < dim; ++b)
            if (b != a) r *= s.w[b][o[b]];
          grad[a] = r;
        }
        if (mass_[k] == 0) {
          nodes_.push_back(k);
          body_[k] = q.body;
        } else if (body_[k] != q.body) {
          body_[k] = -2;
        }
        mass_[k] += s.weight(o) * q.mass;
        gradient_[k] += q.mass * grad;
      });
    }
    std::sort(nodes_.begin(), nodes_.end());
  }

  // After the grid update of the other materials: solves each body's contact (see the header), corrects the
  // water's velocity at its contact nodes, and sets the body field's velocity (the rigid velocity, then the
  // boundaries' conditions) at every node it holds. `owned(k)`: node k's sums belong to this process.
  // A node's share of the contact, c_i in [0, 1], rises linearly from 0 to 1 as its body mass goes from
  // ramp_start to ramp_end of the body mass of a node deep inside the body: the nodes inside the body and those
  // within about half a cell outside its surface take part (a node 0.5 dx outside a face holds 0.16 of it, 0.75 dx
  // outside 0.06, the outermost ring that the body's particles reach, 1.25 dx outside, 0.016). The node enters the
  // sums with the mass c_i m_i and its water takes c_i lambda_i. Contact at every node the body reaches inflates the
  // body by a kernel width (the block of docs/validation.md rose at 0.12 m/s^2 instead of 0.20 at D/8); a sharp
  // cut at 0.1 gives the body an impulse each time a node crosses it as the body moves (its velocity jumps by up to
  // 60 % from one probe to the next once it has moved a quarter of a cell, D/32).
  static constexpr Real ramp_start = Real(0.05), ramp_end = Real(0.2);
  // c_i for a node holding `fraction` of a deep node's body mass (also the deformable solids' share,
  // sim/field_contact.h).
  static Real share(Real fraction) {
    return std::clamp((fraction - ramp_start) / (ramp_end - ramp_start), Real(0), Real(1));
  }

  // The boundaries hold the bodies as a wall of this many times a node's body mass would (a stiff constraint in the
  // implicit system, so that the body does not drift into a wall that the water presses it against).
  static constexpr double wall_weight = 1e6;

  // Nodes inside a boundary's solid take its condition instead of the contact.
  void solve(std::vector<Body>& bodies, Grid<dim>& g, const std::vector<std::unique_ptr<Boundary<dim>>>& bcs,
             const std::function<bool(size_t)>& owned) {
    const size_t nb = bodies.size();
    // The constraint rows: water nodes (the body may not move into the water faster than the water moves away,
    // u . n <= v . n) and body nodes that a boundary holds (u . n <= 0 along the direction it blocks).
    struct Row {
      size_t k;
      int body;
      Vec<dim> n;
      double weight, target;
      bool water;
      Real share;
    };
    std::vector<Row> rows;
    std::vector<Real> full(nb, Real(0));  // a node's body mass deep inside the body
    for (const size_t k : nodes_)
      if (body_[k] >= 0) full[body_[k]] = std::max(full[body_[k]], mass_[k]);
    for (const size_t k : nodes_) {
      const int b = body_[k];
      if (b < 0) continue;
      const Vec<dim> x = position(g, k);
      for (const Vec<dim>& n : blocked_directions(bcs, x, g.dx))
        rows.push_back({k, b, n, wall_weight * static_cast<double>(mass_[k]), 0.0, false, Real(1)});
      const Real len = gradient_[k].norm();
      if (g.mass[k] <= 0 || !(len > 0)) continue;
      const Real share = RigidContact::share(mass_[k] / full[b]);
      if (!(share > 0)) continue;
      if (any_solid(bcs, x)) continue;
      const Vec<dim> n = -gradient_[k] / len;
      rows.push_back({k, b, n, static_cast<double>(g.mass[k] * share), static_cast<double>(g.momentum[k].dot(n)), true,
                      share});
    }
    auto jacobian = [&](const Row& w) {
      const Body& B = bodies[w.body];
      const Vec<dim> r = position(g, w.k) - B.origin;
      Dof J = Dof::Zero();
      if (!B.hinged)
        for (int a = 0; a < dim; ++a) J[a] = w.n[a];
      if constexpr (dim == 2) J[dim] = r[0] * w.n[1] - r[1] * w.n[0];
      else J.template tail<3>() = r.cross(w.n).template cast<double>();
      return J;
    };
    // The active set from s: lambda = J s - target > 0. Whether it changed on any process's own nodes.
    std::vector<char> active(rows.size(), 0);
    auto update_set = [&]() {
      bool changed = false;
      for (size_t i = 0; i < rows.size(); ++i) {
        const Row& w = rows[i];
        const char a = jacobian(w).dot(bodies[w.body].s) - w.target > 0;
        changed |= a != active[i] && owned(w.k);
        active[i] = a;
      }
      return global::max(changed ? 1.0 : 0.0) > 0;
    };
    for (Body& B : bodies) B.s = B.s_star;
    update_set();
    for (int iteration = 0; iteration < 20; ++iteration) {
      // Sums over the active rows: sum weight J^T J and sum weight J^T target, exact.
      std::vector<std::array<ExactSum, ndof * ndof + ndof>> sums(nb);
      for (size_t i = 0; i < rows.size(); ++i) {
        const Row& w = rows[i];
        if (!active[i] || !owned(w.k)) continue;
        const Dof J = jacobian(w);
        for (int r = 0; r < ndof; ++r) {
          for (int c = 0; c < ndof; ++c) sums[w.body][r * ndof + c].add(w.weight * J[r] * J[c]);
          sums[w.body][ndof * ndof + r].add(w.weight * J[r] * w.target);
        }
      }
      for (size_t b = 0; b < nb; ++b) {
        std::vector<ExactSum> v(sums[b].begin(), sums[b].end());
        global::sum(v);
        Body& B = bodies[b];
        if (B.fixed) continue;
        DofMat A = DofMat::Zero();
        Dof rhs = Dof::Zero();
        for (int r = 0; r < ndof; ++r) {
          for (int c = 0; c < ndof; ++c) A(r, c) = v[r * ndof + c].value();
          rhs[r] = v[ndof * ndof + r].value();
        }
        DofMat Mb = DofMat::Zero();
        for (int a = 0; a < dim; ++a) Mb(a, a) = B.hinged ? 1.0 : B.mass;  // hinged: V is not a freedom
        Mb.template bottomRightCorner<rot, rot>() = B.inertia;
        B.s = (Mb + A).ldlt().solve(Mb * B.s_star + rhs);
        if (B.hinged) B.s.template head<dim>().setZero();
      }
      if (!update_set()) break;
    }
    // The water's normal velocity at the active water rows becomes the body's.
    for (size_t i = 0; i < rows.size(); ++i) {
      const Row& w = rows[i];
      if (!active[i] || !w.water) continue;
      const Real lambda = static_cast<Real>(jacobian(w).dot(bodies[w.body].s)) - g.momentum[w.k].dot(w.n);
      g.momentum[w.k] += w.share * lambda * w.n;
      apply_conditions(bcs, position(g, w.k), g.momentum[w.k]);
    }
    // The body field's velocity: its body's rigid velocity (nodes of two bodies: their mass-weighted mean is not
    // known here, so the first body's), then the boundaries' conditions.
    velocity_.assign(g.node_count(), Vec<dim>::Zero());
    for (const size_t k : nodes_) {
      const Vec<dim> x = position(g, k);
      const int b = body_[k] >= 0 ? body_[k] : 0;
      velocity_[k] = rigid_velocity(bodies[b], x);
      apply_conditions(bcs, x, velocity_[k]);
    }
  }

  // APIC grid-to-particle transfer of the body field to the rigid particles (transfer/g2p.h's formula).
  void gather(Particles<dim>& p, const Grid<dim>& g, const std::vector<uint8_t>& rigid_material) const {
    const Real Dinv = Real(4) * g.inv_dx * g.inv_dx;
    const size_t np = p.size();
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < np; ++q) {
      if (!rigid_material[p.material[q]]) continue;
      const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
      Vec<dim> v = Vec<dim>::Zero();
      Mat<dim> B = Mat<dim>::Zero();
      for_each_stencil_node<dim>([&](const IVec<dim>& o) {
        const size_t k = g.find(IVec<dim>(s.base + o));
        if (k == Grid<dim>::npos) return;
        const Real w = s.weight(o);
        v += w * velocity_[k];
        B += (w * velocity_[k]) * (s.offset(o) * g.dx).transpose();
      });
      p.v[q] = v;
      p.C[q] = Dinv * B;
    }
  }

 private:
  static Vec<dim> position(const Grid<dim>& g, size_t k) { return g.position(g.node(k)); }
  // The directions in which the boundaries keep a body from moving at x (unit vectors into their solid), from
  // what their conditions remove of the velocities +-e_a. Removed parts along one direction n (a slip or separating
  // face, at any slope): n, turned towards the side that is solid a cell away. Along several (a sticky face, a
  // corner): each axis e_a whose one side only is solid a cell away, so a sticky face's tangent is not blocked.
  // The boundaries hold a body without friction, and it may leave them.
  static std::vector<Vec<dim>> blocked_directions(const std::vector<std::unique_ptr<Boundary<dim>>>& bcs,
                                                  const Vec<dim>& x, Real dx) {
    Mat<dim> S = Mat<dim>::Zero();
    for (int a = 0; a < dim; ++a)
      for (const Real sign : {Real(1), Real(-1)}) {
        const Vec<dim> v = sign * Vec<dim>::Unit(a);
        Vec<dim> w = v;
        apply_conditions(bcs, x, w);
        S += (v - w) * (v - w).transpose();
      }
    std::vector<Vec<dim>> out;
    if (!(S.norm() > Real(1e-12))) return out;
    const Eigen::SelfAdjointEigenSolver<Mat<dim>> eig(S);
    const Vec<dim> lambda = eig.eigenvalues();  // ascending
    auto towards_solid = [&](const Vec<dim>& n) {
      const bool p = any_solid<dim>(bcs, x + dx * n), m = any_solid<dim>(bcs, x - dx * n);
      if (p != m) out.push_back(p ? n : Vec<dim>(-n));
    };
    if (lambda[dim - 2] < Real(1e-6) * lambda[dim - 1]) {
      towards_solid(eig.eigenvectors().col(dim - 1));
    } else {
      for (int a = 0; a < dim; ++a) towards_solid(Vec<dim>::Unit(a));
    }
    return out;
  }
  static Vec<dim> rigid_velocity(const Body& B, const Vec<dim>& x) {
    const Vec<dim> V = B.s.template head<dim>().template cast<Real>();
    const Vec<dim> r = x - B.origin;
    if constexpr (dim == 2) {
      const Real w = static_cast<Real>(B.s[dim]);
      return V + Vec<dim>(-w * r[1], w * r[0]);
    } else {
      return V + Vec<dim>(B.s.template tail<3>().template cast<Real>()).cross(r);
    }
  }

  std::vector<Real> mass_;
  std::vector<Vec<dim>> gradient_, velocity_;
  std::vector<int> body_;      // per node: the body whose particles reach it, -1 none, -2 several
  std::vector<size_t> nodes_;  // the nodes the bodies reach, ascending
};

}  // namespace cdmpm
