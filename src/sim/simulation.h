// simulation.h - one MPM simulation: particles, grid, materials, boundaries, rigid bodies, the clock, and the
// explicit step (symplectic Euler, Jiang et al. 2016 course notes, sec. 9).
//
// One step runs the named phases of sim/phases.h in order, data flowing one way:
//   particles --bin, p2g--> grid --boundary_fold, grid_update, boundary_unfold--> grid --g2p--> particles
//   --constitutive_update, rigid_projection, advect, sinks--> particles --reductions--> next time step
// Each phase is a function in the file of its concept; the step below only sequences them and times each.
// Ice with `contact` goes through the same phases in a grid field of its own (sim/field_contact.h: scattered after
// the shared field, folded, updated and unfolded with it, in contact with it after both grid updates, read back
// after the shared g2p); rigid bodies with `contact` have their bodies' field (sim/rigid_contact.h).
// The time step is dt = min(cfl dx / max|v_p|, wave_cfl dx / c_max, wave_cfl * the materials' own limits
// (viscosity), max_dt), where c_max is the largest wave speed of any material present (sim/time_step.h); with
// time.multi_rate, of any material outside the solids' own field, which sub-steps at its own (advance_multi_rate).
// The simulation owns its clock: step(dt) advances it by dt, step_until(t) lands it exactly on t (an output
// time).
// Settling (scene time.settle > 0): before t = 0 the scene is stepped for time.settle seconds
// with every solid elastic (no return mapping, so no damage) and, after each step, every particle's velocity and
// APIC matrix scaled by exp(-zeta dt), zeta = time.settle_damping: dynamic relaxation (Underwood 1983) to the
// elastic equilibrium of the seeded bodies under gravity and the water's pressure, e.g. a glacier's cliff face,
// which no seeded stress state balances exactly. The clock and the step count then restart at 0 with the
// materials as given, so damage can only come from the loads of the settled state.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "boundary/boundary.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/material.h"
#include "probe/crack_starts.h"
#include "scene/scene.h"
#include "sim/bed_layer.h"
#include "sim/field_contact.h"
#include "sim/phases.h"
#include "sim/rigid_bodies.h"
#include "transfer/flip.h"
#ifdef CDMPM_MPI
#include "parallel/domain.h"
#endif

namespace cdmpm {

template <int dim>
class Simulation {
 public:
  // Seeds the scene; settles it (see above) unless `settle` is false. A resumed run settles too, before its
  // checkpoint replaces the particles, so that the initial energies of its summary are those of the settled state.
  explicit Simulation(const Scene& scene, bool settle = true);

  // Largest stable time step for the current state (before clamping to output times).
  Real stable_dt() const;
  // Advances the state by dt.
  void step(Real dt);
  // Advances the state by one step that ends exactly at time t (t > time).
  void step_until(double t);
  // Advances the state to exactly time t with stable steps, the last one shortened to land on t (a remainder
  // within 1e-9 of a step is merged into it). Tests and tools that need no output between steps use it.
  void run_until(double t) {
    while (time_ < t) {
      const Real dt = stable_dt();
      if (time_ + double(dt) * (1 + 1e-9) >= t) step_until(t);
      else step(dt);
    }
  }
  // Checks the state after a step; returns a message saying where and why if it is unstable.
  std::optional<std::string> check_state() const;
  // Sets the clock and the time-step reference of a run resumed from a checkpoint (whose particles were loaded
  // into `particles`: all of them, or in a distributed run this rank's share with their order `keys`), and
  // recomputes the speeds from the particle state.
  void restore(double t, long long step_count, Real wave_dt_reference, std::vector<uint64_t>* keys = nullptr);
  double time() const { return time_; }
  long long steps() const { return steps_; }
  const PhaseTimer& phase_timer() const { return timer_; }
  // Calls f with the whole state in the one-process particle order: directly in one process; in a distributed run
  // (MPI build under mpirun, docs/architecture.md) on rank 0 only, after gathering every rank's particles there in
  // that order, with the reductions local (parallel/reduction.h). The outputs are written inside it, so they are
  // those of one process. Collective in a distributed run.
  void with_whole_state(const std::function<void()>& f);
  // Calls f on rank 0 alone (directly in one process), with the reductions local and no gather: for outputs that
  // read no particle (file bookkeeping). Not collective.
  void on_root(const std::function<void()>& f);
#ifdef CDMPM_MPI
  // This rank's part of a distributed run (null in one process).
  const Domain<dim>* domain() const { return domain_.get(); }
#endif

