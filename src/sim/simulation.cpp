// simulation.cpp - building the initial state from a scene, and the MPM step as its named phases
// (simulation.h, sim/phases.h).
#include "sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

#include "grid/grid_update.h"
#include "material/j_bar.h"
#include "material/constitutive_update.h"
#include "material/stress.h"
#include "parallel/decomposition.h"
#include "parallel/reduction.h"
#include "sim/advect.h"
#include "sim/seeding.h"
#include "sim/sinks.h"
#include "sim/time_step.h"
#include "transfer/g2p.h"
#include "transfer/flip.h"
#include "transfer/p2g.h"

namespace cdmpm {

template <int dim>
Simulation<dim>::Simulation(const Scene& s, bool settle) : scene(s), materials(s.materials) {
  for (int a = 0; a < dim; ++a) {
    domain_size[a] = static_cast<Real>(s.domain.size[a]);
    gravity[a] = static_cast<Real>(s.gravity[a]);
  }
  grid = Grid<dim>(domain_size, static_cast<Real>(s.domain.dx));
  for (const BoundarySpec& b : s.boundaries)
    boundaries.push_back(make_boundary<dim>(s, b, BoundaryContext<dim>{domain_size, grid.dx, &boundaries}));
  sinks = s.sinks;
  for (const auto& b : boundaries)
    for (const SinkSpec& k : b->sinks()) sinks.push_back(k);
#ifdef CDMPM_MPI
  if (mpi::active()) seed_distributed();
  else
#endif
    seed_bodies<dim>(s, materials, boundaries, particles, &bed_);
  if (!bed_.empty()) bed_.bins.build(bed_.particles, grid);  // fixed particles: binned once
#ifdef CDMPM_MPI
  if (domain_) domain_->adopt_seeded(particles, grid, &bed_);
  if (domain_)
    for (const BodySpec& b : s.bodies)
      if (b.track)
        throw SceneError(s.path + ": bodies: a replayed source (rigid key \"track\") runs in one process only (its "
                         "particles' seeded positions are kept by the process that seeded them); run without mpirun");
  rigid.init(s, materials, particles, grid.dx, domain_ ? &domain_->keys() : nullptr);
#else
  rigid.init(s, materials, particles, grid.dx);
#endif
  crack_starts.configure(materials, static_cast<Real>(s.output.damage_threshold), grid.dx);
  material_dt_ = material_time_step_limit(materials, grid.dx, dim);
  for (const Material& m : materials) {
    any_flip_ |= m.flip() > 0, any_j_bar_ |= m.j_bar();
    xpic_order_ = std::max(xpic_order_, m.xpic());
  }
  for (const Material& m : materials) {
    rigid_material_.push_back(m.traits().rigid);
    contact_material_.push_back(m.contact() && m.traits().rigid);
    interpolated_divergence_.push_back(m.interpolated_divergence());
  }
  solid_field_.configure(materials, grid);
  multi_rate_ = s.time.multi_rate && solid_field_.any();
#ifdef CDMPM_MPI
  // (A rigid body in contact beside it is refused by the scene loader.)
  if (domain_ && solid_field_.any())
    for (const Material& m : materials)
      if (m.contact() && !m.traits().rigid)
        throw SceneError(s.path + ": materials." + m.name + ".contact: a deformable body in a field of its own runs in "
                         "one process only (the distributed halo exchange carries one field); remove \"contact\" or run "
                         "without mpirun");
#endif
  update_speeds();
  wave_dt_at_start = static_cast<Real>(s.time.wave_cfl) * grid.dx / std::max(max_wave_speed, Real(1e-30));
  if (settle && s.time.settle > 0) settle_elastically(s.time.settle, static_cast<Real>(s.time.settle_damping));
}

// Dynamic relaxation before t = 0 (see simulation.h): elastic solids, damped velocities, then the clock restarts.
template <int dim>
void Simulation<dim>::settle_elastically(double duration, Real damping) {
  const std::vector<Material> as_given = materials;
  for (Material& m : materials)
    if (auto* ice = std::get_if<Ice>(&m.model)) ice->plasticity = false;
  while (time_ < duration) {
    const double dt = std::min(static_cast<double>(stable_dt()), duration - time_);
    if (dt < duration - time_) step(static_cast<Real>(dt));
    else step_until(duration);
    const Real f = std::exp(-damping * static_cast<Real>(dt));
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < particles.size(); ++q) {
      particles.v[q] *= f;
      particles.C[q] *= f;
    }
    update_speeds();
  }
  materials = as_given;
  time_ = 0;
  steps_ = 0;
  update_speeds();
}

