// rigid_bodies.h - rigid bodies made of material points, coupled to the other materials through the shared grid.
//
// Each rigid body is the set of particles of one rigid material (scene material type "rigid"; the loader lets a
// rigid material make only one body). Its particles carry mass, momentum and a penalty pressure (below) to the
// grid like any other particle, so the body and the water share the velocity of every node they both touch
// (no slip). With the rigid key `contact` they scatter instead into the bodies' own grid field, which meets the
// other materials' field in a frictionless contact (contact(), sim/rigid_contact.h: normal velocities exchanged
// where the body approaches the water, tangential ones free), and read their velocities back from it. After
// the grid-to-particle transfer, project() replaces their velocities by the rigid motion that has the same
// linear and angular momentum:
//   v_p = V + omega x (x_p - x_c),   C_p = [omega]_x (the skew matrix of omega, the rigid velocity gradient),
//   V = P / M,  P = sum_p m_p v_p,  M = sum_p m_p,  x_c = sum_p m_p x_p / M,
//   omega = I^-1 L,  L = sum_p [ m_p r_p x v_p + m_p D axial(C_p - C_p^T) ],  r_p = x_p - x_c,
//   I = sum_p m_p [ (|r_p|^2 + 2 D) 1 - r_p r_p^T ]   (2D: I and L are scalars, I = sum_p m_p (|r_p|^2 + 2 D)).
// The terms with D = dx^2/4 (the APIC inertia tensor of quadratic B-splines, Jiang et al. 2015, sec. 5.3) are
// the angular momentum and inertia that a particle's affine velocity C_p carries to the grid: with them the
// projection keeps exactly the angular momentum that p2g/g2p exchange through the grid.
// A hinged body turns about its fixed pivot o only: v_p = omega x (x_p - o), omega = I_o^-1 L_o with L and I
// taken about o (the pivot's reaction changes the linear momentum, not the angular momentum about o).
// A held body (time < hold_until) is at rest: v_p = 0, C_p = 0.
// A driven body (a hinged body with a `motion`, a prescribed tilt a(t)) turns about its pivot at the rate that takes
// it from a(t) to a(t + dt) over the step, whatever the forces: omega = (a(t + dt) - a(t)) / dt about the axis
// normal to the x-z plane (2D: counter-clockwise; 3D: -y, since the tilt turns +x towards +z). It is a wave maker
// of given motion, the same in 2D and 3D (scenes/eqip_sermia_3d.json).
// A replayed body (rigid key `track`, io/source_track.h) is not rigid: each of its particles follows the recorded
// displacement of the ice that started where it started, x_p(t) = X_p + u(X_p, t) (X_p its seeded position; in 3D u
// lies in the x-z plane, the same at every y), moving over each step by exactly x_p(t + dt) - x_p(t) at the velocity
// v_p = (x_p(t + dt) - x_p(t)) / dt, C_p = 0: a recorded 2D failure as a wave maker, in 2D or extruded in 3D
// (scenes/eqip_sermia_replay_2d.json, scenes/eqip_sermia_replay_3d.json). Its seeded positions are kept by particle id,
// so a replay runs in one process (resumed too: the seeding that precedes a checkpoint's load gives them again).
// Before its C_p is replaced, each particle of a body in the shared field has its volume ratio follow the grid:
// J_p <- min(1, J_p (1 + dt tr C_p)), so the particle's pressure (material/material.h, Rigid) resists other material
// flowing into the body. The pressure is zero for J >= 1 (no tension), and J is kept at most 1 so that a body that the
// water has left (the grid diverging around it) resists the water's return at once, without first undoing a fictitious
// expansion. (Known limit, docs/changelog.md, "Buoyancy coupling": through the shared nodes the body drags the water beside it,
// tangentially too, and the water's own transfers lose momentum at every step, so buoyancy-driven motions are slow at
// coarse resolution. A pressure taken instead from the water around the body, continuous across its surface, fed back
// on the water it compressed and made a surfacing body unstable. The contact removes the drag; a body that surfaces in
// it keeps a film of water one cell deep on its top and floats too deep, and its rise stalls when it has moved half
// a cell: sim/rigid_contact.h, docs/validation.md.)
// advance() then moves the particles rigidly over dt (constitutive_update leaves rigid particles in place):
//   x_p <- x_c + V dt + R(omega dt) (x_p - x_c)   (free),   x_p <- o + R(omega dt) (x_p - o)   (hinged),
// so the body keeps its shape exactly, accumulates the orientation R and (2D) the angle, and turns its velocity
// field with it: omega <- I'^-1 L with the turned inertia I' = R I R^T (torque-free, L unchanged; in 2D omega is
// unchanged) and v_p, C_p set from it at the new positions. Without this last step the particles would carry
// the velocities of their old positions, and each step would lose (omega dt)^2 / 2 of the angular momentum.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

