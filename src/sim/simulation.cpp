// simulation.cpp - building the initial state from a scene, and the MPM step (see simulation.h).
#include "sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/bspline.h"
#include "grid/grid_update.h"
#include "material/constitutive_update.h"
#include "material/stress.h"
#include "sim/shape.h"
#include "transfer/g2p.h"
#include "transfer/p2g.h"

namespace cdmpm {

template <int dim>
Simulation<dim>::Simulation(const Scene& s) : scene(s) {
  for (int a = 0; a < dim; ++a) {
    domain_size[a] = static_cast<Real>(s.domain.size[a]);
    gravity[a] = static_cast<Real>(s.gravity[a]);
  }
  grid = Grid<dim>(domain_size, static_cast<Real>(s.domain.dx));
  for (const MaterialSpec& ms : s.materials) {
    Material m;
    m.name = ms.name;
    m.density = static_cast<Real>(ms.density);
    if (ms.type == "rigid") {
      m.kind = MaterialKind::Rigid;
      m.water = {static_cast<Real>(ms.density), static_cast<Real>(ms.bulk_modulus), static_cast<Real>(ms.gamma), 0};
    } else if (ms.type == "water") {
      m.kind = MaterialKind::Water;
      m.water = {static_cast<Real>(ms.density), static_cast<Real>(ms.bulk_modulus), static_cast<Real>(ms.gamma),
                 static_cast<Real>(ms.viscosity)};
    } else {
      m.kind = MaterialKind::Ice;
      IceModel& ice = m.ice;
      ice.elastic = NeoHookeanSplit::from_young_poisson(static_cast<Real>(ms.youngs_modulus),
                                                        static_cast<Real>(ms.poissons_ratio), dim);
      ice.plasticity = ms.plastic;
      ice.plastic.M = static_cast<Real>(ms.M);
      ice.plastic.beta = static_cast<Real>(ms.beta);
      ice.plastic.xi = static_cast<Real>(ms.xi);
      ice.plastic.hardening = ms.hardening;
      ice.p0_initial = static_cast<Real>(ms.p0);
      ice.alpha_initial = ms.plastic ? ice.plastic.alpha_of_p0(ice.p0_initial, ice.elastic.kappa) : Real(0);
      // Damage is measured against the strength the particle actually starts with.
      if (ms.plastic) ice.p0_initial = ice.p0(ice.alpha_initial);
    }
    materials.push_back(m);
  }
  for (const BoundarySpec& b : s.boundaries) boundaries.push_back(make_boundary<dim>(b, domain_size, grid.dx));
  // Solid bodies first, so that adding their particles is an append (core/particles.h: solids first).
  for (const bool solids : {true, false})
    for (const BodySpec& b : s.bodies)
      if ((materials[b.material_index].kind == MaterialKind::Ice) == solids) seed_body(b);
  rigid.init(s, materials, particles, grid.dx);

  // Explicit viscous diffusion limit dt <= dx^2 rho / (2 dim mu), scaled by wave_cfl.
  viscous_dt_ = std::numeric_limits<Real>::max();
  for (const Material& m : materials)
    if (m.kind == MaterialKind::Water && m.water.mu > 0)
      viscous_dt_ = std::min(viscous_dt_, grid.dx * grid.dx * m.density / (Real(2 * dim) * m.water.mu));
  update_speeds();
  wave_dt_at_start = static_cast<Real>(s.time.wave_cfl) * grid.dx / std::max(max_wave_speed, Real(1e-30));
}

// Fills a body's shape with particles on the lattice (k + 1/2) dx / n, n = ppc^(1/dim) per axis, so bodies
// that share a face tile without gaps or overlaps. With `hydrostatic` (default) bodies start in equilibrium
// under gravity, d being the depth below the body's surface level:
//   water: pre-compressed to p = rho0 |g| d, J = J(p) from the equation of state;
//   ice:   lithostatic uniaxial state sigma_v = -rho0 |g| d, sigma_h = 0 (a laterally free slab on a bed),
//          d measured from the body's own top in each lattice column (unless surface_level is given),
//          F = diag(s_h, s_v) from NeoHookeanSplit::uniaxial_vertical_stretches.
// The particle's current volume is (dx/n)^dim; its reference volume is that over J.
template <int dim>
void Simulation<dim>::seed_body(const BodySpec& body) {
  const int n = static_cast<int>(std::lround(std::pow(body.particles_per_cell, 1.0 / dim)));
  const double h = scene.domain.dx / n;
  const Shape<dim> shape(body.shape);
  std::vector<Shape<dim>> holes;
  for (const auto& h : body.holes) holes.emplace_back(h);
  auto filled = [&](const Eigen::Matrix<double, dim, 1>& x) {
    if (!shape.contains(x)) return false;
    for (const auto& h : holes)
      if (h.contains(x)) return false;
    return true;
  };
  Material& mat = materials[body.material_index];
  mat.half_spacing = std::max(mat.half_spacing, static_cast<Real>(0.5 * h));
  const double vol = std::pow(h, dim);
  const double surface = body.surface_level ? *body.surface_level : shape.upper(vertical_axis<dim>);
  const double g = -gravity[vertical_axis<dim>];
  Vec<dim> v0 = Vec<dim>::Zero();
  for (int a = 0; a < dim && !body.velocity.empty(); ++a) v0[a] = static_cast<Real>(body.velocity[a]);
  Mat<dim> G = Mat<dim>::Zero();
  Vec<dim> centre;
  for (int a = 0; a < dim; ++a) centre[a] = static_cast<Real>(0.5 * (shape.lower(a) + shape.upper(a)));
  if (!body.velocity_gradient.empty())
    for (int r = 0; r < dim; ++r)
      for (int c = 0; c < dim; ++c) G(r, c) = static_cast<Real>(body.velocity_gradient[r * dim + c]);

  IVec<dim> lo, hi;
  for (int a = 0; a < dim; ++a) {
    lo[a] = static_cast<int>(std::floor(shape.lower(a) / h - 0.5));
    hi[a] = static_cast<int>(std::ceil(shape.upper(a) / h - 0.5));
  }
  // A rigid body's shape is turned by its tilt about its hinge (or centre): the lattice points of the untilted
  // shape are seeded, turned. Other bodies leave out the points inside any rigid body (a pool around a block).
  struct Tilted {
    Shape<dim> shape;
    Mat<dim> R;
    Vec<dim> pivot;
  };
  auto tilted = [&](const BodySpec& b) {
    Tilted t{Shape<dim>(b.shape), RigidAlgebra<dim>::tilt(b.tilt), Vec<dim>::Zero()};
    for (int a = 0; a < dim; ++a)
      t.pivot[a] = static_cast<Real>(b.hinge.empty() ? 0.5 * (t.shape.lower(a) + t.shape.upper(a)) : b.hinge[a]);
    return t;
  };
  const bool is_rigid = mat.kind == MaterialKind::Rigid;
  const Tilted self = tilted(body);
  std::vector<Tilted> rigid_shapes;
  if (!is_rigid)
    for (const BodySpec& b : scene.bodies)
      if (materials[b.material_index].kind == MaterialKind::Rigid) rigid_shapes.push_back(tilted(b));
  auto in_rigid = [&](const Eigen::Matrix<double, dim, 1>& x) {
    for (const Tilted& t : rigid_shapes) {
      const Vec<dim> u = t.pivot + t.R.transpose() * (x.template cast<Real>() - t.pivot);
      if (t.shape.contains(u.template cast<double>())) return true;
    }
    return false;
  };
  // Lattice columns along the vertical axis (the last), one at a time, so each column's top is known.
  constexpr int up = vertical_axis<dim>;
  IVec<dim> k = lo;
  std::vector<Eigen::Matrix<double, dim, 1>> column;
  while (true) {
    column.clear();
    for (k[up] = lo[up]; k[up] <= hi[up]; ++k[up]) {
      Eigen::Matrix<double, dim, 1> x;
      for (int a = 0; a < dim; ++a) x[a] = (k[a] + 0.5) * h;
      if (filled(x) && !in_rigid(x)) column.push_back(x);
    }
    // Ice: depth below the body's own top surface in this column (a sloping slab); water: below the level.
    const double top = column.empty() ? 0 : column.back()[up] + 0.5 * h;
    const double level = mat.kind == MaterialKind::Ice && !body.surface_level ? top : surface;
    for (const auto& x : column) {
      Real J = 1;
      Mat<dim> F = Mat<dim>::Identity();
      const Real pressure = static_cast<Real>(mat.density * g * std::max(0.0, level - x[up]));
      if (mat.kind != MaterialKind::Ice && body.hydrostatic && g > 0) {
        J = mat.water.volume_ratio_at_pressure(pressure);
      } else if (mat.kind == MaterialKind::Ice && body.hydrostatic && g > 0) {
        const Vec<dim> st = mat.ice.elastic.template uniaxial_vertical_stretches<dim>(-pressure);
        F = st.asDiagonal();
        J = st.prod();
      }
      // The particle occupies volume h^dim now; its reference (unstressed) volume is h^dim / J.
      const Real V0 = static_cast<Real>(vol) / J;
      Vec<dim> xp = x.template cast<Real>();
      if (is_rigid) xp = self.pivot + self.R * (xp - self.pivot);
      const Vec<dim> vp = v0 + G * (xp - centre);
      if (mat.kind == MaterialKind::Ice)
        particles.add_solid(xp, vp, mat.density * V0, J, static_cast<MaterialId>(body.material_index), G, F,
                            mat.ice.alpha_initial);
      else
        particles.add_fluid(xp, vp, mat.density * V0, J, static_cast<MaterialId>(body.material_index), G);
    }
    int a = up - 1;
    for (; a >= 0; --a) {
      if (++k[a] <= hi[a]) break;
      k[a] = lo[a];
    }
    if (a < 0) break;
  }
}

// The largest particle speed, and the largest wave speed from each material's stiffest particle (stress.h).
template <int dim>
void Simulation<dim>::update_speeds() {
  const size_t n = particles.size(), nm = materials.size();
  Real vmax2 = 0;
  std::vector<Real> stiffest(nm, Real(0));
#pragma omp parallel reduction(max : vmax2)
  {
    std::vector<Real> local(nm, Real(0));
#pragma omp for schedule(static) nowait
    for (size_t q = 0; q < n; ++q) {
      vmax2 = std::max(vmax2, particles.v[q].squaredNorm());
      const MaterialId mi = particles.material[q];
      local[mi] = std::max(local[mi], particle_stiffening(materials[mi], particles, q));
    }
#pragma omp critical(cdmpm_update_speeds)
    for (size_t mi = 0; mi < nm; ++mi) stiffest[mi] = std::max(stiffest[mi], local[mi]);
  }
  max_speed = std::sqrt(vmax2);
  max_wave_speed = 0;
  for (size_t mi = 0; mi < nm; ++mi)
    if (stiffest[mi] > 0) max_wave_speed = std::max(max_wave_speed, wave_speed_at_stiffening<dim>(materials[mi], stiffest[mi]));
}

template <int dim>
Real Simulation<dim>::stable_dt() const {
  const Real dx = grid.dx;
  Real dt = viscous_dt_ * static_cast<Real>(scene.time.wave_cfl);
  if (max_speed > 0) dt = std::min(dt, static_cast<Real>(scene.time.cfl) * dx / max_speed);
  if (max_wave_speed > 0) dt = std::min(dt, static_cast<Real>(scene.time.wave_cfl) * dx / max_wave_speed);
  if (scene.time.max_dt > 0) dt = std::min(dt, static_cast<Real>(scene.time.max_dt));
  return dt;
}

template <int dim>
void Simulation<dim>::step(Real dt) {
  if (steps % reorder_interval == 0) {
    bins_.build(particles, grid);
    particles.permute(std::move(bins_.order));  // the bins are rebuilt next
  }
  bins_.build(particles, grid);
  grid.activate(bins_.blocks);
  p2g(particles, materials, bins_, grid, dt);
  for (const auto& b : boundaries) b->fold_ghosts(grid);
  for (const auto& b : boundaries) b->move_to(time);
  grid_update(grid, gravity, dt, boundaries);
  // Unfold in the reverse order of folding (the adjoint), so a ghost that is folded twice, e.g. at the corner
  // of a wall and an obstacle, reads its mirror after that mirror has itself been unfolded.
  for (auto b = boundaries.rbegin(); b != boundaries.rend(); ++b) (*b)->unfold_ghosts(grid);
  // g2p, then each particle's constitutive update, advection and return inside the walls, done per particle
  // while its state is in cache (the same as three passes over the particles, in one). Rigid particles are
  // left to the rigid bodies: their velocities are projected onto the bodies' motion (which needs every
  // particle of a body) and they are moved rigidly.
  auto keep_inside = [&](size_t q) {
    for (const auto& b : boundaries) b->keep_inside(particles.x[q]);
  };
  auto is_rigid = [&](size_t q) { return materials[particles.material[q]].kind == MaterialKind::Rigid; };
  g2p(particles, grid, bins_, [&](size_t q) {
    if (is_rigid(q)) return;
    constitutive_update(particles, materials, q, dt);
    keep_inside(q);
  });
  if (!rigid.bodies.empty()) {
    rigid.project(particles, time, dt, grid.dx);
    rigid.advance(particles, dt);
    const size_t n = particles.size();
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q)
      if (is_rigid(q)) keep_inside(q);
  }
  remove_sunk_particles();
  update_speeds();
  time += dt;
  ++steps;
}

