// test_vtu_writer.cpp - unit tests for the .vtu / .pvd writers: files are parsed back here (XML header
// offsets + appended raw blocks, uncompressed or zlib-compressed) and every byte count and value is
// checked exactly.
#include "io/vtu_writer.h"

#include "vtu_reader.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace cdmpm;

using cdmpm::testing::ParsedVtu;
using cdmpm::testing::read_file;

namespace {

class VtuWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("cdmpm_vtu_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(VtuWriterTest, RoundTripsPointsAndFields) {
  const std::vector<double> points = {0.1, 0.2, 0.0, -1.5, 2.25, 0.0, 1e300, -3.0, 1.0 / 3.0};
  std::vector<VtuField> fields(3);
  fields[0].name = "velocity";
  fields[0].components = 3;
  fields[0].f32 = {1.f, 2.f, 0.f, -0.5f, 0.25f, 0.f, 3.5f, 1e-7f, 0.f};
  fields[1].name = "mass";
  fields[1].f64 = {0.1, 2.0 / 3.0, -7.0};
  fields[2].name = "material_id";
  fields[2].i32 = {0, -2, 2147483647};

  const fs::path file = dir / "frame.vtu";
  write_vtu(file.string(), points, fields);
  ASSERT_TRUE(fs::exists(file));
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));

  const ParsedVtu vtu(file);
  const std::string h = vtu.header();
  EXPECT_NE(h.find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                   "header_type=\"UInt64\">"),
            std::string::npos);
  EXPECT_NE(h.find("NumberOfPoints=\"3\" NumberOfCells=\"3\""), std::string::npos);

  EXPECT_EQ(vtu.attr("Points", "type"), "Float64");
  EXPECT_EQ(vtu.attr("Points", "NumberOfComponents"), "3");
  EXPECT_EQ(vtu.array<double>("Points", 9), points);

  EXPECT_EQ(vtu.attr("velocity", "type"), "Float32");
  EXPECT_EQ(vtu.attr("velocity", "NumberOfComponents"), "3");
  EXPECT_EQ(vtu.array<float>("velocity", 9), fields[0].f32);
  EXPECT_EQ(vtu.attr("mass", "type"), "Float64");
  EXPECT_EQ(vtu.attr("mass", "NumberOfComponents"), "1");
  EXPECT_EQ(vtu.array<double>("mass", 3), fields[1].f64);
  EXPECT_EQ(vtu.attr("material_id", "type"), "Int32");
  EXPECT_EQ(vtu.array<int32_t>("material_id", 3), fields[2].i32);

  EXPECT_EQ(vtu.attr("connectivity", "type"), "Int64");
  EXPECT_EQ(vtu.array<int64_t>("connectivity", 3), (std::vector<int64_t>{0, 1, 2}));
  EXPECT_EQ(vtu.attr("offsets", "type"), "Int64");
  EXPECT_EQ(vtu.array<int64_t>("offsets", 3), (std::vector<int64_t>{1, 2, 3}));
  EXPECT_EQ(vtu.attr("types", "type"), "UInt8");
  EXPECT_EQ(vtu.array<uint8_t>("types", 3), (std::vector<uint8_t>{1, 1, 1}));

  // The last block ends exactly where the closing XML begins.
  const size_t types_end = vtu.data_start + std::stoull(vtu.attr("types", "offset")) + 8 + 3;
  EXPECT_EQ(vtu.text.substr(types_end), "\n  </AppendedData>\n</VTKFile>\n");
}

