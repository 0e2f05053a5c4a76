// bed_height.h - the height of the bed under a horizontal position: the top of the solid that rises from the
// domain's floor there (bathymetry, a half-plane or a box standing on the floor), found through the boundaries'
// is_solid alone, so it serves every boundary type. 0 (the floor) where nothing solid stands on it. The solid
// is assumed to be one connected piece above the floor in each column (terrain); an overhang is read up to
// its first gap.
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "boundary/boundary.h"

namespace cdmpm {

// `horizontal` holds dim - 1 coordinates. Accurate to 1e-9 of the domain's height.
template <int dim>
double bed_height(const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries, const Vec<dim>& domain_size,
                  const std::vector<double>& horizontal) {
  constexpr int up = vertical_axis<dim>;
  Vec<dim> x;
  for (int a = 0; a < dim - 1; ++a) x[a] = static_cast<Real>(horizontal[a]);
  auto solid = [&](double z) {
    x[up] = static_cast<Real>(z);
    return any_solid(boundaries, x);
  };
  const double top = domain_size[up], eps = 1e-9 * top;
  if (!solid(eps)) return 0;
  // March up in steps of 1/256 of the height to the first free point, then bisect.
  double lo = eps, hi = eps;
  while (true) {
    lo = hi;
    hi = std::min(hi + top / 256, top);
    if (!solid(hi)) break;
    if (hi >= top) return top;
  }
  for (int k = 0; k < 60 && hi - lo > eps; ++k) {
    const double mid = 0.5 * (lo + hi);
    (solid(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace cdmpm
