// vtu_writer.h - particle output for ParaView: VTK XML UnstructuredGrid (.vtu) files and .pvd
// time-series collections.
//
// Each .vtu holds n points with one VTK_VERTEX cell per point, plus per-point data arrays. Array data is
// stored in binary "appended" raw encoding (header_type UInt64, little-endian): every block is a UInt64
// byte count followed by the raw values, written with one bulk write per array, so millions of points
// are cheap to dump. Files are written to `path + ".tmp"` and then renamed, so a reader never sees a
// half-written file. Format reference: VTK file formats documentation ("XML File Formats").
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cdmpm {

// One per-point data array. Exactly one of the vectors is non-empty; size == n_points * components.
// (With n_points == 0 all may be empty; the array is then written as Float32.)
struct VtuField {
  std::string name;
  int components = 1;  // 1 (scalar) or 3 (vector; 2D data is padded with 0 by the caller)
  std::vector<float> f32;
  std::vector<double> f64;
  std::vector<int32_t> i32;
};

// Writes a .vtu file of n points with VTK_VERTEX cells (one per point). `points` has 3*n entries
// (x,y,z; z=0 in 2D), stored as Float64. Writes to `path + ".tmp"` then renames. Throws
// std::invalid_argument on malformed input and std::runtime_error naming the path on I/O failure.
void write_vtu(const std::string& path, const std::vector<double>& points, const std::vector<VtuField>& fields);

// Writes a .pvd collection listing (time, file name relative to the pvd's folder) pairs, atomically too.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace cdmpm
