// particles.h - material points stored as a structure of arrays, solids first.
//
// Each field is its own contiguous array so a phase of the step streams only what it needs. Every particle
// carries a 64-bit id (unique in the run, kept through reordering, checkpoints and frames), its mass m, position x, velocity v, APIC affine matrix C (the particle's velocity gradient
// estimate, Jiang et al. 2015), the total volume ratio J = V / V0 and its material index. The reference
// (unstressed) volume is not stored: it is V0 = m / rho0 of the particle's material (material/material.h,
// reference_volume), exactly how seeding sets the mass.
//
// Solids (ice) also carry the elastic deformation gradient F and the hardening variable alpha of the
// plastic model (material/cohesive_cam_clay.h), and in 2D the out-of-plane elastic stretch Fz: a 2D body is in
// plane strain (the total F_zz is 1), so its elastic state is the 3x3 F_e = diag(F, Fz), whose Fz departs from 1
// where plastic flow strains the body out of its plane (material/ice.h). Only solids carry these: the particles are kept in two runs,
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

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/types.h"

namespace cdmpm {

// Index of a particle's material in the scene's material list; at most 256 materials (scene_loader checks).
using MaterialId = uint8_t;

template <int dim>
struct Particles {
  // Every particle.
  std::vector<uint64_t> id;
  std::vector<Vec<dim>> x, v;
  std::vector<Mat<dim>> C;
  std::vector<Real> mass, J;
  std::vector<MaterialId> material;
  // Solids only: entry q is the state of particle q < solid_count().
  std::vector<Mat<dim>> F;
  std::vector<Real> alpha;
  std::vector<Real> Fz;  // 2D only (plane strain): the out-of-plane elastic stretch; empty in 3D

  size_t size() const { return x.size(); }
  size_t solid_count() const { return F.size(); }
  uint64_t next_id = 0;  // id of the next particle added

  // Adds a copy of particle q of `from`, keeping its id (next_id unchanged): a solid after this set's solids, a fluid
  // at the end.
  void add_copy(const Particles& from, size_t q) {
    const uint64_t next = next_id;
    const bool solid = q < from.solid_count();
    if (solid)
      add_solid(from.x[q], from.v[q], from.mass[q], from.J[q], from.material[q], from.C[q], from.F[q], from.alpha[q],
                from.out_of_plane(q));
    else add_fluid(from.x[q], from.v[q], from.mass[q], from.J[q], from.material[q], from.C[q]);
    id[solid ? solid_count() - 1 : size() - 1] = from.id[q];
    next_id = next;
  }
  // Copies of the particles listed in `indices` (ascending), solids first as always: the batch a process sends
  // away when particles migrate (docs/architecture.md).
  Particles extract(const std::vector<uint32_t>& indices) const {
    Particles out;
    for (const uint32_t q : indices) out.add_copy(*this, q);
    return out;
  }
  // Writes the state of a batch from extract(indices) back to the particles it was copied from (the batch in the
  // same order; multi-rate stepping, sim/simulation.cpp).
  void write_back(const std::vector<uint32_t>& indices, const Particles& batch) {
    for (size_t j = 0; j < indices.size(); ++j) {
      const uint32_t q = indices[j];
      x[q] = batch.x[j];
      v[q] = batch.v[j];
      C[q] = batch.C[j];
      mass[q] = batch.mass[j];
      J[q] = batch.J[j];
      if (q < solid_count()) {
        F[q] = batch.F[j];
        alpha[q] = batch.alpha[j];
        if constexpr (dim == 2) Fz[q] = batch.Fz[j];
      }
    }
  }
  // Adds a batch (from extract), keeping its ids: its solids after this set's solids, its fluids at the end.
  void append(const Particles& batch) {
    for (size_t q = 0; q < batch.size(); ++q) add_copy(batch, q);
  }

  // Appends a fluid particle.
  void add_fluid(const Vec<dim>& xp, const Vec<dim>& vp, Real m, Real Jp, MaterialId mat,
                 const Mat<dim>& Cp = Mat<dim>::Zero()) {
    insert_common(size(), xp, vp, Cp, m, Jp, mat);
  }

  // Adds a solid particle with elastic deformation gradient Fe, hardening variable alpha0 and (2D) out-of-plane
  // elastic stretch fz after the last solid (an append while no fluid has been added; otherwise every fluid array
  // is shifted).
  void add_solid(const Vec<dim>& xp, const Vec<dim>& vp, Real m, Real Jp, MaterialId mat, const Mat<dim>& Cp,
                 const Mat<dim>& Fe, Real alpha0, Real fz = 1) {
    insert_common(solid_count(), xp, vp, Cp, m, Jp, mat);
    F.push_back(Fe);
    alpha.push_back(alpha0);
    if constexpr (dim == 2) Fz.push_back(fz);
  }
  // The out-of-plane elastic stretch of solid q: Fz[q] in 2D, 1 in 3D (no such axis).
  Real out_of_plane(size_t q) const {
    if constexpr (dim == 2) return Fz[q];
    else return Real(1);
  }

