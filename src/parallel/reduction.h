// reduction.h - the one interface through which every global quantity is combined across processes: the
// largest speed and wave speed (time step), the stability check, probe values, energies and mass, and the
// rigid-body sums, the hazard record's per-column extremes, the crack-start record's events of a step (concatenate). Each caller first reduces over its own particles (OpenMP, in a fixed order where the result
// must not depend on the thread count), then passes its partial result here.
//
// One process (the default build): every function is the identity. The MPI build (-DCDMPM_MPI=ON,
// parallel/communicator.h) makes them collective: max/min are exact in any order; sums are combined in rank order
// of a partition that follows the global block order (parallel/partition.h), so a result does not depend on how
// the work was split within a rank. Sums that must have the bits of one process whatever the split (the probes'
// and energies' sums over particles) are exact instead: each rank and thread accumulates an ExactSum
// (math/exact_sum.h) and global::sum adds the accumulators' integer chunks, exact in any order.
// Every rank must call the same reductions in the same order.
// Iceberg detection (probe/icebergs.h) joins components across ranks rather than reducing numbers: it has its own
// exchange, parallel/rank_icebergs.h, with the same exact sums.
#pragma once

#include <type_traits>
#include <vector>

#include "math/exact_sum.h"

#ifdef CDMPM_MPI
#include "parallel/communicator.h"
#endif

namespace cdmpm::global {

#ifndef CDMPM_MPI
inline double sum(double local) { return local; }
inline double max(double local) { return local; }
inline double min(double local) { return local; }
template <class T>
void sum(std::vector<T>&) {}
template <class T>
void max(std::vector<T>&) {}
template <class T>
void min(std::vector<T>&) {}
template <class T>
void concatenate(std::vector<T>&) {}
// Every accumulator's total over the processes (in place).
inline void sum(std::vector<ExactSum>&) {}
#else
namespace detail {
// The scalar of T (T itself, or the Scalar of a fixed-size Eigen type) and how many T holds.
template <class T, class = void>
struct ScalarOf {
  using type = T;
};
template <class T>
struct ScalarOf<T, std::void_t<typename T::Scalar>> {
  using type = typename T::Scalar;
};
template <class T, class F>
void apply(std::vector<T>& v, F&& f) {
  using S = typename ScalarOf<T>::type;
  static_assert(std::is_floating_point_v<S> && sizeof(T) % sizeof(S) == 0, "reduce floating-point values");
  f(reinterpret_cast<S*>(v.data()), v.size() * (sizeof(T) / sizeof(S)));
}
}  // namespace detail
inline double sum(double local) { return mpi::sum(local); }
inline double max(double local) { return mpi::max(local); }
inline double min(double local) { return mpi::min(local); }
template <class T>
void sum(std::vector<T>& v) {
  detail::apply(v, [](auto* p, size_t n) { mpi::sum(p, n); });
}
template <class T>
void max(std::vector<T>& v) {
  detail::apply(v, [](auto* p, size_t n) { mpi::max(p, n); });
}
template <class T>
void min(std::vector<T>& v) {
  detail::apply(v, [](auto* p, size_t n) { mpi::min(p, n); });
}
// Every accumulator's total over the processes (in place): the chunks and the counts of infinite and NaN terms
// added as integers, exact in any order.
inline void sum(std::vector<ExactSum>& v) {
  constexpr size_t kWords = ExactSum::kChunks + 3;
  std::vector<int64_t> words(v.size() * kWords);
  for (size_t i = 0; i < v.size(); ++i) {
    v[i].normalize();
    std::copy(v[i].chunks().begin(), v[i].chunks().end(), words.begin() + i * kWords);
    for (int f = 0; f < 3; ++f) words[i * kWords + ExactSum::kChunks + f] = (v[i].flags() >> f) & 1;
  }
  mpi::sum(words.data(), words.size());
  for (size_t i = 0; i < v.size(); ++i) {
    std::copy(words.begin() + i * kWords, words.begin() + i * kWords + ExactSum::kChunks, v[i].chunks().begin());
    uint8_t flags = 0;
    for (int f = 0; f < 3; ++f) flags |= uint8_t(words[i * kWords + ExactSum::kChunks + f] > 0) << f;
    v[i].set_flags(flags);
    v[i].normalize();
  }
}
// Every rank's items, concatenated in rank order, on every rank (plain records copied as bytes: numbers, enums
// and fixed-size Eigen vectors).
template <class T>
void concatenate(std::vector<T>& v) {
  static_assert(std::is_standard_layout_v<T>, "concatenate plain records");
  if (!mpi::active() || mpi::size() == 1) return;
  mpi::Bytes mine;
  mpi::put(mine, v.data(), v.size());
  v.clear();
  for (const mpi::Bytes& b : mpi::allgather(mine)) {
    mpi::Reader r{b};
    const size_t n = b.size() / sizeof(T);
    const size_t at = v.size();
    v.resize(at + n);
    r.get(v.data() + at, n);
  }
}
#endif

}  // namespace cdmpm::global
