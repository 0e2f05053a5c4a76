// failure_plane.h - geometry of a calving failure from the block that broke off: the failure width and the dip of
// the failure plane, the two numbers field studies report for a cliff collapse (Luethi & Vieli 2016 for Eqip
// Sermia: a failure width of 50-60 m at the glacier surface and a failure plane dipping 45-60 degrees).
//
// Input: the positions of the block's particles (the first iceberg, probe/icebergs.h, at the sample where it is
// first detected, so it has barely moved), the grid spacing dx, the flow axis a and the side of the glacier
// (-1: the glacier lies towards -a, the usual case of a front facing +a; +1: towards +a). The vertical axis is
// v = dim - 1; in 3D the remaining axis c runs along the front.
//   Failure surface. The particles are binned into rows of height dx (and, in 3D, into strips of width dx along c).
//   In each bin the block's edge facing the glacier is e = min x_a (glacier at -a) or max x_a (at +a): that edge
//   is the crack the block came off. A least-squares plane e = e0 + b z (+ c y) through the bins' (z, y, e), z and
//   y the bins' mean particle heights and cross positions, gives the dip from horizontal, angle = atan(1 / |b|)
//   (90 degrees for a vertical crack, b = 0).
//   Only the new fracture. A block bounded above by a crevasse has two kinds of glacier-facing edge: the crevasse's
//   wall, a free surface before the event, and below it the crack that broke (Luethi & Vieli 2016 measure the dip
//   of the latter). Given the positions of the broken ice (damage at or above the iceberg threshold), a bin enters
//   the fit only if broken ice lies beyond its edge, within reach = 2 dx along the flow (in its own row or the
//   next one, and strip): the edge faces the broken band, not air or water. If fewer than two bins do, the whole
//   edge is fitted (the block broke with no band left beside it) and rows_fitted says how many rows were.
//   Failure width. The along-flow extent of the block's top: the particles within 2 dx of the block's highest
//   particle (in 3D: per strip, then the median over strips), max x_a - min x_a + spacing, so that a row of n
//   particles at spacing h has width n h as the iceberg lengths of icebergs.h.
// Both are NaN if the block has fewer than two rows (no plane can be fitted).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "core/types.h"

namespace cdmpm {

struct FailureGeometry {
  double width = std::numeric_limits<double>::quiet_NaN();  // [m]
  double angle = std::numeric_limits<double>::quiet_NaN();  // dip of the failure plane from horizontal [degrees]
  size_t rows_fitted = 0;                                    // bins in the fit
  bool band_only = false;                                    // the fit kept only the bins facing broken ice
};

// x: the block's particle positions; glacier_side: -1 or +1 along flow_axis (see above); broken: the positions of
// the broken ice (may be empty: the whole edge is fitted).
template <int dim>
FailureGeometry failure_geometry(const std::vector<Vec<dim>>& x, Real dx, Real spacing, int flow_axis, int glacier_side,
                                 const std::vector<Vec<dim>>& broken = {}) {
  FailureGeometry g;
  if (x.size() < 2 || dx <= 0) return g;
  const int v = dim - 1, a = flow_axis;
  const int c = dim == 3 ? 3 - v - a : -1;  // the axis along the front (3D only)
  const auto strip_of = [&](const Vec<dim>& p) { return c < 0 ? int64_t(0) : static_cast<int64_t>(std::floor(p[c] / dx)); };

  // Bins keyed by (strip, row), in a std::map so the sums run in a fixed order.
  struct Bin {
    double edge = 0, z = 0, y = 0;
    size_t n = 0;
  };
  std::map<std::pair<int64_t, int64_t>, Bin> bins;
  double top = -std::numeric_limits<double>::infinity();
  for (const auto& p : x) {
    top = std::max(top, static_cast<double>(p[v]));
    Bin& b = bins[{strip_of(p), static_cast<int64_t>(std::floor(p[v] / dx))}];
    const double e = p[a];
    b.edge = b.n == 0 ? e : (glacier_side < 0 ? std::min(b.edge, e) : std::max(b.edge, e));
    b.z += p[v];
    b.y += c < 0 ? 0.0 : static_cast<double>(p[c]);
    ++b.n;
  }

  // The bins whose edge faces broken ice: a broken particle beyond the edge (on the glacier's side) within reach,
  // in the bin's row or the next one.
  if (!broken.empty()) {
    const double reach = 2 * static_cast<double>(dx);
    std::map<std::pair<int64_t, int64_t>, bool> faces;
    for (const auto& [key, b] : bins) faces[key] = false;
    for (const auto& p : broken) {
      const int64_t row = static_cast<int64_t>(std::floor(p[v] / dx));
      for (int64_t r = row - 1; r <= row + 1; ++r) {
        const auto it = bins.find({strip_of(p), r});
        if (it == bins.end()) continue;
        const double beyond = glacier_side < 0 ? it->second.edge - p[a] : p[a] - it->second.edge;
        if (beyond >= 0 && beyond <= reach) faces[it->first] = true;
      }
    }
    size_t facing = 0;
    for (const auto& [key, f] : faces) facing += f;
    if (facing >= 2) {
      for (const auto& [key, f] : faces)
        if (!f) bins.erase(key);
      g.band_only = true;
    }
  }
  g.rows_fitted = bins.size();

  // Least squares e = e0 + b z (+ cy y): normal equations in the centred variables.
  const double nb = static_cast<double>(bins.size());
  double mz = 0, my = 0, me = 0;
  for (auto& [key, b] : bins) {
    b.z /= b.n;
    b.y /= b.n;
    mz += b.z / nb;
    my += b.y / nb;
    me += b.edge / nb;
  }
  double szz = 0, szy = 0, syy = 0, sze = 0, sye = 0;
  for (const auto& [key, b] : bins) {
    const double dz = b.z - mz, dy = b.y - my, de = b.edge - me;
    szz += dz * dz;
    szy += dz * dy;
    syy += dy * dy;
    sze += dz * de;
    sye += dy * de;
  }
  double slope = std::numeric_limits<double>::quiet_NaN();
  if (c < 0 || syy <= 0) {
    if (szz > 0) slope = sze / szz;
  } else {
    const double det = szz * syy - szy * szy;
    if (det > 0) slope = (sze * syy - sye * szy) / det;
  }
  if (std::isfinite(slope)) g.angle = std::atan2(1.0, std::abs(slope)) * 180.0 / M_PI;

  // Width of the top: per strip, the extent of the particles within 2 dx of the block's top.
  std::map<int64_t, std::pair<double, double>> extent;  // strip -> (min, max) along flow
  for (const auto& p : x) {
    if (p[v] < top - 2 * dx) continue;
    auto [it, fresh] = extent.try_emplace(strip_of(p), p[a], p[a]);
    if (!fresh) it->second = {std::min(it->second.first, double(p[a])), std::max(it->second.second, double(p[a]))};
  }
  std::vector<double> widths;
  for (const auto& [strip, mm] : extent) widths.push_back(mm.second - mm.first + spacing);
  std::sort(widths.begin(), widths.end());
  if (std::isfinite(g.angle) && !widths.empty()) g.width = widths[widths.size() / 2];
  return g;
}

}  // namespace cdmpm
