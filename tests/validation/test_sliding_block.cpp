// test_sliding_block.cpp - the ice scenes end to end, coarse: scenes/sliding_block_2d.json at D/H = 0.4 and
// H/dx = 12 (at H/dx = 8 the front crumbles into damaged ice before an intact berg forms; the validation
// sweep is tools/sweep_sliding_block.py). The slab is pushed over the bed edge;
// the run must detect the first iceberg (a second connected body of intact ice, probe/icebergs.h), report
// it in summary.json and icebergs.csv, and lose water only through the spillway sink that holds the
// basin's level.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "cli_helpers.h"
#include "scene/scene_loader.h"

namespace cdmpm::testing {
namespace {

TEST(SlidingBlock, CoarseRunDetectsFirstIceberg) {
  TempDir dir;
  const std::vector<std::string> sets = {"parameters.D_over_H=0.4", "parameters.cells_per_H=12"};
  const std::string path = source_path("scenes/sliding_block_2d.json");
  const auto r = run_cdmpm({"run", path, "--out", dir / "out", "--quiet", "--set", sets[0], "--set", sets[1]});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = read_json(dir / "out/summary.json");
  ASSERT_TRUE(s.contains("first_iceberg") && s["first_iceberg"].is_object()) << s.dump(2);
  const auto& b = s["first_iceberg"];
  // The scene's values, read from it: slab thickness, water depth, push speed, water density, sink length.
  const auto json = read_json(path);
  const double H = json["parameters"]["H"], D = 0.4 * H, U = json["parameters"]["push_speed"], g = 9.81;
  const double rho_w = json["materials"]["water"]["density"];
  const Scene scene = load_scene(path, sets);
  ASSERT_EQ(scene.sinks.size(), 1u);
  const double sink_length = scene.sinks[0].max[0] - scene.sinks[0].min[0];
  // The berg broke off the overhang. The slab's front starts at the bed edge, so the edge is the front at t = 0.
  const auto probes = read_probes(dir / "out/probes.csv");
  const double x_edge = probes.at("ice_front").front();
  double overhang = 0;
  for (size_t i = 0; i < probes.at("time").size(); ++i)
    if (probes.at("time")[i] <= b["time"].get<double>()) overhang = probes.at("ice_front")[i] - x_edge;
  // Mass leaves only through the spillway sink: the water the overhang displaced (overhang x D per metre),
  // plus at most what the waves lift above the sink's lower edge over the sink's length, doubled where they
  // reflect at the end wall (the sink reaches that wall). The crest height is the largest elevation that the
  // gauge 2 H from the front records over the run. (It is not the linear piston wave U D / sqrt(g (D + z_bed)),
  // 2.2 m here: the closed basin's level also rises by the displaced volume over its length until the sink
  // takes it, and the gauge records about 3 m.) The sink removes whole particles: a particle whose centre
  // crosses the edge stands for a layer one particle spacing s thick (s = dx / 2 at 4 particles per cell in 2D),
  // so the edge can take one layer of the water below it as well.
  const double m0 = probes.at("mass").front(), m1 = probes.at("mass").back();
  const double overhang_end = probes.at("ice_front").back() - x_edge;
  double a = 0;
  for (double eta : probes.at("gauge_2H"))
    if (std::isfinite(eta)) a = std::max(a, eta);
  // The crest lies between the push wave and that wave doubled by its reflection plus the whole displaced
  // volume spread over the basin (none of it taken by the sink).
  const double a_linear = U * D / std::sqrt(g * (D + H));
  const double basin_length = scene.domain.size[0] - x_edge;
  EXPECT_GT(a, a_linear);
  EXPECT_LT(a, 2 * a_linear + overhang_end * D / basin_length);
  int water_ppc = 0;
  for (const auto& body : scene.bodies)
    if (body.material == "water") water_ppc = body.particles_per_cell;
  ASSERT_GT(water_ppc, 0);
  const double spacing = scene.domain.dx / std::round(std::sqrt(water_ppc));  // n^2 particles per cell in 2D
  EXPECT_LE(m1, m0 * (1 + 1e-12));
  EXPECT_LE(m0 - m1, rho_w * (overhang_end * D + (2 * a + spacing) * sink_length));
  // The crack runs through the slab within the zone where the edge's concentrated reaction spreads into the
  // deep beam: about half a thickness either side of the edge (Saint-Venant). The sweep at H/dx = 16 shows it
  // starting 0.2-0.3 H behind the edge at the top surface.
  EXPECT_GE(b["length"].get<double>(), overhang - 0.5 * H);
  EXPECT_LE(b["length"].get<double>(), overhang + 0.5 * H);
  EXPECT_GT(b["centroid"][0].get<double>(), x_edge - 0.5 * H);
  // icebergs.csv: header and one row per body per frame (the glacier, id 0, in every frame), plus the
  // detection of the first iceberg (a glacier row and at least one berg row).
  const CsvTable csv = read_csv_table(dir / "out/icebergs.csv");
  EXPECT_EQ(csv.header, (std::vector<std::string>{"frame", "time", "id", "particles", "volume", "length", "height",
                                                  "centroid_x", "centroid_y"}));
  int glacier_rows = 0, berg_rows = 0;
  for (double id : csv.numbers("id")) (id == 0 ? glacier_rows : berg_rows)++;
  EXPECT_EQ(glacier_rows, static_cast<int>(s["sim_time"].get<double>()) + 2);  // frame_interval 1 s
  EXPECT_GT(berg_rows, 0);
}

}  // namespace
}  // namespace cdmpm::testing
