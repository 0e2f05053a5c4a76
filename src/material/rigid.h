// rigid.h - the "rigid" material: the particles of one rigid body (sim/rigid_bodies.h). After each g2p their
// velocities are projected onto the body's rigid motion and the body moves them rigidly, so the model's own
// update does nothing (the projection advances their J, see rigid_bodies.h).
// They carry the pressure of the Tait equation of state (material/tait_state.h, with the body's density and
// bulk modulus, no viscosity) of a volume ratio J that follows the divergence of the grid velocity at the
// particle: the pressure that keeps other materials from flowing into the body (without it the body, having
// no stress, would let water seep through it). Its sum over a body is an internal force that the rigid
// projection cancels, so it acts only on the water. Stored with the fluids (no F or alpha).
// Scene keys: density, bulk_modulus (both required), gamma (7) - docs/scenes.md.
#pragma once

#include "material/tait_state.h"

namespace cdmpm {

struct Rigid : TaitState {
  static constexpr std::string_view type = "rigid";
  static constexpr MaterialTraits traits{.rigid = true};

  static Rigid parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "density", "bulk_modulus", "gamma"});
    Rigid b;
    b.eos = read_eos(r, n);
    return b;
  }
  Real stable_dt(Real, int) const { return no_time_step_limit; }
  template <int dim>
  void update(Particles<dim>&, size_t, Real) const {}
};

}  // namespace cdmpm
