// height_field.h - a regular grid of heights h[j][i] at (ox + i sx, oy + j sy), bilinearly interpolated and clamped
// at its edges, with its gradient: the 3D bathymetry (boundary/bathymetry.cpp) and the heightfield shape
// (shape/heightfield.h) read their terrain files (terrain/terrain_file.h) into it.
#pragma once

#include <algorithm>
#include <vector>

namespace cdmpm {

struct HeightField {
  double ox = 0, oy = 0, sx = 1, sy = 1;
  std::vector<std::vector<double>> h;  // at least 2 x 2

  // The bilinear height at (x, y) and its gradient.
  double at(double x, double y, double& dhdx, double& dhdy) const {
    const int nx = static_cast<int>(h[0].size()), ny = static_cast<int>(h.size());
    const double u = std::clamp((x - ox) / sx, 0.0, nx - 1.0), w = std::clamp((y - oy) / sy, 0.0, ny - 1.0);
    const int i = std::min(static_cast<int>(u), nx - 2), j = std::min(static_cast<int>(w), ny - 2);
    const double fu = u - i, fw = w - j;
    const double h00 = h[j][i], h10 = h[j][i + 1], h01 = h[j + 1][i], h11 = h[j + 1][i + 1];
    const double v = (1 - fw) * ((1 - fu) * h00 + fu * h10) + fw * ((1 - fu) * h01 + fu * h11);
    dhdx = ((1 - fw) * (h10 - h00) + fw * (h11 - h01)) / sx;
    dhdy = ((1 - fu) * (h01 - h00) + fu * (h11 - h10)) / sy;
    return v;
  }
  double at(double x, double y) const {
    double gx, gy;
    return at(x, y, gx, gy);
  }
};

}  // namespace cdmpm