#include "core/particles.h"
#include "io/source_track.h"
#include "material/material.h"
#include "parallel/reduction.h"
#include "scene/scene.h"
#include "sim/rigid_contact.h"

namespace cdmpm {

template <int dim>
struct RigidBody {
  static constexpr int rot = dim == 2 ? 1 : 3;  // components of an angular velocity
  using Spin = Eigen::Matrix<Real, rot, 1>;
  // Set-up (from the scene).
  int material = -1;         // the body is the particles of this material
  double hold_until = 0;     // at rest until this time [s]
  bool hinged = false;
  bool contact = false;      // in a field of its own, in frictionless contact with the others (rigid key `contact`)
  Vec<dim> pivot = Vec<dim>::Zero();
  // State.
  double mass = 0;
  Vec<dim> centre = Vec<dim>::Zero();    // centre of mass [m]
  Vec<dim> velocity = Vec<dim>::Zero();  // velocity of the centre of mass [m/s]
  Spin omega = Spin::Zero();             // angular velocity [rad/s] (2D: counter-clockwise)
  Mat<dim> rotation = Mat<dim>::Identity();  // orientation relative to the untilted shape
  Eigen::Matrix<Real, rot, rot> inertia = Eigen::Matrix<Real, rot, rot>::Identity();  // about the centre or pivot
                                                                                      // (set by each projection)
  double angle = 0;  // 2D: counter-clockwise angle from the untilted shape [rad], not wrapped; 3D: angle of `rotation`
  std::vector<std::array<double, 2>> motion;  // driven: prescribed tilt (time [s], degrees), piecewise linear
  std::shared_ptr<const SourceTrack> track;   // replayed: the recorded displacements its particles follow
  uint64_t first_id = 0;                      // replayed: the seeded position of particle `id` is start[id - first_id]
  std::vector<Vec<dim>> start;

  // Replayed: where the particle with this id is at time t, x = X + u(X, t).
  Vec<dim> replayed_position(uint64_t id, double t) const {
    constexpr int up = dim - 1;
    Vec<dim> x = start[id - first_id];
    const std::array<double, 2> u = track->displacement(x[0], x[up], t);
    x[0] += static_cast<Real>(u[0]);
    x[up] += static_cast<Real>(u[1]);
    return x;
  }

