// test_particles.cpp - the particle storage (core/particles.h): solids first, F and alpha only for solids,
// kept so by seeding, reordering and checkpoints (a permutation: tests/unit/test_particles_permute.cpp); an
// old-format checkpoint is refused with a clear message.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "cli_helpers.h"
#include "io/checkpoint.h"
#include "scene/scene_loader.h"
#include "sim/simulation.h"

namespace cdmpm {
namespace {

Mat<2> diag(Real a) { return Vec<2>(a, a).asDiagonal(); }

// The batch a process sends away when particles migrate: extract copies the listed particles with their ids and
// solid state; append adds them to another set, solids after its solids; ids follow the particles.
TEST(Particles, ExtractAndAppendMoveParticlesWithTheirIdsAndState) {
  Particles<2> a, b;
  for (Real k : {1, 2, 3}) a.add_solid(Vec<2>::Constant(k), Vec<2>::Zero(), k, 1, 1, Mat<2>::Zero(), diag(k), -k);
  for (Real k : {4, 5}) a.add_fluid(Vec<2>::Constant(k), Vec<2>::Zero(), k, 1, 0);
  b.next_id = 100;
  b.add_solid(Vec<2>::Zero(), Vec<2>::Zero(), 10, 1, 1, Mat<2>::Zero(), diag(10), -10);
  b.add_fluid(Vec<2>::Zero(), Vec<2>::Zero(), 11, 1, 0);
  const Particles<2> batch = a.extract({1, 2, 4});
  EXPECT_EQ(batch.id, (std::vector<uint64_t>{1, 2, 4}));
  EXPECT_EQ(batch.solid_count(), 2u);
  b.append(batch);
  EXPECT_EQ(b.id, (std::vector<uint64_t>{100, 1, 2, 101, 4}));
  EXPECT_EQ(b.mass, (std::vector<Real>{10, 2, 3, 11, 5}));
  ASSERT_EQ(b.solid_count(), 3u);
  for (size_t q = 0; q < b.solid_count(); ++q) EXPECT_EQ(b.F[q], diag(b.mass[q])) << q;
  EXPECT_EQ(b.alpha, (std::vector<Real>{-10, -2, -3}));
}

TEST(Particles, WriteBackReturnsAnExtractedBatchsStateToItsParticles) {
  // Multi-rate stepping extracts the solids of the solids' own field, steps them and writes them back.
  Particles<2> a;
  for (Real k : {1, 2, 3}) a.add_solid(Vec<2>::Constant(k), Vec<2>::Zero(), k, 1, 1, Mat<2>::Zero(), diag(k), -k);
  for (Real k : {4, 5}) a.add_fluid(Vec<2>::Constant(k), Vec<2>::Zero(), k, 1, 0);
  const std::vector<uint32_t> index = {0, 2, 3};
  Particles<2> batch = a.extract(index);
  for (size_t j = 0; j < batch.size(); ++j) {  // a new state: everything times 10
    batch.x[j] *= 10;
    batch.v[j] = Vec<2>::Constant(10 * batch.mass[j]);
    batch.C[j] = diag(10 * batch.mass[j]);
    batch.J[j] = 10 * batch.mass[j];
  }
  for (size_t j = 0; j < batch.solid_count(); ++j) {
    batch.F[j] *= 10;
    batch.alpha[j] *= 10;
  }
  a.write_back(index, batch);
  for (size_t q = 0; q < a.size(); ++q) {
    const Real k = a.mass[q], f = (q == 1 || q == 4) ? 1 : 10;  // particles 1 and 4 were not in the batch
    EXPECT_EQ(a.x[q], Vec<2>::Constant(f * k)) << q;
    EXPECT_EQ(a.v[q], Vec<2>::Constant(f == 10 ? 10 * k : 0)) << q;
    EXPECT_EQ(a.C[q], f == 10 ? diag(10 * k) : Mat<2>::Zero()) << q;
    EXPECT_EQ(a.J[q], f == 10 ? 10 * k : 1) << q;
    if (q < a.solid_count()) {
      EXPECT_EQ(a.F[q], diag(f * k)) << q;
      EXPECT_EQ(a.alpha[q], -f * k) << q;
    }
  }
  EXPECT_EQ(a.id, (std::vector<uint64_t>{0, 1, 2, 3, 4}));
}

// Water listed before ice, so the seeding order has to put the ice first.
Scene mixed_scene() {
  const nlohmann::json j = {
      {"name", "mixed"},
      {"dim", 2},
      {"domain", {{"size", {1.0, 1.0}}, {"dx", 0.05}}},
      {"time", {{"end", 1.0}, {"frame_interval", 0.1}}},
      {"gravity", {0, -9.81}},
      {"materials",
       {{"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1.0e6}}},
        {"ice", {{"type", "ice"}, {"density", 917}, {"youngs_modulus", 1.0e8}, {"M", 1.85}, {"beta", 0.3}, {"xi", 3},
                 {"tensile_strength", 1.0e4}}}}},
      {"bodies",
       {{{"material", "water"}, {"particles_per_cell", 4}, {"shape", {{"type", "box"}, {"min", {0.5, 0}}, {"max", {1.0, 0.4}}}}},
        {{"material", "ice"}, {"particles_per_cell", 4}, {"shape", {{"type", "box"}, {"min", {0, 0}}, {"max", {0.5, 0.5}}}}}}},
      {"boundaries", {{{"type", "walls"}, {"condition", "slip"}}}},
      {"output", {{"frames", false}}}};
  return scene_from_json(j, "<mixed>");
}

void expect_solids_first(const Simulation<2>& sim) {
  const auto& P = sim.particles;
  EXPECT_EQ(P.solid_count(), 400u);  // (0.5 / 0.05)^2 cells, 4 particles each
  EXPECT_EQ(P.alpha.size(), P.solid_count());
  for (size_t q = 0; q < P.size(); ++q)
    ASSERT_EQ(sim.materials[P.material[q]].traits().solid_state, q < P.solid_count()) << "particle " << q;
}

TEST(Particles, SimulationSeedsSolidsFirstAndReorderingKeepsThem) {
  const Scene scene = mixed_scene();
  Simulation<2> sim(scene);
  EXPECT_EQ(sim.particles.size(), 400u + 320u);
  expect_solids_first(sim);
  for (int s = 0; s < 2 * Simulation<2>::reorder_interval + 1; ++s) sim.step(sim.stable_dt());
  EXPECT_FALSE(sim.check_state());
  expect_solids_first(sim);
}

TEST(Checkpoint, RoundTripsTheSolidStateAndRefusesTheOldFormat) {
  const Scene scene = mixed_scene();
  Simulation<2> sim(scene);
  for (int s = 0; s < 3; ++s) sim.step(sim.stable_dt());
  testing::TempDir dir;
  const std::string path = dir / "checkpoint.bin";
  write_checkpoint(path, sim.particles, CheckpointMeta{});
  Particles<2> back;
  read_checkpoint(path, back);
  ASSERT_EQ(back.size(), sim.particles.size());
  ASSERT_EQ(back.solid_count(), sim.particles.solid_count());
  EXPECT_EQ(std::memcmp(back.F.data(), sim.particles.F.data(), back.F.size() * sizeof(Mat<2>)), 0);
  EXPECT_EQ(back.alpha, sim.particles.alpha);
  EXPECT_EQ(back.x, sim.particles.x);

  // A checkpoint of the previous format (reference volume stored, no rigid bodies) names both formats.
  std::ofstream(dir / "old.bin", std::ios::binary) << "CDMPMCK4" << std::string(64, '\0');
  try {
    read_checkpoint(dir / "old.bin", back);
    FAIL() << "an old-format checkpoint was read";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("CDMPMCK4"), std::string::npos) << what;
    EXPECT_NE(what.find("CDMPMCKA"), std::string::npos) << what;
    EXPECT_NE(what.find("without --resume"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace cdmpm
