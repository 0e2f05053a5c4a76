// simplex_noise.h - seeded 2D simplex noise (Perlin 2001, "Noise hardware"; Gustavson 2005, "Simplex noise
// demystified"), the random field behind surface crevasses (shape/crevasse_field.h).
//
// The plane is skewed onto a lattice of equilateral triangles: a point p lies in the simplex with corners
// c0 = floor(p + F (px + py)) unskewed by G, F = (sqrt(3) - 1) / 2, G = (3 - sqrt(3)) / 6 (Gustavson, eqs. of
// section "Simplex noise in 2D"). Each corner c_k with offset d_k = p - c_k contributes
//   n_k = max(0, 1/2 - |d_k|^2)^4 (g_k . d_k),
// g_k one of 8 gradients (+-1, +-1), (+-1, 0), (0, +-1) picked by hashing the corner's lattice indices through a
// permutation of 0..255; the noise is 70 (n_0 + n_1 + n_2), in [-1, 1] (tests/unit/test_crevasses.cpp).
// A corner reaches no point farther than sqrt(1/2) from it, so points more than sqrt(2) apart share no corner.
//
// The seed shuffles the permutation (Fisher-Yates) with splitmix64 (Steele, Lea & Flood 2014), a fixed integer
// recurrence: the same seed gives the same field bit for bit on every machine, compiler and thread count (no
// std:: distribution, whose output differs between standard libraries). The noise is a pure function of the
// point: evaluation order and threads do not matter. The 8 gradients are used equally often (256 = 32 x 8)
// and come in opposite pairs, so the noise has mean zero over its 256-periodic lattice.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace cdmpm {

// splitmix64: the next 64-bit output of the generator with state `s` (which it advances).
inline uint64_t splitmix64(uint64_t& s) {
  uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

class SimplexNoise {
 public:
  explicit SimplexNoise(uint64_t seed) {
    std::iota(perm_.begin(), perm_.end(), 0);
    uint64_t state = seed;
    for (int i = 255; i > 0; --i) {
      const auto j = static_cast<int>(splitmix64(state) % static_cast<uint64_t>(i + 1));
      std::swap(perm_[i], perm_[j]);
    }
  }

  // The noise at (x, y), in [-1, 1].
  double operator()(double x, double y) const {
    const double F = 0.5 * (std::sqrt(3.0) - 1), G = (3 - std::sqrt(3.0)) / 6;
    const double s = (x + y) * F;
    const double i = std::floor(x + s), j = std::floor(y + s);
    const double t = (i + j) * G;
    const double x0 = x - (i - t), y0 = y - (j - t);  // offset from the first corner
    const int i1 = x0 > y0 ? 1 : 0, j1 = 1 - i1;      // second corner: lower or upper triangle
    const double x1 = x0 - i1 + G, y1 = y0 - j1 + G;
    const double x2 = x0 - 1 + 2 * G, y2 = y0 - 1 + 2 * G;
    const int ii = static_cast<int>(i - 256 * std::floor(i / 256)), jj = static_cast<int>(j - 256 * std::floor(j / 256));
    return 70 * (corner(hash(ii, jj), x0, y0) + corner(hash(ii + i1, jj + j1), x1, y1) +
                 corner(hash(ii + 1, jj + 1), x2, y2));
  }

 private:
  int hash(int i, int j) const { return perm_[(i + perm_[j & 255]) & 255]; }
  static double corner(int h, double x, double y) {
    const double t = 0.5 - x * x - y * y;
    if (t <= 0) return 0;
    static constexpr std::array<std::array<double, 2>, 8> g = {
        {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
    const auto& gk = g[h & 7];
    return t * t * t * t * (gk[0] * x + gk[1] * y);
  }
  std::array<int, 256> perm_{};
};

}  // namespace cdmpm