  // The prescribed tilt [rad] at time t: linear between the motion's pairs, held after the last.
  double prescribed_tilt(double t) const {
    const size_t i = motion_segment(t);
    if (i == motion.size()) return motion.back()[1] * std::numbers::pi / 180;
    const auto &a = motion[i - 1], &b = motion[i];
    const double f = std::clamp((t - a[0]) / (b[0] - a[0]), 0.0, 1.0);
    return (a[1] + f * (b[1] - a[1])) * std::numbers::pi / 180;
  }
  // The prescribed tilt rate [rad/s] at time t: the slope of the pair interval holding t, 0 after the last pair.
  double prescribed_rate(double t) const {
    const size_t i = motion_segment(t);
    if (i == motion.size()) return 0;
    const auto &a = motion[i - 1], &b = motion[i];
    return (b[1] - a[1]) / (b[0] - a[0]) * std::numbers::pi / 180;
  }
  // Index of the first pair later than or at t (motion.size() past the last), at least 1.
  size_t motion_segment(double t) const {
    size_t i = 1;
    while (i < motion.size() && motion[i][0] < t) ++i;
    return i;
  }
};

// Small helpers shared by the projection and the seeding: 2D angular quantities are 1-vectors.
template <int dim>
struct RigidAlgebra {
  using Spin = typename RigidBody<dim>::Spin;
  using Inertia = Eigen::Matrix<Real, RigidBody<dim>::rot, RigidBody<dim>::rot>;
  static Spin cross(const Vec<dim>& r, const Vec<dim>& v) {
    if constexpr (dim == 2) return Spin(r[0] * v[1] - r[1] * v[0]);
    else return r.cross(v);
  }
  static Vec<dim> spin_cross(const Spin& w, const Vec<dim>& r) {
    if constexpr (dim == 2) return Vec<dim>(-w[0] * r[1], w[0] * r[0]);
    else return w.cross(r);
  }
  static Mat<dim> skew(const Spin& w) {
    Mat<dim> S;
    if constexpr (dim == 2) S << 0, -w[0], w[0], 0;
    else S << 0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0;
    return S;
  }
  // axial(C - C^T): 2 omega when C = skew(omega).
  static Spin axial2(const Mat<dim>& C) {
    if constexpr (dim == 2) return Spin(C(1, 0) - C(0, 1));
    else return Spin(C(2, 1) - C(1, 2), C(0, 2) - C(2, 0), C(1, 0) - C(0, 1));
  }
  // The spin I^-1 L for the (symmetric positive-definite) inertia I and angular momentum L. In 2D I is 1 x 1 and
  // this is the quotient, the bits of Eigen's LDLT of a 1 x 1 matrix, whose pivoting code GCC 12 flags with
  // -Warray-bounds for that size.
  template <class I, class L>
  static L solve_spin(const I& inertia, const L& momentum) {
    if constexpr (dim == 2) return L(momentum[0] / inertia(0, 0));
    else return inertia.ldlt().solve(momentum);
  }
  // Inertia of mass m at offset r from the axis point, plus its APIC self-inertia 2 m D.
  static Inertia inertia(Real m, const Vec<dim>& r, Real D) {
    if constexpr (dim == 2) return Inertia(m * (r.squaredNorm() + 2 * D));
    else return m * ((r.squaredNorm() + 2 * D) * Inertia::Identity() - r * r.transpose());
  }
  // Rotation by the rotation vector w t (2D: angle w t counter-clockwise).
  static Mat<dim> rotation(const Spin& w, Real t) {
    if constexpr (dim == 2) return Eigen::Rotation2D<Real>(w[0] * t).toRotationMatrix();
    else {
      const Real a = w.norm() * t;
      return a == 0 ? Mat<dim>::Identity() : Eigen::AngleAxis<Real>(a, w.normalized()).toRotationMatrix();
    }
  }
  // The scene's tilt [degrees] as a rotation turning +x towards the vertical axis.
  static Mat<dim> tilt(double degrees) {
    const Real a = static_cast<Real>(degrees * std::numbers::pi / 180);
    Mat<dim> R = Mat<dim>::Identity();
    R(0, 0) = R(dim - 1, dim - 1) = std::cos(a);
    R(dim - 1, 0) = std::sin(a);
    R(0, dim - 1) = -std::sin(a);
    return R;
  }
};

template <int dim>
class RigidBodies {
 public:
  using A = RigidAlgebra<dim>;
  using Spin = typename RigidBody<dim>::Spin;
  static constexpr int rot_dofs = RigidBody<dim>::rot;
  std::vector<RigidBody<dim>> bodies;

