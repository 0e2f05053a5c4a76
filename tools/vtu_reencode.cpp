// vtu_reencode.cpp - re-encodes existing cdmpm frames with io/vtu_writer in several layouts (uncompressed,
// zlib at several levels and block sizes, Float32 positions, 1 or more threads) and prints the bytes per
// particle per frame and the write time per frame of each, to choose the frame output options.
//   build/tests/vtu_reencode SCRATCH_DIR frame.vtu...     (target vtu_reencode, not built by default)
//   build/tests/vtu_reencode --sample OUT.vtu TIME frame.vtu [MATERIAL_NAME...]
//     writes one frame zlib-compressed with Float32 positions, an Int64 "id" field (2^32 + index), the
//     TimeValue TIME and the material names as field data: a file to open in ParaView.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/vtu_writer.h"
#include "vtu_reader.h"

namespace fs = std::filesystem;
using namespace cdmpm;

namespace {

struct Frame {
  std::vector<double> points;
  std::vector<VtuField> fields;
};

Frame load(const fs::path& file) {
  const testing::ParsedVtu vtu(file);
  const size_t n = vtu.points();
  Frame f{vtu.array<double>("Points", 3 * n), {}};
  for (const std::string& name : vtu.point_data_names()) {
    VtuField v{name, std::stoi(vtu.attr(name, "NumberOfComponents")), {}, {}, {}};
    const std::string type = vtu.attr(name, "type");
    const size_t count = n * v.components;
    if (type == "Float32") v.f32 = vtu.array<float>(name, count);
    if (type == "Float64") v.f64 = vtu.array<double>(name, count);
    if (type == "Int32") v.i32 = vtu.array<int32_t>(name, count);
    if (type == "Int64") v.i64 = vtu.array<int64_t>(name, count);
    f.fields.push_back(std::move(v));
  }
  return f;
}

struct Layout {
  const char* label;
  VtuOptions options;
  int threads;
};

std::vector<Layout> layouts() {
  auto z = [](int level, uint64_t block, VtuReal pos) {
    VtuOptions o;
    o.compression = VtuCompression::ZLib, o.zlib_level = level, o.block_bytes = block, o.positions = pos;
    return o;
  };
  VtuOptions raw32;
  raw32.positions = VtuReal::Float32;
  const int all = omp_get_max_threads();
  return {{"raw, Float64 positions (before)", {}, 1},
          {"raw, Float32 positions", raw32, 1},
          {"zlib 1, 32 KiB, Float64", z(1, 1u << 15, VtuReal::Float64), 1},
          {"zlib 1, 64 KiB, Float64", z(1, 1u << 16, VtuReal::Float64), 1},
          {"zlib 1, 64 KiB, Float64, all threads", z(1, 1u << 16, VtuReal::Float64), all},
          {"zlib 6, 64 KiB, Float64", z(6, 1u << 16, VtuReal::Float64), 1},
          {"zlib 6, 64 KiB, Float64, all threads", z(6, 1u << 16, VtuReal::Float64), all},
          {"zlib 9, 64 KiB, Float64", z(9, 1u << 16, VtuReal::Float64), 1},
          {"zlib 1, 64 KiB, Float32", z(1, 1u << 16, VtuReal::Float32), 1},
          {"zlib 1, 64 KiB, Float32, all threads", z(1, 1u << 16, VtuReal::Float32), all},
          {"zlib 6, 64 KiB, Float32", z(6, 1u << 16, VtuReal::Float32), 1}};
}

int write_sample(int argc, char** argv) {
  Frame f = load(argv[4]);
  const size_t n = f.points.size() / 3;
  VtuField id{"id", 1, {}, {}, {}};
  for (size_t q = 0; q < n; ++q) id.i64.push_back((int64_t{1} << 32) + int64_t(q));
  f.fields.push_back(std::move(id));
  VtuOptions o;
  o.compression = VtuCompression::ZLib, o.positions = VtuReal::Float32, o.time = std::stod(argv[3]);
  o.metadata = {{kVtuMaterialNames, std::vector<std::string>(argv + 5, argv + argc)}};
  write_vtu(argv[2], f.points, f.fields, o);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 5 && std::string(argv[1]) == "--sample") return write_sample(argc, argv);
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SCRATCH_DIR frame.vtu...\n", argv[0]);
    return 2;
  }
  const fs::path scratch = argv[1];
  fs::create_directories(scratch);
  std::vector<Frame> frames;
  size_t particles = 0;
  for (int i = 2; i < argc; ++i) frames.push_back(load(argv[i])), particles += frames.back().points.size() / 3;
  std::printf("%zu frames, %zu particle-frames, %d threads available\n", frames.size(), particles, omp_get_max_threads());
  std::printf("%-40s %14s %12s %14s\n", "layout", "bytes/particle", "ratio", "ms/frame (min of 3)");
  double raw_bytes = 0;
  for (const Layout& L : layouts()) {
    omp_set_num_threads(L.threads);
    double bytes = 0, ms = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
      const fs::path out = scratch / ("frame_" + std::to_string(i) + ".vtu");
      double best = 1e300;
      for (int rep = 0; rep < 3; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        write_vtu(out.string(), frames[i].points, frames[i].fields, L.options);
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      ms += best;
      bytes += double(fs::file_size(out));
    }
    if (raw_bytes == 0) raw_bytes = bytes;
    std::printf("%-40s %14.2f %12.3f %14.3f\n", L.label, bytes / double(particles), bytes / raw_bytes,
                ms / double(frames.size()));
  }
  fs::remove_all(scratch);
  return 0;
}