template <int dim>
void Simulation<dim>::restore(double t, long long step_count, Real wave_dt_reference, std::vector<uint64_t>* keys) {
  time_ = t;
  steps_ = step_count;
  wave_dt_at_start = wave_dt_reference;
#ifdef CDMPM_MPI
  // The loaded particles are this rank's share of the checkpoint (`keys`: their order keys): partitioned again for
  // the counts over all ranks, each particle moved to its owner.
  if (domain_) domain_->adopt_loaded(particles, std::move(*keys), grid, &bed_);
#else
  (void)keys;
#endif
  update_speeds();
}

#ifdef CDMPM_MPI
// The scene seeded without any rank holding all of it: a first pass counts the particles of every block (keeping
// none), the blocks are partitioned for those counts with the blocks of the boundaries' mirror pairs kept on one
// rank (parallel/partition.h), and a second pass keeps this rank's particles (sim/seeding.h). The bed layer of
// the well-balanced beds is seeded whole on every rank (bed_; this rank's part: parallel/bed_part.h).
template <int dim>
void Simulation<dim>::seed_distributed() {
  domain_ = std::make_unique<Domain<dim>>(grid, domain_size, joined_blocks(boundaries, grid));
  domain_->partition_seeded(seeded_per_block(scene, materials, boundaries, grid), grid);
  const int me = mpi::rank();
  seed_bodies<dim>(scene, materials, boundaries, particles, &bed_,
                   [&](uint64_t, const Vec<dim>& x) { return domain_->owner_at(x, grid) == me; });
}
#endif

template <int dim>
void Simulation<dim>::with_whole_state(const std::function<void()>& f) {
#ifdef CDMPM_MPI
  if (domain_) {
    Particles<dim> whole = domain_->gather(particles);
    if (mpi::rank() != 0) return;
    std::swap(particles, whole);
    const mpi::LocalScope local;
    try {
      f();
    } catch (...) {
      std::swap(particles, whole);
      throw;
    }
    std::swap(particles, whole);
    return;
  }
#endif
  f();
}

template <int dim>
void Simulation<dim>::on_root(const std::function<void()>& f) {
#ifdef CDMPM_MPI
  if (domain_) {
    if (mpi::rank() != 0) return;
    const mpi::LocalScope local;
    return f();
  }
#endif
  f();
}

template <int dim>
Real Simulation<dim>::stable_dt() const {
  return stable_time_step(scene.time, grid.dx, max_speed, max_wave_speed, material_dt_);
}

template <int dim>
void Simulation<dim>::step(Real dt) {
  advance(dt, time_ + dt);
  time_ += dt;
}

template <int dim>
void Simulation<dim>::step_until(double t) {
  advance(static_cast<Real>(t - time_), t);
  time_ = t;
}

// One step: the phases of sim/phases.h in order.
template <int dim>
void Simulation<dim>::advance(Real dt, double t_end) {
  if (multi_rate_) return advance_multi_rate(dt, t_end);
  timer_.run(Phase::Bin, [&] { bin(); });
  if (any_flip_) timer_.run(Phase::FlipTransfer, [&] { flip_transfer(); });
  timer_.run(Phase::P2G, [&] { p2g_phase(dt, true); });
  timer_.run(Phase::BoundaryFold, [&] { boundary_fold(); });
  timer_.run(Phase::GridUpdate, [&] { grid_update_phase(dt, true); });
  timer_.run(Phase::BoundaryUnfold, [&] { boundary_unfold(); });
  timer_.run(Phase::G2P, [&] {
    g2p(particles, grid, bins_, interpolated_divergence_);
    if (solid_field_.any()) solid_field_.gather(particles, bins_);
    if (any_flip_) flip_blend(particles, materials, flip_u_);
  });
  timer_.run(Phase::ConstitutiveUpdate, [&] {
    crack_starts.before_update(particles);
    constitutive_update(particles, materials, dt);
    crack_starts.after_update(particles, materials, steps_ + 1, t_end);
  });
  timer_.run(Phase::RigidProjection, [&] { rigid_projection(dt); });
  timer_.run(Phase::Advect, [&] { advect_phase(dt); });
  timer_.run(Phase::Sinks, [&] { sinks_phase(); });
  timer_.run(Phase::Reductions, [&] { update_speeds(); });
  ++steps_;
}

