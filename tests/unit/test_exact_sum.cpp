// test_exact_sum.cpp - the order-independent exact sum (math/exact_sum.h): cancellation that rounds away in double
// arithmetic, sums whose exact value is known, the extremes of the double range, infinities and NaN, the same bits
// for the same terms in any order or split (as threads and processes split them), and exact_sums over threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "math/exact_sum.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace cdmpm {
namespace {

double exact(const std::vector<double>& terms) {
  ExactSum s;
  for (double t : terms) s.add(t);
  return s.value();
}

TEST(ExactSum, KeepsWhatDoubleAdditionRoundsAway) {
  EXPECT_EQ(exact({1e16, 1.0, -1e16}), 1.0);           // double arithmetic gives 0
  EXPECT_EQ(exact({1.0, 1e-30, -1.0}), 1e-30);
  EXPECT_EQ(exact({DBL_MAX, DBL_MAX, -DBL_MAX}), DBL_MAX);  // no overflow on the way
  EXPECT_EQ(exact({DBL_TRUE_MIN, DBL_TRUE_MIN}), 2 * DBL_TRUE_MIN);
  EXPECT_EQ(exact({-3.5, 1.25}), -2.25);
  EXPECT_EQ(exact({}), 0.0);
  EXPECT_EQ(exact({0.1, -0.1}), 0.0);
  // 0.1 ten times: the exact sum of the ten doubles nearest 0.1, rounded once, is 1.0 (naively 0.9999999999999999).
  EXPECT_EQ(exact(std::vector<double>(10, 0.1)), 1.0);
}

TEST(ExactSum, KnownSumsOfIntegersTimesPowersOfTwo) {
  // Terms k 2^-40 for k = -N .. N+1 and big terms 2^60 ± 1 that cancel: the exact sum is (N + 1) 2^-40.
  std::vector<double> t;
  const int N = 100000;
  for (int k = -N; k <= N + 1; ++k) t.push_back(std::ldexp(double(k), -40));
  t.push_back(std::ldexp(1.0, 60) + 0.0);
  t.push_back(-std::ldexp(1.0, 60));
  EXPECT_EQ(exact(t), std::ldexp(double(N + 1), -40));
}

TEST(ExactSum, InfinitiesAndNaNAsIeeeAddition) {
  const double inf = INFINITY;
  EXPECT_EQ(exact({1.0, inf}), inf);
  EXPECT_EQ(exact({-inf, 5.0}), -inf);
  EXPECT_TRUE(std::isnan(exact({inf, -inf})));
  EXPECT_TRUE(std::isnan(exact({1.0, NAN})));
}

TEST(ExactSum, SameBitsInAnyOrderAndSplit) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mant(-1, 1);
  std::uniform_int_distribution<int> expo(-60, 60);
  std::vector<double> t(20000);
  for (double& x : t) x = std::ldexp(mant(rng), expo(rng));
  const double forward = exact(t);
  std::reverse(t.begin(), t.end());
  EXPECT_EQ(exact(t), forward);
  std::shuffle(t.begin(), t.end(), rng);
  EXPECT_EQ(exact(t), forward);
  // Split in three parts (three processes), added part by part in two orders.
  ExactSum a, b, c;
  for (size_t i = 0; i < t.size(); ++i) (i % 3 == 0 ? a : i % 3 == 1 ? b : c).add(t[i]);
  ExactSum abc = a, cba = c;
  abc += b, abc += c;
  cba += b, cba += a;
  EXPECT_EQ(abc.value(), forward);
  EXPECT_EQ(cba.value(), forward);
  // Double arithmetic in these orders differs in the last bits (what the exact sum is for).
  double naive_forward = 0, naive_sorted = 0;
  for (double x : t) naive_forward += x;
  std::sort(t.begin(), t.end());
  for (double x : t) naive_sorted += x;
  EXPECT_NE(naive_forward, naive_sorted);
}

TEST(ExactSum, ExactSumsDoNotDependOnTheThreadCount) {
  std::vector<double> t(100000);
  for (size_t q = 0; q < t.size(); ++q) t[q] = std::sin(double(q)) * std::pow(10.0, double(q % 17) - 8);
  auto sums = [&] {
    return exact_sums(2, t.size(), [&](size_t q, ExactSum* acc) {
      acc[0].add(t[q]);
      acc[1].add(t[q] * t[q]);
    });
  };
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::vector<ExactSum> one = sums();
  omp_set_num_threads(4);
  const std::vector<ExactSum> four = sums();
  omp_set_num_threads(threads);
#else
  const std::vector<ExactSum> one = sums(), four = sums();
#endif
  EXPECT_EQ(one[0].value(), four[0].value());
  EXPECT_EQ(one[1].value(), four[1].value());
  EXPECT_EQ(one[0].value(), exact(t));
}

}  // namespace
}  // namespace cdmpm