TEST_F(VtuWriterTest, EmptyPointSetIsValid) {
  std::vector<VtuField> fields(2);
  fields[0].name = "velocity";
  fields[0].components = 3;
  fields[1].name = "mass";
  const fs::path file = dir / "empty.vtu";
  write_vtu(file.string(), {}, fields);

  const ParsedVtu vtu(file);
  EXPECT_NE(vtu.header().find("NumberOfPoints=\"0\" NumberOfCells=\"0\""), std::string::npos);
  EXPECT_TRUE(vtu.array<double>("Points", 0).empty());
  EXPECT_TRUE(vtu.array<float>("velocity", 0).empty());
  EXPECT_TRUE(vtu.array<float>("mass", 0).empty());
  EXPECT_TRUE(vtu.array<int64_t>("connectivity", 0).empty());
  EXPECT_TRUE(vtu.array<int64_t>("offsets", 0).empty());
  EXPECT_TRUE(vtu.array<uint8_t>("types", 0).empty());
  EXPECT_EQ(vtu.text.size() - vtu.data_start, 6 * 8 + std::string("\n  </AppendedData>\n</VTKFile>\n").size());
}

TEST_F(VtuWriterTest, RejectsMalformedFields) {
  VtuField f;
  f.name = "bad";
  f.f32 = {1.f, 2.f};  // 2 values for 1 point
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), {0, 0, 0}, {f}), std::invalid_argument);
  f.f32 = {1.f};
  f.i32 = {1};  // two data vectors
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), {0, 0, 0}, {f}), std::invalid_argument);
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), {0, 0}, {}), std::invalid_argument);
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST_F(VtuWriterTest, PvdListsTimesAndFiles) {
  const fs::path file = dir / "run.pvd";
  write_pvd(file.string(), {{0.0, "frames/f_0000.vtu"}, {0.125, "frames/f_0001.vtu"}, {1e-3, "a&b.vtu"}});
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  const std::string text = read_file(file);
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  const size_t a = text.find("<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frames/f_0000.vtu\"/>");
  const size_t b = text.find("<DataSet timestep=\"0.125\" group=\"\" part=\"0\" file=\"frames/f_0001.vtu\"/>");
  const size_t c = text.find("<DataSet timestep=\"0.001\" group=\"\" part=\"0\" file=\"a&amp;b.vtu\"/>");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(c, std::string::npos);
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_NE(text.find("</Collection>\n</VTKFile>"), std::string::npos);
}

TEST_F(VtuWriterTest, OverwritesExistingFile) {
  const fs::path file = dir / "frame.vtu";
  write_vtu(file.string(), {1, 2, 3, 4, 5, 6}, {});
  write_vtu(file.string(), {7, 8, 9}, {});
  EXPECT_EQ(ParsedVtu(file).array<double>("Points", 3), (std::vector<double>{7, 8, 9}));
}

TEST_F(VtuWriterTest, NonexistentDirectoryThrowsAndLeavesNoFile) {
  const fs::path missing = dir / "no_such_dir";
  const std::string vtu = (missing / "frame.vtu").string();
  try {
    write_vtu(vtu, {0, 0, 0}, {});
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(vtu), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_pvd((missing / "run.pvd").string(), {{0.0, "a.vtu"}}), std::runtime_error);
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(fs::is_empty(dir));
}