  const Scene& scene;
  Particles<dim> particles;
  Grid<dim> grid;
  std::vector<Material> materials;
  std::vector<std::unique_ptr<Boundary<dim>>> boundaries;
  std::vector<SinkSpec> sinks;  // the scene's sinks and those of its boundaries (absorbing layers' spillways)
  RigidBodies<dim> rigid;
  Vec<dim> gravity, domain_size;
  Real max_wave_speed = 0;   // over particles, updated each step
  Real max_speed = 0;        // max |v_p|, updated each step
  Real wave_dt_at_start = 0; // reference for detecting a collapsing time step
  // Where and how the ice first breaks (probe/crack_starts.h), updated around each constitutive update; saved in
  // checkpoints by the run (run/run_files.cpp).
  CrackStartRecord<dim> crack_starts;

  static constexpr int reorder_interval = 8;  // steps between reorderings of particle memory by block

 private:
  void advance(Real dt, double t_end);
  void advance_multi_rate(Real dt, double t_end);
  // The phases (sim/phases.h).
  void bin();
  void flip_transfer();
  void p2g_phase(Real dt, bool solid_field);
  void scatter(Real dt);
  void transfer_velocity();
  void boundary_fold(bool solid_field = true);
  void grid_update_phase(Real dt, bool solid_field);
  void boundary_unfold(bool solid_field = true);
  void rigid_projection(Real dt);
  void advect_phase(Real dt);
  void sinks_phase();
  void update_speeds();
  void settle_elastically(double duration, Real damping);
#ifdef CDMPM_MPI
  void seed_distributed();
#endif

  double time_ = 0;
  long long steps_ = 0;
  Real material_dt_ = 0;                 // smallest of the materials' own time-step limits
  std::vector<uint8_t> rigid_material_;  // per material: its particles are moved by a rigid body
  std::vector<uint8_t> contact_material_;  // per material: a rigid body in contact, in its own field
  std::vector<uint8_t> interpolated_divergence_;  // per material: tr C_p from the interpolated velocity (g2p.h)
  ParticleBins bins_;
  RigidContact<dim> contact_;      // the rigid bodies' grid field and its contact with the others (sim/rigid_contact.h)
  FieldContact<dim> solid_field_;  // the deformable solids' own field and its contact with the others (sim/field_contact.h)
  BedLayer<dim> bed_;              // fixed water particles in the well-balanced beds (sim/bed_layer.h)
  std::vector<uint32_t> blocks_;   // the blocks of the particles and of the bed layer
  bool any_flip_ = false, any_j_bar_ = false;  // some material has a FLIP share, J-bar (material/water.h)
  bool multi_rate_ = false;        // time.multi_rate: the solids' field sub-steps (advance_multi_rate)
  Real solid_wave_speed_ = 0;      // multi-rate: the largest wave speed of the solids' field (max_wave_speed: the others')
  std::vector<uint32_t> field_index_;  // multi-rate: the particles of the solids' field, ascending
  std::vector<Vec<dim>> v0_;       // multi-rate: the shared field's velocity at the start of the step
  std::vector<Vec<dim>> flip_u_;   // per particle: its velocity the grid did not see (transfer/flip.h)
  int xpic_order_ = 0;             // the largest XPIC order of the materials (transfer/flip.h)
  XpicScratch<dim> xpic_;          // the XPIC recurrence's work arrays (transfer/flip.h)
  std::vector<Real> J_state_;      // the particles' own J while p2g takes the stress at the cell means (material/j_bar.h)
  PhaseTimer timer_;
#ifdef CDMPM_MPI
  std::unique_ptr<Domain<dim>> domain_;
#endif
};

}  // namespace cdmpm
