// test_reference_step.cpp - the optimised engine step (Simulation<dim>::step: sparse blocked grid, coloured
// block scatter, dense patches, particle reordering) against the slow dense textbook step of
// tests/common/reference_step.h, on water and ice blobs in 2D and 3D.
//
// Each scene is a blob well inside the domain (at least 0.25 of the domain from every wall, many cells more
// than the 1.5 dx stencil reach and the few dx it moves), so the walls' mirror folding never has mass to
// fold and the two steps must compute the same thing. The initial state is not trivial: a uniform velocity
// plus a velocity gradient G (v = v0 + G (x - c), C = G), the hydrostatic (water) or lithostatic (ice)
// pre-stress, gravity, viscosity for water and Cam-Clay plasticity with a strength low enough that part of
// the ice yields (checked: the return mapping's plastic branch is exercised) while part stays elastic.
//
// Matching particles: the engine reorders its particles (by block, every Simulation::reorder_interval steps),
// so each particle is given a distinct mass (m_p (1 + 1e-3 q / n)); a step never changes a mass, and a
// permutation moves it bitwise, so the mass identifies the particle in both runs.
//
// Each step is compared from identical inputs: before every engine step the reference copies the engine's
// particles and makes the same step (so the comparison is of the two step maps; through the dynamics round-off
// would grow, and the strain softening of the ice amplifies it by up to ~ 3 kappa cosh(xi alpha) / mu per
// yielding step, since p0(alpha) falls as alpha grows, material/cohesive_cam_clay.h).
//
// Tolerance: both steps evaluate the same sums in different orders (per block and colour, per axis
// partial sums in the patches, 4-wide records), so they differ by round-off only. Each grid or particle
// value is a sum of at most 3^dim x (particles per cell) x 3^dim terms (<= 8 x 729 in 3D), each bounded by
// the field's scale S (below), so reordering changes it by at most about (terms) eps S in the worst case and
// by sqrt(terms) eps S ~ 1e-14 S typically; the constitutive update and return mapping are Lipschitz with a
// constant of order 1 in their inputs. The bound 4096 eps S (9e-13 S in double) leaves that margin, while any
// wrong factor in a formula changes the result by far more than 1e-12 of its scale.
// The scales S: positions, max |x_p|; velocities, max |v_p| plus the largest stress impulse per unit mass
// 4 dt |tau_p| / (rho0 dx) (the p2g term m_p v_p and the force term dt V0 D^-1 tau_p (x_i - x_p) enter the
// same sum) plus |g| dt; C (a difference quotient of v over dx), D^-1 dx = 4 / dx times the velocity scale;
// J and F (dimensionless stretches), 1; alpha, max(|alpha_p|, 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "reference_step.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

using reference::DenseStep;
using reference::RefMaterial;

constexpr double kRel = 4096 * std::numeric_limits<Real>::epsilon();

nlohmann::json base_scene(int dim, double dx) {
  std::vector<double> size(dim, 1.0);
  return {{"dim", dim},
          {"domain", {{"size", size}, {"dx", dx}}},
          {"time", {{"end", 1.0}, {"frame_interval", 1.0}}},
          {"boundaries", {{{"type", "walls"}, {"condition", "slip"}}}},
          {"output", {{"frames", false}}}};
}

// A row-major dim x dim matrix as the scene's array of rows.
nlohmann::json rows(const std::vector<double>& m, int dim) {
  nlohmann::json r = nlohmann::json::array();
  for (int i = 0; i < dim; ++i) r.push_back(std::vector<double>(m.begin() + i * dim, m.begin() + (i + 1) * dim));
  return r;
}

// Water (Tait, K = 1e5 Pa, viscosity 10 Pa s): a ball of radius 0.22 centred at 0.5, compressing (tr G < 0),
// shearing and spinning, moving at v0.
nlohmann::json water_scene(int dim, double dx) {
  nlohmann::json j = base_scene(dim, dx);
  j["materials"] = {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e5}, {"viscosity", 10}}}};
  const std::vector<double> centre(dim, 0.5), v0 = dim == 2 ? std::vector<double>{0.3, -0.2}
                                                           : std::vector<double>{0.3, -0.1, -0.2};
  const std::vector<double> G = dim == 2 ? std::vector<double>{-0.4, 0.5, -0.3, -0.2}
                                         : std::vector<double>{-0.4, 0.5, 0.1, -0.3, -0.2, 0.2, 0.3, -0.1, -0.1};
  j["bodies"] = {{{"material", "water"}, {"particles_per_cell", dim == 2 ? 4 : 8},
                  {"shape", {{"type", "ball"}, {"center", centre}, {"radius", 0.22}}},
                  {"velocity", v0}, {"velocity_gradient", rows(G, dim)}}};
  return j;
}

