// test_checkpoint_pieces.cpp - a distributed run's checkpoint (io/checkpoint.h): every rank's piece with the order
// keys of its particles, and the manifest naming them. Reading merges the pieces by key into the one-process array
// whatever the ranks held (solids and fluids on every rank, a migrated particle's key inside another rank's range),
// and refuses a missing piece, a piece of another checkpoint, a piece name with a path, and two pieces claiming
// one particle, naming the file.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "cli_helpers.h"
#include "io/checkpoint.h"
#include "io/checkpoint_format.h"

namespace cdmpm {
namespace {

// The one-process array: particles 0..2 solids, 3..6 fluids; particle k has key k and a state made of k.
Particles<2> whole() {
  Particles<2> p;
  for (int k = 0; k < 7; ++k) {
    const Real r = Real(k);
    const Mat<2> Ck = Mat<2>::Constant(r), F = Vec<2>(1 + r, 1 - r / 10).asDiagonal();
    if (k < 3) p.add_solid(Vec<2>(r, 2 * r), Vec<2>(-r, r), 1 + r, 1 - r / 100, 1, Ck, F, -r);
    else p.add_fluid(Vec<2>(r, 2 * r), Vec<2>(-r, r), 1 + r, 1 - r / 100, 0, Ck);
  }
  for (int k = 0; k < 7; ++k) p.id[k] = 100 + k;  // ids differ from keys
  return p;
}

struct Written {
  testing::TempDir dir;
  std::string manifest = dir / "checkpoint.bin";
  CheckpointMeta meta;
};

// Rank 0 holds keys {0, 3, 5}, rank 1 {1, 2, 4, 6}: each has solids and fluids, and their keys interleave.
void write_two_ranks(Written& w, const std::vector<std::vector<uint32_t>>& ranks) {
  const Particles<2> all = whole();
  w.meta.time = 1.5;
  w.meta.steps = 42;
  for (size_t r = 0; r < ranks.size(); ++r) {
    Particles<2> p = all.extract(ranks[r]);  // the particles of these keys, as a rank holds them
    const std::vector<uint64_t> keys(ranks[r].begin(), ranks[r].end());
    w.meta.pieces.push_back(write_checkpoint_piece(w.dir / ("checkpoint_a_r" + std::to_string(r) + ".bin"), p, keys));
  }
  write_checkpoint_manifest(w.manifest, 2, w.meta);
}

std::string read_error(const std::string& path) {
  Particles<2> back;
  try {
    read_checkpoint(path, back);
  } catch (const CheckpointError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointPieces, MergeByKeyIntoTheOneProcessArray) {
  Written w;
  write_two_ranks(w, {{0, 3, 5}, {1, 2, 4, 6}});
  Particles<2> back;
  back.next_id = 107;
  const CheckpointMeta m = read_checkpoint(w.manifest, back);
  EXPECT_EQ(m.time, 1.5);
  EXPECT_EQ(m.steps, 42);
  ASSERT_EQ(m.pieces.size(), 2u);
  const Particles<2> expected = whole();
  ASSERT_EQ(back.size(), expected.size());
  ASSERT_EQ(back.solid_count(), 3u);
  EXPECT_EQ(back.id, expected.id);
  EXPECT_EQ(back.x, expected.x);
  EXPECT_EQ(back.v, expected.v);
  EXPECT_EQ(back.C, expected.C);
  EXPECT_EQ(back.mass, expected.mass);
  EXPECT_EQ(back.J, expected.J);
  EXPECT_EQ(back.material, expected.material);
  EXPECT_EQ(back.F, expected.F);
  EXPECT_EQ(back.alpha, expected.alpha);
  EXPECT_EQ(back.next_id, 107u);
}

// The particles of `keys` in the one-process array, in that order, as the reader of a share returns them.
void expect_keys(const Particles<2>& back, const std::vector<uint64_t>& got, const std::vector<uint64_t>& keys) {
  EXPECT_EQ(got, keys);
  const Particles<2> all = whole();
  ASSERT_EQ(back.size(), keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    EXPECT_EQ(back.id[i], all.id[keys[i]]);
    EXPECT_EQ(back.x[i], all.x[keys[i]]);
    EXPECT_EQ(back.J[i], all.J[keys[i]]);
    if (keys[i] < 3) {
      EXPECT_EQ(back.F[i], all.F[keys[i]]);
    }
  }
}

// A distributed run's rank reads only its share (the pieces k with k % ranks == rank, merged by key): a piece it does
// not read may even be missing. Of a one-file checkpoint it keeps its range of the one-process array.
TEST(CheckpointPieces, ARankReadsOnlyItsShare) {
  Written w;
  write_two_ranks(w, {{0, 4}, {1, 2, 5}, {3, 6}});
  std::filesystem::remove(w.dir / "checkpoint_a_r1.bin");
  CheckpointShare first{0, 2, {}};
  Particles<2> back;
  read_checkpoint(w.manifest, back, &first);
  expect_keys(back, first.keys, {0, 3, 4, 6});
  EXPECT_EQ(back.solid_count(), 1u);
  CheckpointShare second{1, 2, {}};
  EXPECT_THROW(read_checkpoint(w.manifest, back, &second), CheckpointError);  // its piece is the missing one

  testing::TempDir dir;
  Particles<2> all = whole();
  write_checkpoint(dir / "one.bin", all, CheckpointMeta{});
  CheckpointShare middle{1, 3, {}};
  Particles<2> part;
  read_checkpoint(dir / "one.bin", part, &middle);
  expect_keys(part, middle.keys, {2, 3});  // [7 / 3, 14 / 3)
  EXPECT_EQ(part.solid_count(), 1u);
}

TEST(CheckpointPieces, RefuseMissingForeignMisnamedAndOverlappingPieces) {
  {
    Written w;
    write_two_ranks(w, {{0, 3, 5}, {1, 2, 4, 6}});
    std::filesystem::remove(w.dir / "checkpoint_a_r1.bin");
    const std::string e = read_error(w.manifest);
    EXPECT_NE(e.find("checkpoint_a_r1.bin: no checkpoint piece"), std::string::npos) << e;
  }
  {
    // A piece of another checkpoint in its place (another state, same counts): its checksum is not the manifest's.
    Written w, other;
    write_two_ranks(w, {{0, 3, 5}, {1, 2, 4, 6}});
    write_two_ranks(other, {{0, 3, 6}, {1, 2, 4, 5}});
    std::filesystem::copy_file(other.dir / "checkpoint_a_r0.bin", w.dir / "checkpoint_a_r0.bin",
                               std::filesystem::copy_options::overwrite_existing);
    const std::string e = read_error(w.manifest);
    EXPECT_NE(e.find("checkpoint_a_r0.bin: checkpoint piece is not the one"), std::string::npos) << e;
  }
  {
    Written w;
    write_two_ranks(w, {{0, 3, 5}, {1, 2, 4, 6}});
    w.meta.pieces[1].file = "../checkpoint_a_r1.bin";
    write_checkpoint_manifest(w.manifest, 2, w.meta);
    const std::string e = read_error(w.manifest);
    EXPECT_NE(e.find("piece file name '../checkpoint_a_r1.bin'"), std::string::npos) << e;
  }
  {
    Written w;
    write_two_ranks(w, {{0, 3, 5}, {1, 2, 3, 6}});
    const std::string e = read_error(w.manifest);
    EXPECT_NE(e.find("two pieces hold a particle of key 3"), std::string::npos) << e;
  }
  {
    // A manifest cut short: its own checksum.
    Written w;
    write_two_ranks(w, {{0, 3, 5}, {1, 2, 4, 6}});
    std::filesystem::resize_file(w.manifest, std::filesystem::file_size(w.manifest) - 9);
    const std::string e = read_error(w.manifest);
    EXPECT_NE(e.find("checkpoint.bin: checkpoint is corrupt (checksum"), std::string::npos) << e;
  }
}

}  // namespace
}  // namespace cdmpm
