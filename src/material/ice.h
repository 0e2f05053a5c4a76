// ice.h - the "ice" material: split Neo-Hookean elasticity (material/neo_hookean_split.h) with non-associative
// Cohesive Cam Clay plasticity and softening (material/cohesive_cam_clay.h); Wolper et al. 2019 (CD-MPM), 2021.
//
// State: the elastic deformation gradient F and the hardening variable alpha (core/particles.h: solids), and
// the total volume ratio J. The update after g2p (Jiang et al. 2016 course notes, eq. 202; Wolper et al. 2019,
// sec. 4):
//   J <- J (1 + dt tr C_p),   F_trial = (I + dt C_p) F,   then the return mapping projects F_trial onto the
//   yield surface and updates alpha.
// Damage d = 1 - p0(alpha) / p0_initial in [0, 1]: 0 intact, 1 all cohesion lost. Fastest wave: the P-wave
// speed sqrt(M_p / rho), M_p = kappa + 2 mu (1 - 1/d), raised by the density ratio max(det F, 1) (the
// volumetric tangent kappa/2 (J^2 + 1) J-scaled grows like J^2 in tension). Seeded under a lithostatic
// vertical stress -p with sigma_h = 0 (a laterally free slab on a bed): F = diag(s_h, s_v).
// Hydrofracture (poro-damage, optional key "hydrofracture"; Duddu, Jimenez & Bassis 2020, J. Glaciol. 66(257),
// 415-429, "A non-local continuum poro-damage mechanics model for hydrofracturing of surface crevasses in grounded
// glaciers"; Sun, Duddu & Hirshikesh 2021, Extreme Mech. Lett. 45, 101277, the phase-field form): water standing at level z_w in the ice's crack system fills its damage, and the
// Cauchy stress of ice with damage d is
//   sigma = sigma_ice(F) - d p_w I,   p_w = rho_w g max(z_w - z, 0),
// z the particle's elevation (the last axis), so the Kirchhoff stress p2g uses is tau = tau_ice - J d p_w I (J = det F).
// sigma_ice is the skeleton's (effective) stress: the yield surface and the softening see it alone, as Biot's
// effective stress with coefficient d; the water acts on the ice through the momentum balance, pushing the walls of a
// damaged band apart. It acts in every damaged particle below z_w (optionally only within `region` along x).
// Plane strain (2D): a 2D body is a slice of a 3D one that cannot strain out of its plane (total F_zz = 1). Its
// elastic state is diag(F, Fz) (core/particles.h), and the energy, the stress, p, q and the return mapping are
// those of that 3x3 state (material/cohesive_cam_clay.h, return_mapping_plane_strain), so the same parameters mean
// the same ice in 2D and in 3D. The in-plane block of tau drives the motion; tau_zz holds the body in its plane.
// convention_2d = "cd_mpm" instead takes the reference implementation's 2D convention (the 2x2 state;
// CohesiveCamClay::use_reference_2d), to reproduce its set-ups.
// Scene keys (docs/ice.md, docs/scenes.md): density, youngs_modulus, poissons_ratio (0.3); M or
// friction_angle; beta; xi; exactly one of p0, alpha0, tensile_strength; hardening (true); plastic (true);
// convention_2d ("plane_strain");
// hydrofracture {water_level, water_density (1025), region} (off); flip (0: the FLIP share) and xpic (off:
// its XPIC order), transfer/flip.h; contact (false: the ice shares the grid's velocity field with the water; true: a
// field of its own in frictionless contact with the other materials, sim/field_contact.h; needs flip 0).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "material/cohesive_cam_clay.h"
#include "material/flip_share.h"
#include "material/material_model.h"
#include "material/neo_hookean_split.h"