// Ice (E = 1e5 Pa, nu = 0.3; Cam-Clay M = 1.85, beta = 0.3, xi = 3, p0 = 1500 Pa): a slab 0.4 wide and
// 0.25 high under its lithostatic stress (up to rho g h = 2.2 kPa), sheared and stretched: part of it yields.
nlohmann::json ice_scene(int dim, double dx) {
  nlohmann::json j = base_scene(dim, dx);
  j["materials"] = {{"ice", {{"type", "ice"}, {"density", 900}, {"youngs_modulus", 1e5}, {"poissons_ratio", 0.3},
                             {"M", 1.85}, {"beta", 0.3}, {"xi", 3}, {"p0", 1500}}}};
  std::vector<double> lo(dim, 0.3), hi(dim, 0.7);
  lo[dim - 1] = 0.375, hi[dim - 1] = 0.625;
  const std::vector<double> v0 = dim == 2 ? std::vector<double>{0.2, 0.1} : std::vector<double>{0.2, -0.1, 0.1};
  const std::vector<double> G = dim == 2 ? std::vector<double>{0.3, 2.0, -0.5, -0.2}
                                         : std::vector<double>{0.3, 0.2, 0.5, -0.2, 0.1, 0.1, -0.1, 0.1, -0.2};
  j["bodies"] = {{{"material", "ice"}, {"particles_per_cell", dim == 2 ? 4 : 8},
                  {"shape", {{"type", "box"}, {"min", lo}, {"max", hi}}}, {"velocity", v0},
                  {"velocity_gradient", rows(G, dim)}}};
  return j;
}

// The reference's material table, from the constants the scene's models were read with (the models' own
// constructors and functions; the reference step is about the transfers and the step's order, not the parsing).
template <int dim>
std::vector<RefMaterial> reference_materials(const Scene& s) {
  std::vector<RefMaterial> out;
  for (const Material& mat : s.materials) {
    RefMaterial m;
    m.rho0 = mat.density();
    if (const Water* w = std::get_if<Water>(&mat.model)) m.water = w->eos;
    if (const Ice* ice = std::get_if<Ice>(&mat.model)) {
      m.ice = true;
      m.elastic = ice->elastic;
      m.plane_strain = ice->plane_strain;
      m.plastic = ice->plastic;
      m.plasticity = ice->plasticity;
    }
    out.push_back(m);
  }
  return out;
}

template <int dim>
Real largest_stress_impulse(const Particles<dim>& p, const std::vector<RefMaterial>& mats, Real dt, Real dx) {
  Real s = 0;
  for (size_t q = 0; q < p.size(); ++q) {
    const RefMaterial& m = mats[p.material[q]];
    const Mat<dim> tau = m.ice ? m.elastic.kirchhoff<dim>(p.F[q]) : m.water.kirchhoff<dim>(p.J[q], p.C[q]);
    s = std::max(s, 4 * dt * tau.norm() / (m.rho0 * dx));
  }
  return s;
}

template <int dim>
Real max_norm(const std::vector<Vec<dim>>& a) {
  Real s = 0;
  for (const auto& v : a) s = std::max(s, v.norm());
  return s;
}