  // Applies fn to every array with one entry per particle, then to every solid-only array (used to
  // reorder, save and load them generically).
  template <class Fn>
  void for_each_array(Fn&& fn) {
    fn(id); fn(x); fn(v); fn(C); fn(mass); fn(J); fn(material);
  }
  template <class Fn>
  void for_each_solid_array(Fn&& fn) {
    fn(F); fn(alpha);
    if constexpr (dim == 2) fn(Fz);
  }

  // Reorders the particles so that new particle k is old particle order[k], except that the solids are moved
  // (keeping their relative order) in front of the fluids, so any order keeps the solids-first layout.
  // `order` may list a subset: the particles it leaves out are removed (sinks, sim/sinks.h).
  //
  // A full permutation is applied in place along its cycles, every array by its own thread, so the
  // reordering holds no copy of any field: it needs the permutation (4 B per particle; a second copy only
  // when solids must be moved in front) and a bit per particle.
  // A subset in increasing order (removal) is compacted in place; any other subset is gathered into copies.
  void permute(std::vector<uint32_t> o) {  // pass the order with std::move where it is not needed after
    const size_t ns = solid_count(), n = size();
    size_t new_ns = 0;
    for (const uint32_t q : o) new_ns += q < ns;
    // Solids first already (always when all particles are solids or all fluids): o is used as it is.
    if (!std::all_of(o.begin(), o.begin() + new_ns, [&](uint32_t q) { return q < ns; })) {
      std::vector<uint32_t> split;
      split.reserve(o.size());
      for (const uint32_t q : o)
        if (q < ns) split.push_back(q);
      for (const uint32_t q : o)
        if (q >= ns) split.push_back(q);
      o.swap(split);
    }
    if (o.size() == n && permute_in_place(o)) return;
    const bool increasing = std::is_sorted(o.begin(), o.end()) && std::adjacent_find(o.begin(), o.end()) == o.end();
    auto compact_or_gather = [&](auto& a, size_t m) {  // the first m entries of o index into a
      if (increasing) {
        for (size_t k = 0; k < m; ++k) a[k] = a[o[k]];  // o[k] >= k: sources are read before being overwritten
        a.resize(m);
        return;
      }
      std::remove_reference_t<decltype(a)> out(m);
#pragma omp parallel for schedule(static)
      for (size_t k = 0; k < out.size(); ++k) out[k] = a[o[k]];
      a.swap(out);
    };
    for_each_array([&](auto& a) { compact_or_gather(a, o.size()); });
    for_each_solid_array([&](auto& a) { compact_or_gather(a, new_ns); });
  }

 private:
  // Applies the permutation o (new k = old o[k]; a bijection, solids onto solids) to every array in place,
  // following its cycles from their smallest index. Returns false if o is not a bijection.
  bool permute_in_place(const std::vector<uint32_t>& o) {
    const size_t n = o.size();
    std::vector<bool> seen(n, false);
    std::vector<uint32_t> leaders;  // smallest index of every cycle longer than one
    for (size_t s = 0; s < n; ++s) {
      if (seen[s]) continue;
      size_t k = s, length = 0;
      while (!seen[k]) {
        seen[k] = true;
        k = o[k];
        ++length;
        if (k >= n) return false;
      }
      if (k != s) return false;  // entered a cycle elsewhere: o repeats an index
      if (length > 1) leaders.push_back(static_cast<uint32_t>(s));
    }
    // Leaders ascend, so the solids' cycles (within [0, solid_count()), as o maps solids onto solids) come first.
    const size_t solid_leaders =
        std::lower_bound(leaders.begin(), leaders.end(), static_cast<uint32_t>(solid_count())) - leaders.begin();
    auto apply = [&](auto& a) {
      const size_t count = a.size() == n ? leaders.size() : solid_leaders;
      for (size_t c = 0; c < count; ++c) {
        const uint32_t s = leaders[c];
        auto first = a[s];
        size_t k = s;
        for (size_t next = o[k]; next != s; k = next, next = o[k]) a[k] = a[next];
        a[k] = first;
      }
    };
    // One task per array.
#pragma omp parallel
#pragma omp single
    {
      auto spawn = [&](auto& a) {
        auto* array = &a;
#pragma omp task firstprivate(array)
        apply(*array);
      };
      for_each_array(spawn);
      for_each_solid_array(spawn);
    }
    return true;
  }

  void insert_common(size_t k, const Vec<dim>& xp, const Vec<dim>& vp, const Mat<dim>& Cp, Real m, Real Jp,
                     MaterialId mat) {
    id.insert(id.begin() + k, next_id++);
    x.insert(x.begin() + k, xp);
    v.insert(v.begin() + k, vp);
    C.insert(C.begin() + k, Cp);
    mass.insert(mass.begin() + k, m);
    J.insert(J.begin() + k, Jp);
    material.insert(material.begin() + k, mat);
  }
};

}  // namespace cdmpm