// One step with the solids' own field sub-stepped (time.multi_rate; sim/field_contact.h, subcycle): the phases of
// advance() for the shared field and its particles, with the solids' field's n steps of dt / n between the shared
// grid update and g2p. n is dt over the solids' own stable step (their wave speed; dt is the others'), rounded up.
// The solids' particles are extracted for the sub-steps and their state is written back after the step's
// advection (the shared field's g2p, constitutive update and advection pass over them and are overwritten), before
// the crack-start record compares the damage with the step's start.
template <int dim>
void Simulation<dim>::advance_multi_rate(Real dt, double t_end) {
  const Real solid_dt = stable_time_step(scene.time, grid.dx, max_speed, solid_wave_speed_, material_dt_);
  const int n = std::max(1, static_cast<int>(std::ceil(dt / solid_dt * (1 - 1e-9))));
  timer_.run(Phase::Bin, [&] { bin(); });
  if (any_flip_) timer_.run(Phase::FlipTransfer, [&] { flip_transfer(); });
  Particles<dim> solids;
  timer_.run(Phase::P2G, [&] {
    field_index_.clear();
    const auto& in_field = solid_field_.in_field();
    for (size_t q = 0; q < particles.solid_count(); ++q)
      if (in_field[particles.material[q]]) field_index_.push_back(static_cast<uint32_t>(q));
    solids = particles.extract(field_index_);
    transfer_velocity();  // v0: the shared field's velocity at the start of the step
    v0_.assign(grid.momentum.begin(), grid.momentum.end());
    grid.clear();
    p2g_phase(dt, false);
  });
  timer_.run(Phase::BoundaryFold, [&] { boundary_fold(false); });
  timer_.run(Phase::GridUpdate, [&] { grid_update_phase(dt, false); });
  timer_.run(Phase::BoundaryUnfold, [&] { boundary_unfold(false); });
  crack_starts.before_update(particles);
  timer_.run(Phase::GridUpdate, [&] {
    solid_field_.subcycle(solids, grid, v0_, n, dt, gravity, materials, rigid_material_, boundaries);
  });
  timer_.run(Phase::G2P, [&] {
    g2p(particles, grid, bins_, interpolated_divergence_);
    if (any_flip_) flip_blend(particles, materials, flip_u_);
  });
  timer_.run(Phase::ConstitutiveUpdate, [&] { constitutive_update(particles, materials, dt); });
  timer_.run(Phase::RigidProjection, [&] { rigid_projection(dt); });
  timer_.run(Phase::Advect, [&] {
    advect_phase(dt);
    particles.write_back(field_index_, solids);
  });
  crack_starts.after_update(particles, materials, steps_ + 1, t_end);
  timer_.run(Phase::Sinks, [&] { sinks_phase(); });
  timer_.run(Phase::Reductions, [&] { update_speeds(); });
  ++steps_;
}

// The step's p2g: each particle's mass, momentum and stress impulse to the shared field (scatter below), a J-bar
// material's stress taken at its cell's mean J (material/j_bar.h) with the particles' own J kept, and the solids'
// own field filled with its particles when it steps with the others (solid_field; multi-rate fills it per sub-step).
template <int dim>
void Simulation<dim>::p2g_phase(Real dt, bool solid_field) {
  if (any_j_bar_) {
    cell_mean_J(particles, materials, grid, bins_, J_state_);
    std::swap(particles.J, J_state_);
  }
  scatter(dt);
  if (solid_field && solid_field_.any()) solid_field_.scatter(particles, materials, bins_, dt);
  if (any_j_bar_) std::swap(particles.J, J_state_);
}

