// exact_sum.h - the exact sum of doubles, independent of the order of the terms: a fixed-point accumulator wide
// enough for every finite double (a "superaccumulator", Kulisch & Miranker 1981; the chunked form of Neal 2015,
// arXiv:1505.05571). The result is the exact sum rounded once, so it has the same bits however the terms are split
// over threads and processes and in whatever order they arrive (floating-point addition is not associative;
// integer addition is).
//
// Every finite double is M 2^(e - 1074) with M an integer below 2^53 and e = max(E, 1) - 1 in [0, 2045] (E its
// biased exponent). The accumulator holds sum_k c_k 2^(32 k - 1074) with 67 signed 64-bit chunks c_k: a term adds
// the 32-bit pieces of M 2^(e mod 32) to the chunks from e / 32 up. A chunk takes 2^31 such additions before it
// could overflow; normalize() carries every chunk's bits above 32 into the next one (arithmetic shift, so negative
// sums carry too) long before that, after which every chunk but the top one is in [0, 2^32): a canonical form,
// the same for any order of the same terms. value() rounds the canonical form to a double (the top 128 bits, the
// rest as a sticky bit: within one unit in the last place of the exact sum). Infinities and NaN are kept aside and
// give inf or NaN as IEEE addition would.
// Cost: a few integer operations per term, 536 bytes per accumulator.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace cdmpm {

class ExactSum {
 public:
  static constexpr int kChunks = 67;

  void add(double x) {
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int E = static_cast<int>((bits >> 52) & 0x7FF);
    if (E == 0x7FF) {  // infinity or NaN
      if (std::isnan(x)) nan_ = true;
      else (x > 0 ? pos_inf_ : neg_inf_) = true;
      return;
    }
    uint64_t M = bits & ((uint64_t(1) << 52) - 1);
    if (E != 0) M |= uint64_t(1) << 52;
    if (M == 0) return;
    const int e = (E == 0 ? 1 : E) - 1;
    const int k = e / 32, s = e % 32;
    const unsigned __int128 v = static_cast<unsigned __int128>(M) << s;  // at most 84 bits
    const int64_t c0 = static_cast<int64_t>(v & 0xFFFFFFFFu), c1 = static_cast<int64_t>((v >> 32) & 0xFFFFFFFFu),
                  c2 = static_cast<int64_t>(v >> 64);
    if (bits >> 63) c_[k] -= c0, c_[k + 1] -= c1, c_[k + 2] -= c2;
    else c_[k] += c0, c_[k + 1] += c1, c_[k + 2] += c2;
    if (++adds_ == kAddsBeforeCarry) normalize();
  }

  ExactSum& operator+=(const ExactSum& o) {
    ExactSum b = o;
    b.normalize();
    normalize();
    for (int k = 0; k < kChunks; ++k) c_[k] += b.c_[k];
    nan_ |= b.nan_, pos_inf_ |= b.pos_inf_, neg_inf_ |= b.neg_inf_;
    normalize();
    return *this;
  }

  // The canonical form: chunks 0 .. kChunks - 2 in [0, 2^32), the top chunk signed.
  void normalize() {
    for (int k = 0; k + 1 < kChunks; ++k) {
      const int64_t carry = c_[k] >> 32;  // arithmetic shift: floor(c / 2^32)
      c_[k] -= carry * (int64_t(1) << 32);
      c_[k + 1] += carry;
    }
    adds_ = 0;
  }

  // The exact sum rounded to a double.
  double value() const {
    if (nan_ || (pos_inf_ && neg_inf_)) return std::numeric_limits<double>::quiet_NaN();
    if (pos_inf_) return std::numeric_limits<double>::infinity();
    if (neg_inf_) return -std::numeric_limits<double>::infinity();
    ExactSum a = *this;
    a.normalize();
    const bool negative = a.c_[kChunks - 1] < 0;
    if (negative) a.negate();
    int top = kChunks - 1;
    while (top >= 0 && a.c_[top] == 0) --top;
    if (top < 0) return 0.0;
    // The top four chunks (128 bits), the chunks below them as a sticky bit.
    const int low = top >= 3 ? top - 3 : 0;
    unsigned __int128 m = 0;
    for (int k = top; k >= low; --k) m = (m << 32) | static_cast<uint64_t>(a.c_[k]);
    bool sticky = false;
    for (int k = low - 1; k >= 0 && !sticky; --k) sticky = a.c_[k] != 0;
    if (sticky) m |= 1;  // below the 53 bits kept as long as m has 64 or more (the top chunk is non-zero)
    const double r = std::ldexp(static_cast<double>(m), 32 * low - 1074);
    return negative ? -r : r;
  }

  // The chunks, for sending between processes (parallel/reduction.h).
  const std::array<int64_t, kChunks>& chunks() const { return c_; }
  std::array<int64_t, kChunks>& chunks() { return c_; }
  uint8_t flags() const { return uint8_t(nan_) | uint8_t(pos_inf_) << 1 | uint8_t(neg_inf_) << 2; }
  void set_flags(uint8_t f) { nan_ = f & 1, pos_inf_ = f & 2, neg_inf_ = f & 4; }

 private:
  static constexpr int kAddsBeforeCarry = 1 << 30;

  // Two's complement over the chunks of a canonical form (then again canonical, with a non-negative top).
  void negate() {
    for (int k = 0; k < kChunks; ++k) c_[k] = -c_[k];
    normalize();
  }

  std::array<int64_t, kChunks> c_{};
  int adds_ = 0;
  bool nan_ = false, pos_inf_ = false, neg_inf_ = false;
};

// `count` sums over q in [0, n): f(q, acc) adds particle q's terms to acc[0 .. count - 1]. OpenMP threads each
// fill their own accumulators, which are then added (exact, so in any order): the sums do not depend on the
// number of threads.
template <class F>
std::vector<ExactSum> exact_sums(size_t count, size_t n, F&& f) {
  std::vector<ExactSum> total(count);
#pragma omp parallel
  {
    std::vector<ExactSum> acc(count);
#pragma omp for schedule(static) nowait
    for (size_t q = 0; q < n; ++q) f(q, acc.data());
#pragma omp critical(cdmpm_exact_sums)
    for (size_t i = 0; i < count; ++i) total[i] += acc[i];
  }
  return total;
}

}  // namespace cdmpm
