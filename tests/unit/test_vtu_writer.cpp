// test_vtu_writer.cpp - unit tests for the .vtu / .pvd writers: files are parsed back here (XML header
// offsets + appended raw blocks) and every byte count and value is checked exactly.
#include "io/vtu_writer.h"

#include "vtu_reader.h"

#include <gtest/gtest.h>

#include <cstring>
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

}  // namespace

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
