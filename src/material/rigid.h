// rigid.h - the "rigid" material: the particles of one rigid body (sim/rigid_bodies.h). After each g2p their
// velocities are projected onto the body's rigid motion and the body moves them rigidly, so the model's own
// update does nothing (the projection advances their J, see rigid_bodies.h).
// They carry the pressure of the Tait equation of state (material/tait_state.h, with the body's density and
// bulk modulus, no viscosity) of a volume ratio J that follows the divergence of the grid velocity at the
// particle: the pressure that keeps other materials from flowing into the body (without it the body, having
// no stress, would let water seep through it). Its sum over a body is an internal force that the rigid
// projection cancels, so it acts only on the water. Stored with the fluids (no F or alpha).
// With `flip` (transfer/flip.h) the particles' velocities before the projection keep that share of FLIP, so the
// body's momentum follows the grid's change of velocity instead of its smoothed velocity.
// With `contact` the body has a grid field of its own in frictionless contact with the other materials
// (sim/rigid_contact.h): its particles leave the shared field, so their pressure, J-bar and FLIP share do nothing.
// Scene keys: density, bulk_modulus (both required), gamma (7), flip (0, in [0, 1]), xpic (off; 1-8, with flip),
// j_bar (false), contact (false) - docs/scenes.md.
#pragma once

#include "material/flip_share.h"
#include "material/tait_state.h"

namespace cdmpm {

struct Rigid : TaitState {
  static constexpr std::string_view type = "rigid";
  static constexpr MaterialTraits traits{.rigid = true};

  static Rigid parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "density", "bulk_modulus", "gamma", "flip", "xpic", "j_bar", "contact"});
    Rigid b;
    b.eos = read_eos(r, n);
    b.flip = read_flip_share(r, n);
    b.j_bar = r.boolean(n, "j_bar", false);
    b.contact = r.boolean(n, "contact", false);
    return b;
  }
  FlipShare flip;  // the FLIP share of the particles' velocity update and its XPIC order (transfer/flip.h)
  bool j_bar = false;  // its pressure from the cell-mean J (material/j_bar.h)
  bool contact = false;  // a field of its own, in frictionless contact with the others (sim/rigid_contact.h)
  Real stable_dt(Real, int) const { return no_time_step_limit; }
  template <int dim>
  void update(Particles<dim>&, size_t, Real) const {}
};

}  // namespace cdmpm
