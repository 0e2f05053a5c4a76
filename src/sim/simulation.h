// simulation.h - one MPM simulation: particles, grid, materials, boundaries, and the explicit step.
//
// One step (symplectic Euler, Jiang et al. 2016 course notes, sec. 9), data flowing one way:
//   particles --p2g--> grid --wall folding, grid_update + boundary conditions--> grid --g2p--> particles
//   --rigid projection--> particles --constitutive_update, rigid motion--> particles --sinks--> particles
// (rigid bodies: sim/rigid_bodies.h; sinks remove the particles inside them)
// The time step is dt = min(cfl dx / max|v_p|, wave_cfl dx / c_max, viscous limit, max_dt), where c_max is
// the largest wave speed of any material present (acoustic speed of water in its current state).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "boundary/boundary.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/material.h"
#include "scene/scene.h"
#include "sim/rigid_bodies.h"

namespace cdmpm {

template <int dim>
class Simulation {
 public:
  explicit Simulation(const Scene& scene);

  // Largest stable time step for the current state (before clamping to output times).
  Real stable_dt() const;
  // Advances the state by dt.
  void step(Real dt);
  // Checks the state after a step; returns a message saying where and why if it is unstable.
  std::optional<std::string> check_state() const;
  // Recomputes derived quantities (speeds) after the particle state was replaced, e.g. from a checkpoint.
  void refresh() { update_speeds(); }

  const Scene& scene;
  Particles<dim> particles;
  Grid<dim> grid;
  std::vector<Material> materials;
  std::vector<std::unique_ptr<Boundary<dim>>> boundaries;
  RigidBodies<dim> rigid;
  Vec<dim> gravity, domain_size;
  double time = 0;
  long long steps = 0;
  Real max_wave_speed = 0;   // over particles, updated each step
  Real max_speed = 0;        // max |v_p|, updated each step
  Real wave_dt_at_start = 0; // reference for detecting a collapsing time step

  static constexpr int reorder_interval = 8;  // steps between reorderings of particle memory by block

 private:
  Real viscous_dt_ = 0;
  ParticleBins bins_;
  void seed_body(const BodySpec& body);
  void remove_sunk_particles();
  void update_speeds();
};

}  // namespace cdmpm
