// powers.h - the powers of J that the constitutive models evaluate per particle and step, without std::pow.
//
// std::pow costs tens of nanoseconds (it was a fifth of a water step); the exponents that occur are either
// integers (the Tait exponent gamma = 7) or -2/dim, 1/dim, which square roots and cube roots give exactly
// to rounding.
#pragma once

#include <cmath>

#include "core/types.h"

namespace cdmpm {

// x^n for an integer n >= 0 by repeated squaring.
inline Real int_pow(Real x, int n) {
  Real r = 1;
  while (n > 0) {
    if (n & 1) r *= x;
    x *= x;
    n >>= 1;
  }
  return r;
}

// x^e; by repeated squaring when e is an integer of modest size, std::pow otherwise.
inline Real real_pow(Real x, Real e) {
  if (std::abs(e) <= 32) {
    const int n = static_cast<int>(e);  // truncation; e is an integer iff it equals n
    if (static_cast<Real>(n) == e) return n >= 0 ? int_pow(x, n) : int_pow(Real(1) / x, -n);
  }
  return std::pow(x, e);
}

// J^(1/dim).
template <int dim>
inline Real root_dim(Real J) {
  if constexpr (dim == 2) return std::sqrt(J);
  else return std::cbrt(J);
}

// J^(-2/dim).
template <int dim>
inline Real pow_minus_two_over_dim(Real J) {
  if constexpr (dim == 2) return Real(1) / J;
  else {
    const Real c = std::cbrt(J);
    return Real(1) / (c * c);
  }
}

}  // namespace cdmpm
