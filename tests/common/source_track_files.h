// source_track_files.h - source-track files for the tests (io/source_track.h): a track of a field the
// interpolation represents exactly, written into a test's folder.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.h"

namespace cdmpm {

// A track of u = t (a + b X + c Z) per component on an nx x nz lattice at (x0 + i h, z0 + j h), records at `times`;
// fill 1 where X <= fill_below, else 0.
inline std::string linear_track(int nx, int nz, double x0, double z0, double h, const std::vector<double>& times,
                         const double (&a)[2], const double (&b)[2], const double (&c)[2], double fill_below = 1e300) {
  std::ostringstream s;
  s.precision(17);
  s << "# a test track\ncdmpm_source_track 1\nlattice " << nx << " " << nz << " " << x0 << " " << z0 << " " << h << "\n";
  s << "fill";
  for (int j = 0; j < nz; ++j)
    for (int i = 0; i < nx; ++i) s << " " << (x0 + i * h <= fill_below ? 1 : 0);
  s << "\ntimes " << times.size() << "\n";
  for (double t : times) {
    s << t;
    for (int j = 0; j < nz; ++j)
      for (int i = 0; i < nx; ++i)
        for (int k = 0; k < 2; ++k) s << " " << t * (a[k] + b[k] * (x0 + i * h) + c[k] * (z0 + j * h));
    s << "\n";
  }
  return s.str();
}

inline std::string write_file(const testing::TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir / name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace cdmpm
