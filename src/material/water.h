// water.h - the "water" material: a weakly compressible fluid (material/weakly_compressible_water.h: Tait
// equation of state p(J) = K/gamma (J^-gamma - 1), cut off at p >= 0, optional Newtonian viscosity; stress,
// energy, wave speed and initial state in material/tait_state.h).
//
// State: the total volume ratio J = V / V0, advanced by the discrete continuity equation
//   J <- J (1 + dt tr C_p)                  (dJ/dt = J div v, C_p the particle's velocity gradient).
// `continuity` says which divergence tr C_p is: "apic" (default), APIC's moving-least-squares gradient
// C_p = D^-1 sum_i w_ip v_i (x_i - x_p)^T; or "interpolated", the divergence of the interpolated velocity that
// moves the particles, div v(x_p) = sum_i v_i . grad w_ip, which g2p puts in C_p's isotropic part
// (transfer/g2p.h). The two agree for a velocity linear across the stencil; where it is not, APIC's lets a
// particle's J drift from the volume its neighbours leave it, and stirred water packs (docs/water.md, "Packing").
// Viscosity adds the explicit diffusion limit dt <= dx^2 rho / (2 dim mu).
// Two options against the spurious drag of one velocity field at small acoustic time steps (docs/water.md,
// "Buoyancy: J-bar and FLIP"): `j_bar`, the stress from the mean J of the particles of this material around the
// same grid node (material/j_bar.h), and `flip`, the share of FLIP in the velocity update (transfer/flip.h).
// Scene keys: density, bulk_modulus (both required), gamma (7), viscosity (0, at most 1e6 Pa s), j_bar (false),
// flip (0, in [0, 1]), xpic (off; 1-8, with flip), continuity ("apic"; "interpolated") - docs/scenes.md.
#pragma once

#include "material/flip_share.h"
#include "material/tait_state.h"

namespace cdmpm {

struct Water : TaitState {
  static constexpr std::string_view type = "water";
  static constexpr MaterialTraits traits{.fluid = true};

  static Water parse(const SceneReader& r, const Node& n) {
    r.object(n, {"type", "density", "bulk_modulus", "gamma", "viscosity", "j_bar", "flip", "xpic", "continuity"});
    Water w;
    w.eos = read_eos(r, n);
    w.eos.mu = static_cast<Real>(r.number(n, "viscosity", {0, 1e6}, 0.0));
    w.j_bar = r.boolean(n, "j_bar", false);
    w.flip = read_flip_share(r, n);
    w.interpolated_divergence = n.has("continuity") && r.string(n["continuity"], {"apic", "interpolated"}) == "interpolated";
    return w;
  }
  bool j_bar = false;  // the stress from the cell-mean J (material/j_bar.h)
  FlipShare flip;      // the FLIP share of the velocity update and its XPIC order (transfer/flip.h)
  bool interpolated_divergence = false;  // continuity "interpolated": tr C_p = div of the interpolated velocity
  Real stable_dt(Real dx, int dim) const {
    return eos.mu > 0 ? dx * dx * eos.rho0 / (Real(2 * dim) * eos.mu) : no_time_step_limit;
  }
  template <int dim>
  void update(Particles<dim>& p, size_t q, Real dt) const { p.J[q] *= Real(1) + dt * p.C[q].trace(); }
};

}  // namespace cdmpm
