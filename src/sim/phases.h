// phases.h - the named phases of one MPM step, in the order the step runs them (sim/simulation.cpp), and the
// timer that accumulates the wall time of each (written to summary.json as phase_seconds).
//
//   bin               sort particles by grid block, activate the blocks they touch   grid/particle_bins.h
//   flip_transfer     [materials with a FLIP share] the transfer's grid velocity v^n  transfer/flip.h
//                     without forces, and each particle's velocity it does not hold
//                     [materials with xpic: that velocity filtered by XPIC's PIC transfers]
//   p2g               mass, momentum and stress impulse to the grid                    transfer/p2g.h
//                     [fluids with j_bar: the stress at the cell-mean J]               material/j_bar.h
//                     [distributed: halo sum, other ranks' patches added in colour order, parallel/halo_exchange.h]
//   boundary_fold     ghost-node contributions to their mirror nodes                  boundary/*.cpp
//                     [distributed: on the owner of both nodes, the partition never cuts a pair]
//   grid_update       v = mv / m + dt g, then the boundary conditions                 grid/grid_update.h
//   boundary_unfold   mirror velocities back to the ghost nodes                       boundary/*.cpp
//                     [distributed: halo exchange, owned velocities copied to ghosts]
//   g2p               particle v and C from the grid [plus the FLIP share]             transfer/g2p.h, flip.h
//   constitutive_update  each material's state update from C                          material/*.h
//   rigid_projection  rigid particles onto their bodies' rigid motion                 sim/rigid_bodies.h
//   advect            x += dt v (rigid bodies move rigidly), kept inside the walls    sim/advect.h
//   sinks             particles inside a sink removed                                 sim/sinks.h
//                     [distributed: then particle migration to the ranks owning their blocks, parallel/migration.h]
//   reductions        largest speed and wave speed for the next time step            sim/simulation.cpp
#pragma once

#include <array>
#include <chrono>

namespace cdmpm {

enum class Phase { Bin, FlipTransfer, P2G, BoundaryFold, GridUpdate, BoundaryUnfold, G2P, ConstitutiveUpdate, RigidProjection, Advect,
                   Sinks, Reductions, Count };

inline constexpr std::array<const char*, static_cast<size_t>(Phase::Count)> phase_names = {
    "bin", "flip_transfer", "p2g", "boundary_fold", "grid_update", "boundary_unfold", "g2p", "constitutive_update", "rigid_projection",
    "advect", "sinks", "reductions"};

class PhaseTimer {
 public:
  // Runs f, adding its wall time to phase p.
  template <class F>
  void run(Phase p, F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    seconds_[static_cast<size_t>(p)] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  double seconds(Phase p) const { return seconds_[static_cast<size_t>(p)]; }

 private:
  std::array<double, static_cast<size_t>(Phase::Count)> seconds_{};
};

}  // namespace cdmpm