// Bit-for-bit equality (NaN and -0 included).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// n points with smooth coordinates and one field of each type: f32 vector, f64, i32, i64 ids.
struct Frame {
  std::vector<double> points;
  std::vector<VtuField> fields;
  explicit Frame(size_t n) : fields(4) {
    fields[0] = {"velocity", 3, {}, {}, {}};
    fields[1] = {"mass", 1, {}, {}, {}};
    fields[2] = {"material", 1, {}, {}, {}};
    fields[3] = {"id", 1, {}, {}, {}};
    for (size_t q = 0; q < n; ++q) {
      const double s = 0.01 * double(q);
      points.insert(points.end(), {std::sin(s) * 100, std::cos(s) + 1.0 / 3.0, 0.0});
      fields[0].f32.insert(fields[0].f32.end(), {float(s), -float(s) * 1e-3f, 0.f});
      fields[1].f64.push_back(1.0 / (1.0 + double(q)));
      fields[2].i32.push_back(int32_t(q % 3));
      fields[3].i64.push_back(int64_t{5'000'000'000} + int64_t(q));  // past 2^32: needs 64 bits
    }
    if (n > 1) fields[0].f32[0] = std::numeric_limits<float>::quiet_NaN(), fields[0].f32[1] = -0.f;
  }
};

void expect_frame(const ParsedVtu& vtu, const Frame& f) {
  const size_t n = f.points.size() / 3;
  ASSERT_EQ(vtu.points(), n);
  EXPECT_TRUE(same_bits(vtu.array<double>("Points", 3 * n), f.points));
  EXPECT_TRUE(same_bits(vtu.array<float>("velocity", 3 * n), f.fields[0].f32));
  EXPECT_TRUE(same_bits(vtu.array<double>("mass", n), f.fields[1].f64));
  EXPECT_TRUE(same_bits(vtu.array<int32_t>("material", n), f.fields[2].i32));
  EXPECT_EQ(vtu.attr("id", "type"), "Int64");
  EXPECT_TRUE(same_bits(vtu.array<int64_t>("id", n), f.fields[3].i64));
  std::vector<int64_t> iota(n);
  for (size_t q = 0; q < n; ++q) iota[q] = int64_t(q);
  EXPECT_EQ(vtu.array<int64_t>("connectivity", n), iota);
  for (auto& v : iota) ++v;
  EXPECT_EQ(vtu.array<int64_t>("offsets", n), iota);
  EXPECT_EQ(vtu.array<uint8_t>("types", n), std::vector<uint8_t>(n, 1));
}

VtuOptions zlib(uint64_t block_bytes) {
  VtuOptions o;
  o.compression = VtuCompression::ZLib;
  o.block_bytes = block_bytes;
  return o;
}

uint64_t u64_at(const ParsedVtu& vtu, const std::string& name, size_t i) {
  uint64_t v;
  std::memcpy(&v, vtu.text.data() + vtu.data_start + std::stoull(vtu.attr(name, "offset")) + 8 * i, 8);
  return v;
}

TEST_F(VtuWriterTest, CompressedAndUncompressedRoundTripBitForBit) {
  const Frame f(1000);
  const fs::path raw = dir / "raw.vtu", packed = dir / "zlib.vtu";
  write_vtu(raw.string(), f.points, f.fields);
  write_vtu(packed.string(), f.points, f.fields, zlib(999));  // every array has full blocks and a partial last one
  const ParsedVtu a(raw), b(packed);
  EXPECT_FALSE(a.compressed);
  ASSERT_TRUE(b.compressed);
  EXPECT_NE(b.header().find("header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">"), std::string::npos);
  expect_frame(a, f);
  expect_frame(b, f);
  EXPECT_LT(fs::file_size(packed), fs::file_size(raw));
}

TEST_F(VtuWriterTest, CompressedHeaderCountsBlocks) {
  const Frame f(1000);
  const fs::path file = dir / "zlib.vtu";
  write_vtu(file.string(), f.points, f.fields, zlib(3000));
  const ParsedVtu vtu(file);
  // mass: 8000 bytes = 2 full blocks and a partial one of 2000 bytes.
  EXPECT_EQ(u64_at(vtu, "mass", 0), 3u);
  EXPECT_EQ(u64_at(vtu, "mass", 1), 3000u);
  EXPECT_EQ(u64_at(vtu, "mass", 2), 2000u);
  // Points: 24000 bytes = 8 full blocks, no partial one; the next array starts after the compressed blocks.
  ASSERT_EQ(u64_at(vtu, "Points", 0), 8u);
  EXPECT_EQ(u64_at(vtu, "Points", 2), 0u);
  uint64_t end = std::stoull(vtu.attr("Points", "offset")) + 8 * (3 + 8);
  for (size_t b = 0; b < 8; ++b) end += u64_at(vtu, "Points", 3 + b);
  EXPECT_EQ(end, std::stoull(vtu.attr("connectivity", "offset")));
}

TEST_F(VtuWriterTest, CompressedBytesDoNotDependOnThreads) {
  const Frame f(5000);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  write_vtu((dir / "one.vtu").string(), f.points, f.fields, zlib(4096));
  omp_set_num_threads(4);
  write_vtu((dir / "four.vtu").string(), f.points, f.fields, zlib(4096));
  omp_set_num_threads(threads);
  EXPECT_EQ(read_file(dir / "one.vtu"), read_file(dir / "four.vtu"));
}

TEST_F(VtuWriterTest, Float32Positions) {
  const Frame f(100);
  VtuOptions o = zlib(1u << 16);
  o.positions = VtuReal::Float32;
  write_vtu((dir / "f32.vtu").string(), f.points, f.fields, o);
  const ParsedVtu vtu(dir / "f32.vtu");
  EXPECT_EQ(vtu.attr("Points", "type"), "Float32");
  const std::vector<float> expected(f.points.begin(), f.points.end());
  EXPECT_TRUE(same_bits(vtu.array<float>("Points", 300), expected));
  EXPECT_TRUE(same_bits(vtu.array<int64_t>("id", 100), f.fields[3].i64));
}

TEST_F(VtuWriterTest, FieldDataHoldsTimeAndMaterialNames) {
  for (const VtuCompression c : {VtuCompression::None, VtuCompression::ZLib}) {
    VtuOptions o;
    o.compression = c;
    o.time = 0.1 + 0.2;
    o.metadata = {{kVtuMaterialNames, {"water", "ice", ""}}, {"scene", {"calving <front> & \"2d\""}}};
    const Frame f(10);
    write_vtu((dir / "t.vtu").string(), f.points, f.fields, o);
    const ParsedVtu vtu(dir / "t.vtu");
    const std::string h = vtu.header();
    ASSERT_NE(h.find("<FieldData>"), std::string::npos);
    EXPECT_LT(h.find("</FieldData>"), h.find("<Piece"));
    EXPECT_EQ(vtu.attr("TimeValue", "type"), "Float64");
    EXPECT_EQ(vtu.attr("TimeValue", "NumberOfTuples"), "1");
    EXPECT_TRUE(same_bits(vtu.array<double>("TimeValue", 1), std::vector<double>{0.1 + 0.2}));
    EXPECT_EQ(vtu.attr("material_names", "NumberOfTuples"), "3");
    EXPECT_EQ(vtu.strings("material_names"), (std::vector<std::string>{"water", "ice", ""}));
    EXPECT_EQ(vtu.strings("scene"), std::vector<std::string>{"calving <front> & \"2d\""});
    expect_frame(vtu, f);
  }
}

TEST_F(VtuWriterTest, CompressedEmptyPointSetHasNoBlocks) {
  const fs::path file = dir / "empty.vtu";
  write_vtu(file.string(), {}, {{"id", 1, {}, {}, {}}}, zlib(1024));
  const ParsedVtu vtu(file);
  EXPECT_TRUE(vtu.array<double>("Points", 0).empty());
  EXPECT_TRUE(vtu.array<float>("id", 0).empty());
  EXPECT_EQ(u64_at(vtu, "types", 0), 0u);
  EXPECT_EQ(u64_at(vtu, "types", 1), 1024u);
  EXPECT_EQ(u64_at(vtu, "types", 2), 0u);
}

TEST_F(VtuWriterTest, RejectsBadOptions) {
  const Frame f(2);
  VtuOptions o = zlib(0);
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), f.points, f.fields, o), std::invalid_argument);
  o = zlib(64);
  o.zlib_level = 0;
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), f.points, f.fields, o), std::invalid_argument);
  o = VtuOptions{};
  o.metadata = {{"names", {std::string("a\0b", 3)}}};
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), f.points, f.fields, o), std::invalid_argument);
  VtuField two{"two", 1, {}, {}, {1, 2}, {1, 2}};
  EXPECT_THROW(write_vtu((dir / "bad.vtu").string(), f.points, {two}, {}), std::invalid_argument);
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace (the fixture and the tests: file-local, also when the unity build joins files)