  // One body per rigid body in the scene, with its initial state measured from the seeded particles; its
  // particles' velocities are projected (held bodies set at rest) so the state is consistent from t = 0. `keys`: as
  // for project().
  void init(const Scene& scene, const std::vector<Material>& materials, Particles<dim>& p, Real dx,
            const std::vector<uint64_t>* keys = nullptr) {
    bodies.clear();
    body_of_.assign(materials.size(), -1);
    for (const BodySpec& b : scene.bodies) {
      if (!materials[b.material_index].traits().rigid) continue;
      RigidBody<dim> body;
      body.material = b.material_index;
      body.hold_until = b.hold_until;
      body.motion = b.motion;
      body.track = b.track;
      body.hinged = !b.hinge.empty();
      body.contact = materials[b.material_index].contact();
      for (int a = 0; a < dim && body.hinged; ++a) body.pivot[a] = static_cast<Real>(b.hinge[a]);
      body.rotation = A::tilt(b.tilt);
      body.angle = b.tilt * std::numbers::pi / 180;
      body_of_[b.material_index] = static_cast<int>(bodies.size());
      bodies.push_back(body);
    }
    for (RigidBody<dim>& B : bodies) {  // a replayed body's seeded positions, by id
      if (!B.track) continue;
      uint64_t lo = UINT64_MAX, hi = 0;
      for (size_t q = 0; q < p.size(); ++q)
        if (p.material[q] == B.material) lo = std::min(lo, p.id[q]), hi = std::max(hi, p.id[q]);
      if (lo > hi) continue;
      B.first_id = lo;
      B.start.assign(hi - lo + 1, Vec<dim>::Zero());
      for (size_t q = 0; q < p.size(); ++q)
        if (p.material[q] == B.material) B.start[p.id[q] - lo] = p.x[q];
    }
    project(p, 0.0, 0, dx, keys);
  }

  // Index into `bodies` of the body made of `material`, -1 if that material is not rigid.
  int index_of_material(int material) const { return body_of_[material]; }

  // After g2p at time `time`: replaces the rigid particles' v and C by their bodies' rigid motion. `keys`: in a
  // distributed run, the order keys of this rank's particles (parallel/migration.h); null when p is the whole set.
  void project(Particles<dim>& p, double time, Real dt, Real dx, const std::vector<uint64_t>* keys = nullptr) {
    if (bodies.empty()) return;
    const Real D = dx * dx / 4;
    const size_t n = p.size(), nb = bodies.size();
    const std::vector<int>& body_of = body_of_;
    // The rigid particles in the one-process array order, the order of the sums below (bodies_in_order).
    const std::vector<Sample> s = samples_in_order(p, keys);
    // Pass 1: mass, centre of mass and inertia about the origin (centre of mass or pivot); momentum.
    // Pass 2: angular momentum about the origin. Serial, so the sums do not depend on the thread count.
    const MassProperties mp = mass_properties(s, D);
    std::vector<DVec> momentum(nb, DVec::Zero());
    for (const Sample& q : s) momentum[q.body] += static_cast<double>(q.mass) * q.v.template cast<double>();
    std::vector<DSpin> L(nb, DSpin::Zero());
    for (const Sample& q : s) {
      const Vec<dim> r = q.x - mp.origin[q.body];
      L[q.body] += (q.mass * (A::cross(r, q.v) + D * A::axial2(q.C))).template cast<double>();
    }
    const std::vector<double>& mass = mp.mass;
    const std::vector<DInertia>& I = mp.inertia;
    for (size_t b = 0; b < nb; ++b) {
      RigidBody<dim>& B = bodies[b];
      B.mass = mass[b];
      B.centre = mp.centre[b];
      B.inertia = I[b].template cast<Real>();
      if (time < B.hold_until) {
        B.velocity.setZero();
        B.omega.setZero();
        continue;
      }
      if (B.track) {  // pass 3 sets each particle's own velocity
        B.velocity.setZero();
        B.omega.setZero();
        continue;
      }
      if (!B.motion.empty()) {
        const double rate = dt > 0 ? (B.prescribed_tilt(time + dt) - B.prescribed_tilt(time)) / dt
                                   : B.prescribed_rate(time);  // the initial state (no step to cover)
        B.omega.setZero();
        if constexpr (dim == 2) B.omega[0] = static_cast<Real>(rate);
        else B.omega[1] = static_cast<Real>(-rate);
        B.velocity = A::spin_cross(B.omega, B.centre - B.pivot);
        continue;
      }
      const DSpin omega = A::solve_spin(I[b], L[b]);
      B.omega = omega.template cast<Real>();
      if (B.hinged) {
        B.velocity = A::spin_cross(B.omega, B.centre - B.pivot);
      } else {
        B.velocity = (momentum[b] / mass[b]).template cast<Real>();
      }
    }
    // Pass 3: impose the rigid motion.
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q) {
      const int b = body_of[p.material[q]];
      if (b < 0) continue;
      const RigidBody<dim>& B = bodies[b];
      if (!B.contact) p.J[q] = std::min(Real(1), p.J[q] * (Real(1) + dt * p.C[q].trace()));
      if (B.track) {  // the step's displacement over dt (at t = 0 with no step yet: over the first millisecond)
        const double span = dt > 0 ? static_cast<double>(dt) : 1e-3;
        p.v[q] = ((B.replayed_position(p.id[q], time + span) - B.replayed_position(p.id[q], time)) /
                  static_cast<Real>(span));
        p.C[q].setZero();
        continue;
      }
      p.v[q] = B.velocity + A::spin_cross(B.omega, p.x[q] - B.centre);
      p.C[q] = A::skew(B.omega);
    }
  }