namespace cdmpm {

// Water pressure in damaged ice (poro-damage, see the header). Off by default: the stress is then the skeleton's,
// bit for bit.
struct PoroDamage {
  bool on = false;
  Real water_level = 0;                           // z_w, elevation of the water in the crack system [m]
  Real water_density = 1025;                      // rho_w [kg/m^3]
  Real gravity = 0;                               // g [m/s^2], set by the scene loader from the scene's gravity
  Real x_min = -std::numeric_limits<Real>::max();  // the region along the first axis where it acts [m]
  Real x_max = std::numeric_limits<Real>::max();
  // p_w = rho_w g max(z_w - z, 0) at position x (zero outside the region).
  template <int dim>
  Real water_pressure(const Vec<dim>& x) const {
    const Real head = water_level - x(dim - 1);
    if (!(head > 0) || x(0) < x_min || x(0) > x_max) return 0;
    return water_density * gravity * head;
  }
};

struct Ice {
  static constexpr std::string_view type = "ice";
  static constexpr MaterialTraits traits{.solid_state = true, .breakable = true};
  Real rho0 = 0;
  NeoHookeanSplit elastic;
  CohesiveCamClay plastic;
  bool plasticity = true;   // false: purely elastic (no return mapping)
  Real p0_initial = 0;      // pre-consolidation pressure of intact ice [Pa]
  Real alpha_initial = 0;   // alpha giving p0_initial
  PoroDamage hydrofracture;  // water pressure in damaged ice (off unless the scene sets "hydrofracture")
  FlipShare flip;            // the FLIP share of the velocity update and its XPIC order (transfer/flip.h)
  bool contact = false;      // a velocity field of its own, in frictionless contact with the others (sim/field_contact.h)
  bool plane_strain = false;  // 2D: plane strain (the default); false in 3D and in the reference 2D convention

  static Ice parse(const SceneReader& r, const Node& n);

  Real p0(Real alpha) const { return plastic.p0_of_alpha(alpha, elastic.kappa); }
  Real damage(Real alpha) const { return plasticity ? CohesiveCamClay::damage(p0(alpha), p0_initial) : Real(0); }

