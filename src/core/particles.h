// particles.h - material points stored as a structure of arrays, solids first.
//
// Each field is its own contiguous array so a phase of the step streams only what it needs. Every particle
// carries its mass m, reference volume V0 (volume in the unstressed state, so V = J V0), position x,
// velocity v, APIC affine matrix C (the particle's velocity gradient estimate, Jiang et al. 2015), the
// total volume ratio J = V / V0 and its material index.
//
// Solids (ice) also carry the elastic deformation gradient F and the hardening variable alpha of the
// plastic model (material/cohesive_cam_clay.h). Only they do: the particles are kept in two runs,
//   [0, solid_count())       the solids, whose F[q] and alpha[q] are the state of particle q,
//   [solid_count(), size())  the fluids (water), which have no F or alpha at all,
// so F and alpha hold solid_count() entries and are indexed by the particle index itself. This layout
// costs nothing per particle (no index array: a fluid pays only for what it uses, a solid for nothing
// extra), code that reads F[q] under a material-kind dispatch (material/stress.h,
// material/constitutive_update.h) is unchanged, and a loop over [0, solid_count()) visits exactly the
// solids. The runs are kept by add_solid (inserts after the last solid; seed solids before fluids so that
// this is an append) and by permute (which moves the solids, in order, in front of the fluids). A
// particle's material never changes from solid to fluid or back. Material kind Ice <=> q < solid_count().
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/types.h"

namespace cdmpm {

template <int dim>
struct Particles {
  // Every particle.
  std::vector<Vec<dim>> x, v;
  std::vector<Mat<dim>> C;
  std::vector<Real> mass, volume0, J;
  std::vector<int32_t> material;
  // Solids only: entry q is the state of particle q < solid_count().
  std::vector<Mat<dim>> F;
  std::vector<Real> alpha;

  size_t size() const { return x.size(); }
  size_t solid_count() const { return F.size(); }

  // Appends a fluid particle.
  void add_fluid(const Vec<dim>& xp, const Vec<dim>& vp, Real m, Real V0, Real Jp, int32_t mat,
                 const Mat<dim>& Cp = Mat<dim>::Zero()) {
    insert_common(size(), xp, vp, Cp, m, V0, Jp, mat);
  }

  // Adds a solid particle with elastic deformation gradient Fe and hardening variable alpha0 after the
  // last solid (an append while no fluid has been added; otherwise every fluid array is shifted).
  void add_solid(const Vec<dim>& xp, const Vec<dim>& vp, Real m, Real V0, Real Jp, int32_t mat, const Mat<dim>& Cp,
                 const Mat<dim>& Fe, Real alpha0) {
    insert_common(solid_count(), xp, vp, Cp, m, V0, Jp, mat);
    F.push_back(Fe);
    alpha.push_back(alpha0);
  }

  // Applies fn to every array with one entry per particle, then to every solid-only array (used to
  // reorder, save and load them generically).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(x); fn(v); fn(C); fn(mass); fn(volume0); fn(J); fn(material);
  }
  template <class Fn>
  void for_each_solid_array(Fn&& fn) {
    fn(F); fn(alpha);
  }

  // Reorders the particles so that new particle k is old particle order[k], except that the solids are moved
  // (keeping their relative order) in front of the fluids, so any order keeps the solids-first layout.
  // `order` may list a subset: the particles it leaves out are removed (sinks, sim/simulation.cpp).
  void permute(const std::vector<uint32_t>& order) {
    const size_t ns = solid_count();
    std::vector<uint32_t> o;
    o.reserve(order.size());
    for (const uint32_t q : order)
      if (q < ns) o.push_back(q);
    const size_t new_ns = o.size();
    for (const uint32_t q : order)
      if (q >= ns) o.push_back(q);
    auto gather = [&](auto& a, size_t n) {  // the first n entries of o index into a
      std::remove_reference_t<decltype(a)> out(n);
#pragma omp parallel for schedule(static)
      for (size_t k = 0; k < out.size(); ++k) out[k] = a[o[k]];
      a.swap(out);
    };
    for_each_array([&](auto& a) { gather(a, o.size()); });
    for_each_solid_array([&](auto& a) { gather(a, new_ns); });
  }

 private:
  void insert_common(size_t k, const Vec<dim>& xp, const Vec<dim>& vp, const Mat<dim>& Cp, Real m, Real V0, Real Jp,
                     int32_t mat) {
    x.insert(x.begin() + k, xp);
    v.insert(v.begin() + k, vp);
    C.insert(C.begin() + k, Cp);
    mass.insert(mass.begin() + k, m);
    volume0.insert(volume0.begin() + k, V0);
    J.insert(J.begin() + k, Jp);
    material.insert(material.begin() + k, mat);
  }
};

}  // namespace cdmpm