// Mass, momentum and the stress impulse to the grid (transfer/p2g.h), the bed layer's too.
template <int dim>
void Simulation<dim>::scatter(Real dt) {
#ifdef CDMPM_MPI
  if (domain_) return domain_->p2g(particles, materials, bins_, grid, dt);  // the bed layer's too, as below
#endif
  if (!bed_.empty()) {  // the water's velocity along the bed, for the bed layer (sim/bed_layer.h)
    p2g(particles, materials, bins_, grid, Real(0));
    bed_.take_velocity(grid);
    grid.clear();
  }
  p2g(particles, materials, bins_, grid, dt);
  if (!bed_.empty()) p2g(bed_.particles, materials, bed_.bins, grid, dt);
}

// The grid velocity of the transfer alone, v_i^n (p2g without forces, folded and unfolded as the step's), and
// each FLIP particle's velocity that it does not hold, u_p, filtered by XPIC where a material asks for it
// (transfer/flip.h); the grid is then cleared for p2g.
template <int dim>
void Simulation<dim>::flip_transfer() {
  transfer_velocity();
  flip_residual(particles, materials, grid, bins_, flip_u_);
  if (xpic_order_ > 0) {
    xpic_filter(particles, materials, grid, bins_, xpic_order_, [&] {
      grid.clear();
      transfer_velocity();
    }, xpic_, flip_u_);
  }
  grid.clear();
}

// The particles' velocities to the grid without force: p2g with dt = 0, the boundaries' fold, v = mv / m (no
// boundary condition), their unfold.
template <int dim>
void Simulation<dim>::transfer_velocity() {
  scatter(Real(0));
  boundary_fold(false);
  grid_update<dim>(grid, Vec<dim>::Zero(), Real(0), {});
  boundary_unfold(false);
}

// Every reorder_interval steps the particle arrays are reordered by block (memory locality); then the bins of
// the current order, and the grid blocks they touch.
template <int dim>
void Simulation<dim>::bin() {
#ifdef CDMPM_MPI
  if (domain_) {  // the grid is activated in p2g, after the halo exchange (parallel/halo_exchange.h)
    if (steps_ % reorder_interval == 0) domain_->sort(particles, grid, bins_);
    else bins_.build(particles, grid);
    return;
  }
#endif
  if (steps_ % reorder_interval == 0) {
    bins_.build(particles, grid);
    particles.permute(std::move(bins_.order));  // the bins are rebuilt next
  }
  bins_.build(particles, grid);
  const std::vector<uint32_t>* blocks = &bins_.blocks;
  if (!bed_.empty()) {  // the well-balanced bed: the blocks of the particles and of the bed layer
    blocks_.clear();
    std::set_union(bins_.blocks.begin(), bins_.blocks.end(), bed_.bins.blocks.begin(), bed_.bins.blocks.end(),
                   std::back_inserter(blocks_));
    blocks = &blocks_;
  }
  grid.activate(*blocks);
  // The solids' own field in the same slots as the shared field; under multi-rate each sub-step activates its own.
  if (solid_field_.any() && !multi_rate_) solid_field_.activate(*blocks);
}

// The solids' own field (sim/field_contact.h) is folded and unfolded with the shared one, except for the FLIP
// transfer, which does not fill it.
template <int dim>
void Simulation<dim>::boundary_fold(bool solid_field) {
  for (const auto& b : boundaries) b->fold_ghosts(grid);
  if (solid_field && solid_field_.any())
    for (const auto& b : boundaries) b->fold_ghosts(solid_field_.field);
}

