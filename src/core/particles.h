// particles.h - material points stored as a structure of arrays.
//
// Each field is its own contiguous array so a phase of the step streams only what it needs. A particle
// carries its mass m, reference volume V0 (volume in the unstressed state, so V = J V0), position x,
// velocity v, APIC affine matrix C (the particle's velocity gradient estimate, Jiang et al. 2015), the
// total volume ratio J = V / V0, its material index, and for solids the elastic deformation gradient F and
// the hardening variable alpha of the plastic model (material/cohesive_cam_clay.h). Fluids leave F = I and
// alpha = 0 untouched.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.h"

namespace cdmpm {

template <int dim>
struct Particles {
  std::vector<Vec<dim>> x, v;
  std::vector<Mat<dim>> C, F;
  std::vector<Real> mass, volume0, J, alpha;
  std::vector<int32_t> material;

  size_t size() const { return x.size(); }

  void add(const Vec<dim>& xp, const Vec<dim>& vp, Real m, Real V0, Real Jp, int32_t mat, Real alpha0 = 0) {
    x.push_back(xp);
    v.push_back(vp);
    C.push_back(Mat<dim>::Zero());
    F.push_back(Mat<dim>::Identity());
    mass.push_back(m);
    volume0.push_back(V0);
    J.push_back(Jp);
    alpha.push_back(alpha0);
    material.push_back(mat);
  }

  // Applies fn to every per-particle array (used to reorder, save and load them generically).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(x); fn(v); fn(C); fn(F); fn(mass); fn(volume0); fn(J); fn(alpha); fn(material);
  }

  // Reorders all arrays so that new particle k is old particle order[k].
  void permute(const std::vector<uint32_t>& order) {
    for_each_array([&](auto& a) {
      std::remove_reference_t<decltype(a)> out(order.size());
#pragma omp parallel for schedule(static)
      for (size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
      a.swap(out);
    });
  }
};

}  // namespace cdmpm