// Removes the particles inside a sink (scene.h, SinkSpec), keeping the order of the others, so the result
// does not depend on the thread count.
template <int dim>
void Simulation<dim>::remove_sunk_particles() {
  if (scene.sinks.empty()) return;
  const size_t n = particles.size();
  std::vector<uint8_t> sunk(n, 0);
  size_t count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count)
  for (size_t q = 0; q < n; ++q) {
    for (const auto& s : scene.sinks) {
      if (s.material_index >= 0 && particles.material[q] != s.material_index) continue;
      bool in = true;
      for (int a = 0; a < dim && in; ++a) in = particles.x[q][a] >= s.min[a] && particles.x[q][a] <= s.max[a];
      if (in) {
        sunk[q] = 1;
        ++count;
        break;
      }
    }
  }
  if (count == 0) return;
  std::vector<uint32_t> keep;
  keep.reserve(n - count);
  for (size_t q = 0; q < n; ++q)
    if (!sunk[q]) keep.push_back(static_cast<uint32_t>(q));
  particles.permute(std::move(keep));
}

template <int dim>
std::optional<std::string> Simulation<dim>::check_state() const {
  const size_t n = particles.size();
  const Real margin = grid.dx;
  size_t bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (size_t q = 0; q < n; ++q) {
    const auto& x = particles.x[q];
    bool ok = x.allFinite() && particles.v[q].allFinite() && std::isfinite(particles.J[q]) && particles.J[q] > 0;
    for (int a = 0; a < dim && ok; ++a) ok = x[a] >= -margin && x[a] <= domain_size[a] + margin;
    if (!ok) bad = std::min(bad, q);
  }
  if (bad == n) return std::nullopt;
  std::ostringstream os;
  const auto& x = particles.x[bad];
  const auto& v = particles.v[bad];
  const char* why = !x.allFinite() || !v.allFinite() ? "non-finite position or velocity"
                    : !(particles.J[bad] > 0 && std::isfinite(particles.J[bad])) ? "non-positive or non-finite volume ratio J"
                                                                                  : "particle left the domain";
  os << why << ": particle " << bad << " (material '" << materials[particles.material[bad]].name << "') at x = ("
     << x.transpose() << ") m, v = (" << v.transpose() << ") m/s, J = " << particles.J[bad] << ", t = " << time
     << " s, step " << steps;
  return os.str();
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace cdmpm