// Moving obstacles take their position at the start of the step, then the grid velocities are updated: the shared
// field's, the solids' own field's with its contact when it steps with the others (solid_field), and the rigid
// bodies' contact.
template <int dim>
void Simulation<dim>::grid_update_phase(Real dt, bool solid_field) {
  for (const auto& b : boundaries) {
    b->move_to(time_);
    b->prepare(*this, dt);
  }
  grid_update(grid, gravity, dt, boundaries);
  if (solid_field && solid_field_.any()) solid_field_.update(grid, gravity, dt, boundaries);
  if (!rigid.any_contact()) return;
  // The rigid bodies' contact with the other materials (sim/rigid_contact.h); a distributed run sums its own nodes.
  std::function<bool(size_t)> owned = [](size_t) { return true; };
  const std::vector<uint64_t>* keys = nullptr;
#ifdef CDMPM_MPI
  if (domain_) {
    keys = &domain_->keys();
    owned = [this](size_t k) { return domain_->partition().owner(grid.block_index(grid.block_of(grid.node(k)))) == mpi::rank(); };
  }
#endif
  rigid.contact(contact_, particles, grid, gravity, dt, time_, boundaries, owned, keys);
}

// Unfold in the reverse order of folding (the adjoint), so a ghost that is folded twice, e.g. at the corner
// of a wall and an obstacle, reads its mirror after that mirror has itself been unfolded.
template <int dim>
void Simulation<dim>::boundary_unfold(bool solid_field) {
  for (auto b = boundaries.rbegin(); b != boundaries.rend(); ++b) (*b)->unfold_ghosts(grid);
  if (solid_field && solid_field_.any())
    for (auto b = boundaries.rbegin(); b != boundaries.rend(); ++b) (*b)->unfold_ghosts(solid_field_.field);
#ifdef CDMPM_MPI
  if (domain_) domain_->halo.share_velocities(grid);
#endif
}

// The particles of bodies in contact read their bodies' field (sim/rigid_contact.h; g2p gave them the other
// materials'), then every rigid particle takes its body's rigid motion.
template <int dim>
void Simulation<dim>::rigid_projection(Real dt) {
  if (rigid.any_contact()) contact_.gather(particles, grid, contact_material_);
#ifdef CDMPM_MPI
  if (domain_) return rigid.project(particles, time_, dt, grid.dx, &domain_->keys());
#endif
  rigid.project(particles, time_, dt, grid.dx);
}

// Particles inside a sink are removed; a distributed run then sends particles to the ranks that own their blocks.
template <int dim>
void Simulation<dim>::sinks_phase() {
#ifdef CDMPM_MPI
  if (domain_) {
    std::vector<uint32_t> kept;
    if (remove_sunk_particles(particles, sinks, &kept)) domain_->removed(kept);
    return domain_->migrate_particles(particles, grid);
  }
#endif
  remove_sunk_particles(particles, sinks);
}

// Free particles move with their velocity, rigid ones with their body; all are then kept inside the walls.
template <int dim>
void Simulation<dim>::advect_phase(Real dt) {
  advect(particles, rigid_material_, dt);
  rigid.advance(particles, dt, time_);
  keep_inside(particles, boundaries);
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
  global::max(stiffest);
  max_speed = std::sqrt(static_cast<Real>(global::max(vmax2)));
  max_wave_speed = 0;
  solid_wave_speed_ = 0;
  for (size_t mi = 0; mi < nm; ++mi) {
    if (!(stiffest[mi] > 0)) continue;
    Real& c = multi_rate_ && solid_field_.in_field()[mi] ? solid_wave_speed_ : max_wave_speed;
    c = std::max(c, wave_speed_at_stiffening<dim>(materials[mi], stiffest[mi]));
  }
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
  // A distributed run combines the failure flag (global::max) and reports the first failing particle's rank.
  if (global::max(bad < n ? 1.0 : 0.0) == 0.0) return std::nullopt;
  if (bad == n) return std::string("a particle on another rank went bad (that rank reports which)");
  std::ostringstream os;
  const auto& x = particles.x[bad];
  const auto& v = particles.v[bad];
  const char* why = !x.allFinite() || !v.allFinite() ? "non-finite position or velocity"
                    : !(particles.J[bad] > 0 && std::isfinite(particles.J[bad])) ? "non-positive or non-finite volume ratio J"
                                                                                  : "particle left the domain";
  os << why << ": particle " << bad << " (id " << particles.id[bad] << ", material '" << materials[particles.material[bad]].name
     << "') at x = (" << x.transpose() << ") m, v = (" << v.transpose() << ") m/s, J = " << particles.J[bad]
     << ", t = " << time_ << " s, step " << steps_;
  return os.str();
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace cdmpm