  // Whether some body is in contact (rigid key `contact`) rather than in the shared field.
  bool any_contact() const {
    return std::any_of(bodies.begin(), bodies.end(), [](const RigidBody<dim>& B) { return B.contact; });
  }

  // After the grid update of the other materials at time `time`: the bodies' frictionless contact with them
  // (sim/rigid_contact.h), from each body's mass, centre, inertia (summed over its particles in the one-process
  // order, in double, as in project()) and motion at the start of the step; sets the field that project() then
  // reads through contact.gather(). `owned`: a distributed run's own grid nodes; `keys` as for project().
  void contact(RigidContact<dim>& contact, const Particles<dim>& p, Grid<dim>& g, const Vec<dim>& gravity, Real dt,
               double time, const std::vector<std::unique_ptr<Boundary<dim>>>& bcs,
               const std::function<bool(size_t)>& owned, const std::vector<uint64_t>* keys = nullptr) {
    using C = RigidContact<dim>;
    const size_t nb = bodies.size();
    const std::vector<Sample> s = samples_in_order(p, keys);
    std::vector<typename C::Input> in;
    in.reserve(s.size());
    for (const Sample& q : s)
      if (bodies[q.body].contact) in.push_back({q.body, q.mass, q.x});
    // A body in the shared field has no contact nodes; a held or driven one moves as given (s = s*).
    const MassProperties mp = mass_properties(s, g.dx * g.dx / 4);
    std::vector<typename C::Body> state(nb);
    for (size_t b = 0; b < nb; ++b) {
      const RigidBody<dim>& B = bodies[b];
      typename C::Body& S = state[b];
      S.mass = mp.mass[b];
      S.centre = mp.centre[b];
      S.origin = mp.origin[b];
      S.inertia = mp.inertia[b];
      S.hinged = B.hinged;
      S.fixed = !B.contact || time < B.hold_until || !B.motion.empty();
    }
    for (size_t b = 0; b < nb; ++b) {
      const RigidBody<dim>& B = bodies[b];
      typename C::Body& S = state[b];
      if (!B.contact || time < B.hold_until) continue;  // s* = 0
      S.s_star.template tail<rot_dofs>() = B.omega.template cast<double>();
      if (!B.motion.empty()) {  // driven: the tilt rate over this step, as project() sets it
        const double rate = (B.prescribed_tilt(time + dt) - B.prescribed_tilt(time)) / dt;
        if constexpr (dim == 2) S.s_star[dim] = rate;
        else S.s_star[dim + 1] = -rate;
      } else if (B.hinged) {  // gravity's torque about the hinge
        const Spin torque = A::cross(S.centre - B.pivot, static_cast<Real>(S.mass) * gravity);
        S.s_star.template tail<rot_dofs>() +=
            static_cast<double>(dt) * A::solve_spin(S.inertia, DSpin(torque.template cast<double>()));
      } else {
        S.s_star.template head<dim>() = (B.velocity + dt * gravity).template cast<double>();
      }
    }
    contact.scatter(in, g);
    contact.solve(state, g, bcs, owned);
  }

