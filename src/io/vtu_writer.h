// vtu_writer.h - particle output for ParaView: VTK XML UnstructuredGrid (.vtu) files and .pvd
// time-series collections.
//
// Each .vtu holds n points with one VTK_VERTEX cell per point, plus per-point data arrays and optional
// <FieldData> (the frame time and string metadata). Array data is stored in binary "appended" raw
// encoding (header_type UInt64, little-endian), either uncompressed (every block is a UInt64 byte count
// followed by the raw values) or compressed with zlib (compressor="vtkZLibDataCompressor": every block
// is the header [number of blocks, uncompressed block size, uncompressed size of a partial last block
// or 0, compressed size of each block] followed by the zlib streams of the blocks). Files are written to
// `path + ".tmp"` and then renamed, so a reader never sees a half-written file.
// Format reference: VTK file formats documentation ("XML File Formats": VTKFile header_type and
// compressor attributes, FieldData, AppendedData, and the compressed data header).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cdmpm {

// One per-point data array. Exactly one of the vectors is non-empty; size == n_points * components.
// (With n_points == 0 all may be empty; the array is then written as Float32.)
struct VtuField {
  std::string name;
  int components = 1;  // 1 (scalar), 3 (vector; 2D data is padded with 0 by the caller) or 9 (3x3 tensor)
  std::vector<float> f32;
  std::vector<double> f64;
  std::vector<int32_t> i32;
  std::vector<int64_t> i64 = {};  // e.g. 64-bit particle ids (the initializer keeps 5-member aggregates quiet)
};

enum class VtuCompression { None, ZLib };
enum class VtuReal { Float64, Float32 };

// A <FieldData> array of strings (VTK type="String", one tuple per string; in the appended block each
// string is followed by a NUL byte). Names must not contain NUL bytes.
struct VtuStrings {
  std::string name;
  std::vector<std::string> values;
};

// The name of the field-data string array that lists material names: tuple i is the name of the material
// with id i (the per-point "material" array holds ids).
inline constexpr const char* kVtuMaterialNames = "material_names";
// The name of the field-data Float64 array holding the frame time (ParaView reads it as the time).
inline constexpr const char* kVtuTimeValue = "TimeValue";

struct VtuOptions {
  VtuCompression compression = VtuCompression::None;
  int zlib_level = 1;                 // 1 (fastest) .. 9 (smallest); only with ZLib
  uint64_t block_bytes = 1u << 16;    // uncompressed bytes per compressed block (> 0); only with ZLib
  VtuReal positions = VtuReal::Float64;  // Float32 halves the Points array (rounded to nearest)
  std::optional<double> time;         // written as FieldData TimeValue (one Float64 tuple) when set
  std::vector<VtuStrings> metadata;   // FieldData string arrays, e.g. {kVtuMaterialNames, {"water", "ice"}}
};

// Writes a .vtu file of n points with VTK_VERTEX cells (one per point). `points` has 3*n entries
// (x,y,z; z=0 in 2D). With default options the file is the uncompressed Float64-positions layout without
// FieldData. With ZLib the blocks are compressed in parallel (OpenMP); the bytes do not depend on the
// thread count. Writes to `path + ".tmp"` then renames. Throws std::invalid_argument on malformed input
// and std::runtime_error naming the path on I/O failure.
void write_vtu(const std::string& path, const std::vector<double>& points, const std::vector<VtuField>& fields,
               const VtuOptions& options = {});

// Writes a .pvtu (VTK XML PUnstructuredGrid) that joins the .vtu pieces `pieces` (file names relative to the
// .pvtu's folder, each written by write_vtu with the same fields and options) into one data set: the point arrays
// of `fields` (name, type, components; their values are not read), the positions' precision and the compressor of
// `options`. Atomically too. Format reference: VTK file formats, "Parallel File Formats".
void write_pvtu(const std::string& path, const std::vector<std::string>& pieces, const std::vector<VtuField>& fields,
                const VtuOptions& options);

// Writes a .pvd collection listing (time, file name relative to the pvd's folder) pairs, atomically too.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

}  // namespace cdmpm