  Real density() const { return rho0; }
  // Whether a 2D particle is a plane-strain body (its elastic state the 3x3 diag(F, Fz)); never in 3D.
  template <int dim>
  bool in_plane_strain() const { return dim == 2 && plane_strain; }
  // The elastic state diag(F, Fz) of a plane-strain particle.
  template <int dim>
  static Mat<3> plane_strain_F(const Particles<dim>& p, size_t q) {
    Mat<3> F3 = Mat<3>::Zero();
    F3.template topLeftCorner<dim, dim>() = p.F[q];
    F3(2, 2) = p.out_of_plane(q);
    return F3;
  }
  // d p_w of particle q: the pressure of the water in its damage (0 with hydrofracture off).
  template <int dim>
  Real pore_pressure(const Particles<dim>& p, size_t q) const {
    if (!hydrofracture.on) return 0;
    const Real pw = hydrofracture.water_pressure<dim>(p.x[q]);
    return pw > 0 ? damage(p.alpha[q]) * pw : Real(0);
  }
  // The skeleton's Kirchhoff stress: of F, or in plane strain the in-plane block of that of diag(F, Fz).
  template <int dim>
  Mat<dim> skeleton_kirchhoff(const Particles<dim>& p, size_t q) const {
    if (in_plane_strain<dim>())
      return elastic.kirchhoff<3>(plane_strain_F(p, q)).template topLeftCorner<dim, dim>();
    return elastic.kirchhoff<dim>(p.F[q]);
  }
  // tau = tau_ice(F) - J d p_w I (poro-damage; the header).
  template <int dim>
  Mat<dim> kirchhoff(const Particles<dim>& p, size_t q) const {
    Mat<dim> tau = skeleton_kirchhoff(p, q);
    if (hydrofracture.on) {
      const Real pp = pore_pressure<dim>(p, q);
      if (pp > 0) tau.diagonal().array() -= volume_ratio(p, q) * pp;
    }
    return tau;
  }
  // The elastic volume ratio det F_e (det F Fz in plane strain).
  template <int dim>
  Real volume_ratio(const Particles<dim>& p, size_t q) const {
    const Real J = p.F[q].determinant();
    return in_plane_strain<dim>() ? J * p.out_of_plane(q) : J;
  }
  template <int dim>
  Real pressure(const Particles<dim>& p, size_t q) const {
    const Real Je = volume_ratio(p, q);
    const Real skeleton = elastic.pressure_of_J(Je) / Je;
    return hydrofracture.on ? skeleton + pore_pressure<dim>(p, q) : skeleton;  // off: bit for bit (a -0 stays -0)
  }
  template <int dim>
  Real energy_density(const Particles<dim>& p, size_t q) const {
    return in_plane_strain<dim>() ? elastic.energy_density<3>(plane_strain_F(p, q)) : elastic.energy_density<dim>(p.F[q]);
  }
  template <int dim>
  Real stiffening(const Particles<dim>& p, size_t q) const { return std::max(volume_ratio(p, q), Real(1)); }
  // P-wave speed: lambda + 2 mu in 3D and in plane strain, kappa + mu in the reference 2D convention.
  template <int dim>
  Real wave_speed(Real s) const {
    const Real modulus = in_plane_strain<dim>() ? elastic.p_wave_modulus<3>() : elastic.p_wave_modulus<dim>();
    return s * std::sqrt(modulus / rho0);
  }
  Real stable_dt(Real, int) const { return no_time_step_limit; }
  template <int dim>
  void update(Particles<dim>& p, size_t q, Real dt) const {
    p.J[q] *= Real(1) + dt * p.C[q].trace();
    Mat<dim> F = (Mat<dim>::Identity() + dt * p.C[q]) * p.F[q];
    if (plasticity) {
      if constexpr (dim == 2) {
        if (plane_strain) plastic.return_mapping_plane_strain(F, p.Fz[q], p.alpha[q], p0(p.alpha[q]), elastic);
        else plastic.return_mapping<dim>(F, p.alpha[q], p0(p.alpha[q]), elastic);
      } else {
        plastic.return_mapping<dim>(F, p.alpha[q], p0(p.alpha[q]), elastic);
      }
    }
    p.F[q] = F;
  }
  // Lithostatic state: vertical stress -pressure, horizontal -k pressure; in plane strain along both horizontal
  // axes (the in-plane one and the out-of-plane one, as in 3D), with the out-of-plane stretch in Fz and the
  // in-plane area ratio as J.
  template <int dim>
  InitialState<dim> initial_state(Real pressure, Real lateral_ratio) const {
    if (in_plane_strain<dim>()) {
      const Vec<3> st = elastic.template vertical_load_stretches<3>(-pressure, lateral_ratio);
      Mat<dim> F = Mat<dim>::Identity();
      F(0, 0) = st(0);
      F(dim - 1, dim - 1) = st(2);
      return {st(0) * st(2), F, alpha_initial, st(1)};
    }
    const Vec<dim> st = elastic.template vertical_load_stretches<dim>(-pressure, lateral_ratio);
    return {st.prod(), st.asDiagonal(), alpha_initial};
  }
  // Damage in [0, 1], the hardening variable alpha and the current strength p0(alpha) [Pa].
  std::vector<std::string> field_names() const { return {"damage", "alpha", "p0"}; }
  template <int dim>
  void fields(const Particles<dim>& p, size_t q, float* out) const {
    out[0] = static_cast<float>(damage(p.alpha[q]));
    out[1] = static_cast<float>(p.alpha[q]);
    out[2] = static_cast<float>(plasticity ? p0(p.alpha[q]) : Real(0));
  }
};

// Ice: E, nu, density; M or friction_angle; beta, xi; exactly one of p0, alpha0, tensile_strength.
inline Ice Ice::parse(const SceneReader& r, const Node& m) {
  r.object(m, {"type", "density", "youngs_modulus", "poissons_ratio", "M", "friction_angle", "beta", "xi", "p0",
               "alpha0", "tensile_strength", "hardening", "plastic", "hydrofracture", "flip", "xpic", "contact",
               "convention_2d"});
  Ice ice;
  // 2D: plane strain (the 3x3 state with F_zz = 1: one material in 2D and 3D), or the reference implementation's
  // 2D convention (the 2x2 state; docs/ice.md, "Two 2D conventions").
  bool reference_2d = false;
  if (m.has("convention_2d")) {
    if (r.dim() != 2) r.fail(m.child("convention_2d"), "only for 2D scenes (a 3D body has no 2D convention; remove it)");
    reference_2d = r.string(m["convention_2d"], {"plane_strain", "cd_mpm"}) == "cd_mpm";
  }
  ice.plane_strain = r.dim() == 2 && !reference_2d;
  if (reference_2d) ice.plastic.use_reference_2d();
  ice.flip = read_flip_share(r, m);
  ice.contact = r.boolean(m, "contact", false);
  if (ice.contact && ice.flip.a > 0)
    r.fail(m.child("flip"), "not used with \"contact\" (the ice's own field is transferred by APIC; remove \"flip\" or set it to 0)");
  // Bounds of real materials, which keep the time step and the state representable.
  ice.rho0 = static_cast<Real>(r.number(r.required(m, "density"), {1, 1e5}, " kg/m^3"));
  const double E = r.number(r.required(m, "youngs_modulus"), {0, 1e12, true, false}, " Pa");
  const double nu = r.number(m, "poissons_ratio", {-1, 0.49, true, false}, 0.3);
  ice.plasticity = r.boolean(m, "plastic", true);
  ice.plastic.hardening = r.boolean(m, "hardening", true);
  // The bulk modulus of the material (3D) in 3D, plane strain and the reference 2D convention alike (there
  // lambda + 2/3 mu, the same number); the split model's 2D form with it is the reference convention's.
  ice.elastic = NeoHookeanSplit::from_young_poisson(static_cast<Real>(E), static_cast<Real>(nu));
  if (!ice.plasticity) {
    for (const char* key : {"M", "friction_angle", "beta", "xi", "p0", "alpha0", "tensile_strength", "hydrofracture"})
      if (m.has(key)) r.fail(m.child(key), "not used when \"plastic\" is false (remove it)");
    ice.plastic.M = ice.plastic.beta = ice.plastic.xi = 0;
    return ice;
  }
  if (m.has("M") == m.has("friction_angle"))
    r.fail(m.path, "expected exactly one of \"M\" (critical-state slope) or \"friction_angle\" (degrees)");
  // friction_angle: the triaxial-compression Mohr-Coulomb match M = 6 sin(phi) / (3 - sin(phi)); in the reference
  // 2D convention its own, sqrt(2/3) 2 sin(phi) / (3 - sin(phi)) d / sqrt(2 / (6 - d)) = 8/sqrt(3) sin(phi) / (3 - sin(phi)).
  const double phi = m.has("M") ? 0 : r.number(m["friction_angle"], {0, 90, true, true}) * std::numbers::pi / 180;
  const double mc = std::sin(phi) / (3 - std::sin(phi));
  ice.plastic.M = static_cast<Real>(m.has("M") ? r.number(m["M"], gt(0)) : (reference_2d ? 8 / std::sqrt(3.0) : 6.0) * mc);
  ice.plastic.beta = static_cast<Real>(r.number(r.required(m, "beta"), gt(0)));
  ice.plastic.xi = static_cast<Real>(r.number(r.required(m, "xi"), gt(0)));
  if (m.has("p0") + m.has("alpha0") + m.has("tensile_strength") != 1)
    r.fail(m.path, "expected exactly one of \"p0\" [Pa], \"alpha0\" or \"tensile_strength\" [Pa] (initial strength)");
  const double p0_max = 0.5 * ice.elastic.kappa;  // the Kirchhoff pressure of the split model never exceeds kappa/2
  double p0 = 0;
  if (m.has("p0")) {
    p0 = r.number(m["p0"], {0, p0_max, true, true}, " (the initial p0 must be below kappa/2 = " + format_number(p0_max) + " Pa)");
  } else if (m.has("alpha0")) {
    p0 = ice.plastic.p0_of_alpha(static_cast<Real>(r.number(m["alpha0"], {-Range::inf, 0, false, false})), ice.elastic.kappa);
    if (!(p0 < p0_max)) r.expected(m["alpha0"], "a value giving p0 < kappa/2 = " + format_number(p0_max) + " Pa");
  } else {
    // The uniaxial strength of the yield surface is proportional to p0: the material's (3D) uniaxial test, or the
    // 2x2 state's in the reference 2D convention.
    const double per_p0 = reference_2d ? ice.plastic.uniaxial_strength<2>(1, true) : ice.plastic.uniaxial_strength<3>(1, true);
    p0 = r.number(m["tensile_strength"], gt(0)) / per_p0;
    if (!(p0 < p0_max))
      r.expected(m["tensile_strength"], "a strength below " + format_number(p0_max * per_p0) + " Pa (it needs p0 = " +
                                            format_number(p0) + " Pa, above kappa/2)");
  }
  // Damage is measured against the strength the particle actually starts with.
  ice.alpha_initial = ice.plastic.alpha_of_p0(static_cast<Real>(p0), ice.elastic.kappa);
  ice.p0_initial = ice.p0(ice.alpha_initial);
  if (m.has("hydrofracture")) {
    // {"water_level": z_w [m], "water_density": rho_w [kg/m^3] (1025), "region": [x_min, x_max] [m] (everywhere)}.
    const Node h = m["hydrofracture"];
    r.object(h, {"water_level", "water_density", "region"});
    ice.hydrofracture.on = true;
    ice.hydrofracture.water_level = static_cast<Real>(r.number(r.required(h, "water_level"), {-1e7, 1e7}, " m"));
    // Fresh water 1000, sea water 1025, dense brines about 1200 kg/m^3.
    ice.hydrofracture.water_density = static_cast<Real>(r.number(h, "water_density", {900, 1300}, 1025.0));
    if (h.has("region")) {
      const std::vector<double> x = r.numbers(h["region"], 2, {-1e7, 1e7});
      if (!(x[0] < x[1])) r.expected(h["region"], "[x_min, x_max] with x_min < x_max");
      ice.hydrofracture.x_min = static_cast<Real>(x[0]);
      ice.hydrofracture.x_max = static_cast<Real>(x[1]);
    }
  }
  return ice;
}

}  // namespace cdmpm