  // Moves the rigid particles and the bodies' state rigidly over dt with the velocities set by project(), and
  // sets the particles' velocities to the body's at their new positions; a replayed body's particles go to their
  // recorded positions at time + dt (`time`: the step's start).
  void advance(Particles<dim>& p, Real dt, double time) {
    if (bodies.empty()) return;
    const std::vector<int>& body_of = body_of_;
    std::vector<Mat<dim>> R(bodies.size());
    std::vector<Vec<dim>> origin(bodies.size()), shift(bodies.size());
    for (size_t b = 0; b < bodies.size(); ++b) {
      RigidBody<dim>& B = bodies[b];
      R[b] = A::rotation(B.omega, dt);
      origin[b] = B.hinged ? B.pivot : B.centre;
      shift[b] = B.hinged ? Vec<dim>::Zero() : Vec<dim>(dt * B.velocity);
      B.centre = origin[b] + shift[b] + R[b] * (B.centre - origin[b]);
      B.rotation = R[b] * B.rotation;
      if constexpr (dim == 2) {
        B.angle += static_cast<double>(B.omega[0] * dt);
      } else {
        B.angle = Eigen::AngleAxis<Real>(B.rotation).angle();
        if (B.motion.empty()) {  // driven: omega is the motion's (set again by the next projection)
          const typename A::Spin L = B.inertia * B.omega;
          B.inertia = R[b] * B.inertia * R[b].transpose();
          B.omega = A::solve_spin(B.inertia, L);
        }
      }
      if (B.hinged) B.velocity = A::spin_cross(B.omega, B.centre - B.pivot);
    }
    const size_t n = p.size();
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q) {
      const int b = body_of[p.material[q]];
      if (b < 0) continue;
      const RigidBody<dim>& B = bodies[b];
      if (B.track) {
        p.x[q] = B.replayed_position(p.id[q], time + dt);
        continue;
      }
      p.x[q] = origin[b] + shift[b] + R[b] * (p.x[q] - origin[b]);
      p.v[q] = B.velocity + A::spin_cross(B.omega, p.x[q] - B.centre);
      p.C[q] = A::skew(B.omega);
    }
  }

  // The state as numbers (checkpoints): per body mass, centre, velocity, omega, rotation, angle.
  std::vector<double> save() const {
    std::vector<double> out;
    for (const auto& B : bodies) {
      out.push_back(B.mass);
      for (int a = 0; a < dim; ++a) out.push_back(B.centre[a]);
      for (int a = 0; a < dim; ++a) out.push_back(B.velocity[a]);
      for (int a = 0; a < RigidBody<dim>::rot; ++a) out.push_back(B.omega[a]);
      for (int k = 0; k < dim * dim; ++k) out.push_back(B.rotation(k));
      out.push_back(B.angle);
    }
    return out;
  }
  static constexpr size_t saved_per_body = 1 + 2 * dim + RigidBody<dim>::rot + dim * dim + 1;
  // Returns false if `state` does not hold one record per body.
  bool load(const std::vector<double>& state) {
    if (state.size() != bodies.size() * saved_per_body) return false;
    size_t i = 0;
    for (auto& B : bodies) {
      B.mass = state[i++];
      for (int a = 0; a < dim; ++a) B.centre[a] = static_cast<Real>(state[i++]);
      for (int a = 0; a < dim; ++a) B.velocity[a] = static_cast<Real>(state[i++]);
      for (int a = 0; a < RigidBody<dim>::rot; ++a) B.omega[a] = static_cast<Real>(state[i++]);
      for (int k = 0; k < dim * dim; ++k) B.rotation(k) = static_cast<Real>(state[i++]);
      B.angle = state[i++];
    }
    return true;
  }

 private:
  // One rigid particle's inputs to its body's sums, and its place in the one-process array.
  struct Sample {
    uint64_t key;
    int body;
    Real mass;
    Vec<dim> x, v;
    Mat<dim> C;
  };
  using DVec = Eigen::Matrix<double, dim, 1>;
  using DSpin = Eigen::Matrix<double, rot_dofs, 1>;
  using DInertia = Eigen::Matrix<double, rot_dofs, rot_dofs>;
  // Each body's mass M, centre of mass x_c, origin (x_c, or the pivot of a hinged body) and inertia about the
  // origin with the APIC self-inertia (D = dx^2/4), as in the header. Summed in double in the order of `s`, so that
  // a single-precision build keeps them to its own round-off rather than to that of a float sum over thousands of
  // particles, and project() and contact() get the same bits.
  struct MassProperties {
    std::vector<double> mass;
    std::vector<Vec<dim>> centre, origin;
    std::vector<DInertia> inertia;
  };
  MassProperties mass_properties(const std::vector<Sample>& s, Real D) const {
    const size_t nb = bodies.size();
    MassProperties mp{std::vector<double>(nb, 0.0), std::vector<Vec<dim>>(nb), std::vector<Vec<dim>>(nb),
                      std::vector<DInertia>(nb, DInertia::Zero())};
    std::vector<DVec> first(nb, DVec::Zero());
    for (const Sample& q : s) {
      const double m = q.mass;
      mp.mass[q.body] += m;
      first[q.body] += m * q.x.template cast<double>();
    }
    for (size_t b = 0; b < nb; ++b) {
      mp.centre[b] = (first[b] / mp.mass[b]).template cast<Real>();
      mp.origin[b] = bodies[b].hinged ? bodies[b].pivot : mp.centre[b];
    }
    for (const Sample& q : s)
      mp.inertia[q.body] += A::inertia(q.mass, q.x - mp.origin[q.body], D).template cast<double>();
    return mp;
  }
  // The rigid particles of every body in the order of the one-process array, on every rank. The sums of project()
  // then add them in that order, the bits of one process on any number of ranks (per-rank partial sums added in
  // rank order would differ in the last bits, and between two sorts a rank's particles are not a contiguous range
  // of the one-process array anyway: migrants keep their keys). A distributed run concatenates every rank's
  // samples (global::concatenate) and sorts them by key; the cost is an all-gather of the bodies' particles each
  // step (small: a body is a few thousand particles in the laboratory scenes).
  std::vector<Sample> samples_in_order(const Particles<dim>& p, const std::vector<uint64_t>* keys) const {
    std::vector<Sample> s;
    for (size_t q = 0; q < p.size(); ++q) {
      const int b = body_of_[p.material[q]];
      if (b >= 0) s.push_back({keys ? (*keys)[q] : q, b, p.mass[q], p.x[q], p.v[q], p.C[q]});
    }
    if (keys) {
      global::concatenate(s);
      std::sort(s.begin(), s.end(), [](const Sample& a, const Sample& b) { return a.key < b.key; });
    }
    return s;
  }

  std::vector<int> body_of_;  // per material: index of its body in `bodies`, -1 if not rigid
};

}  // namespace cdmpm