// Compares the engine's particles p after a step with the reference's ref, both from the same state; the
// particles are matched by mass. Adds to `plastic` the masses of the ice particles whose alpha the step changed
// (alpha0: the reference's alpha before the step).
template <int dim>
void expect_same_state(const Particles<dim>& p, const Particles<dim>& ref, const std::vector<Real>& alpha0,
                       Real impulse, Real dx, int step, std::set<Real>& plastic) {
  const size_t n = ref.size();
  ASSERT_EQ(p.size(), n);
  std::map<Real, size_t> by_mass;
  for (size_t q = 0; q < n; ++q) by_mass[p.mass[q]] = q;
  ASSERT_EQ(by_mass.size(), n) << "particle masses must be distinct to match the particles";
  const Real sx = max_norm<dim>(ref.x), sv = max_norm<dim>(ref.v) + impulse, sC = 4 / dx * sv;
  Real sa = 1;
  for (const Real a : ref.alpha) sa = std::max(sa, std::abs(a));
  // Largest difference of each field over the particles, and where (one message per field and step).
  struct Worst {
    const char* field;
    Real scale, diff = 0;
    size_t particle = 0;
  };
  Worst worst[] = {{"x", sx}, {"v", sv}, {"C", sC}, {"J", 1}, {"F", 1}, {"alpha", sa}};
  auto note = [&](int f, Real d, size_t q) {
    if (!(d <= worst[f].diff)) worst[f].diff = d, worst[f].particle = q;  // NaN counts as the worst
  };
  for (size_t q = 0; q < n; ++q) {
    const auto it = by_mass.find(ref.mass[q]);
    ASSERT_NE(it, by_mass.end()) << "reference particle " << q << " has no engine particle of its mass";
    const size_t e = it->second;
    ASSERT_EQ(p.material[e], ref.material[q]);
    note(0, (p.x[e] - ref.x[q]).norm(), q);
    note(1, (p.v[e] - ref.v[q]).norm(), q);
    note(2, (p.C[e] - ref.C[q]).norm(), q);
    note(3, std::abs(p.J[e] - ref.J[q]), q);
    if (q < ref.solid_count()) {
      ASSERT_LT(e, p.solid_count());
      note(4, (p.F[e] - ref.F[q]).norm(), q);
      note(5, std::abs(p.alpha[e] - ref.alpha[q]), q);
      if (ref.alpha[q] != alpha0[q]) plastic.insert(ref.mass[q]);
    }
  }
  for (const Worst& w : worst)
    EXPECT_LE(w.diff, kRel * w.scale) << "step " << step << ": |" << w.field << " - reference| of particle "
                                      << w.particle << " is " << w.diff / w.scale << " of the field's scale "
                                      << w.scale;
}

// Runs `steps` engine steps; before each, the reference takes the engine's state and makes the same step
// (see the header).
template <int dim>
void compare_with_reference(const nlohmann::json& j, int steps, bool ice) {
  const Scene scene = scene_from_json(j, "reference.json");
  Simulation<dim> sim(scene);
  Particles<dim>& p = sim.particles;
  const size_t n = p.size();
  ASSERT_GT(n, 100u);
  for (size_t q = 0; q < n; ++q) p.mass[q] *= Real(1) + Real(1e-3) * static_cast<Real>(q) / static_cast<Real>(n);
  const std::vector<RefMaterial> mats = reference_materials<dim>(scene);
  Vec<dim> size, g;
  for (int a = 0; a < dim; ++a) size[a] = static_cast<Real>(scene.domain.size[a]), g[a] = static_cast<Real>(scene.gravity[a]);
  const Real dx = static_cast<Real>(scene.domain.dx);
  const DenseStep<dim> dense(size, dx, g, mats, true);
  std::set<Real> plastic;
  for (int s = 0; s < steps; ++s) {
    Particles<dim> ref = p;
    const std::vector<Real> alpha0 = ref.alpha;
    const Real dt = sim.stable_dt();
    const Real impulse = largest_stress_impulse(ref, mats, dt, dx) + g.norm() * dt;
    sim.step(dt);
    dense.step(ref, dt);
    expect_same_state(p, ref, alpha0, impulse, dx, s, plastic);
    if (::testing::Test::HasFatalFailure()) return;
  }
  if (ice) {  // both branches of the return mapping were taken
    const size_t yielded = plastic.size();
    EXPECT_GT(yielded, 0u) << "no ice particle yielded: the scene does not test the plastic update";
    EXPECT_LT(yielded, n) << "every ice particle yielded: the scene does not test the elastic update";
  }
}

// Ten steps: the engine reorders its particles at steps 0 and 8, both inside the run.
TEST(ReferenceStep, Water2D) { compare_with_reference<2>(water_scene(2, 1.0 / 32), 10, false); }
TEST(ReferenceStep, Water3D) { compare_with_reference<3>(water_scene(3, 1.0 / 16), 10, false); }
TEST(ReferenceStep, Ice2D) { compare_with_reference<2>(ice_scene(2, 1.0 / 32), 10, true); }
TEST(ReferenceStep, Ice3D) { compare_with_reference<3>(ice_scene(3, 1.0 / 16), 10, true); }

}  // namespace
}  // namespace cdmpm
