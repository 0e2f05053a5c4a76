// tait_state.h - what the two models whose state is the volume ratio J alone share (material/water.h,
// material/rigid.h): the Tait equation of state of material/weakly_compressible_water.h for the stress,
// pressure, stored energy and acoustic wave speed, and the hydrostatic initial state.
//   tau = -J p(J) I + 2 mu J dev(D),  sigma = tau / J,  psi(J),  wave speed c(J) growing as J falls (s = 1/J),
//   a particle seeded under pressure p at the J the equation of state gives for p.
#pragma once

#include "material/material_model.h"
#include "material/weakly_compressible_water.h"

namespace cdmpm {

struct TaitState {
  WeaklyCompressibleWater eos;

  Real density() const { return eos.rho0; }
  template <int dim>
  Mat<dim> kirchhoff(const Particles<dim>& p, size_t q) const { return eos.kirchhoff<dim>(p.J[q], p.C[q]); }
  template <int dim>
  Real volume_ratio(const Particles<dim>& p, size_t q) const { return p.J[q]; }
  template <int dim>
  Real pressure(const Particles<dim>& p, size_t q) const { return eos.pressure(p.J[q]); }
  template <int dim>
  Real energy_density(const Particles<dim>& p, size_t q) const { return eos.energy_density(p.J[q]); }
  template <int dim>
  Real stiffening(const Particles<dim>& p, size_t q) const { return Real(1) / p.J[q]; }
  template <int dim>
  Real wave_speed(Real s) const { return eos.wave_speed(Real(1) / s); }
  template <int dim>
  InitialState<dim> initial_state(Real pressure, Real /*lateral_ratio*/) const { return {eos.volume_ratio_at_pressure(pressure)}; }
  std::vector<std::string> field_names() const { return {}; }
  template <int dim>
  void fields(const Particles<dim>&, size_t, float*) const {}

 protected:
  // Reads density [1, 1e5] kg/m^3, bulk_modulus (0, 1e12] Pa (both required) and gamma (0, 20] (default 7) of a
  // scene material object: bounds of real materials, which keep the time step and the state representable.
  static WeaklyCompressibleWater read_eos(const SceneReader& r, const Node& n) {
    return {static_cast<Real>(r.number(r.required(n, "density"), {1, 1e5}, " kg/m^3")),
            static_cast<Real>(r.number(r.required(n, "bulk_modulus"), {0, 1e12, true, false}, " Pa")),
            static_cast<Real>(r.number(n, "gamma", {0, 20, true, false}, 7.0)), 0};
  }
};

}  // namespace cdmpm
