// test_partition.cpp - the decomposition of a distributed run (parallel/partition.h): contiguous ranges of the
// global block order, particle counts balanced to within one block's count of the mean (the cut nearest each target
// r N / ranks is at most half a block's count away from it, so a rank's count, the difference of two such prefixes,
// is within one block's count of the mean), and no cut between a wall's ghost node and its mirror node
// (boundary/walls.cpp: node -k mirrors k at the lower face, top + k mirrors top - k at the upper one).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "parallel/partition.h"

namespace cdmpm {
namespace {

// Random particle counts on a random subset of the blocks of g (ascending blocks, counts 1 .. 200).
template <int dim>
void random_counts(const Grid<dim>& g, unsigned seed, std::vector<uint32_t>& blocks, std::vector<uint64_t>& counts) {
  std::mt19937 rng(seed);
  for (uint32_t b = 0; b < g.block_count(); ++b)
    if (rng() % 3 != 0) {
      blocks.push_back(b);
      counts.push_back(1 + rng() % 200);
    }
}

template <int dim>
void check_contiguous_and_balanced(const Vec<dim>& size, Real dx) {
  const Grid<dim> g(size, dx);
  const std::vector<uint8_t> all(g.block_count() + 1, 1);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::vector<uint32_t> blocks;
    std::vector<uint64_t> counts;
    random_counts(g, seed, blocks, counts);
    uint64_t total = 0, biggest = 0;
    for (const uint64_t n : counts) total += n, biggest = std::max(biggest, n);
    for (int ranks = 1; ranks <= 7; ++ranks) {
      const BlockPartition p = balanced_partition(blocks, counts, ranks, g.block_count(), all);
      ASSERT_EQ(p.ranks(), ranks);
      EXPECT_EQ(p.first.front(), 0u);
      EXPECT_EQ(p.first.back(), g.block_count());
      EXPECT_TRUE(std::is_sorted(p.first.begin(), p.first.end()));  // contiguous, in rank order
      for (uint32_t b = 0; b < g.block_count(); ++b) {
        const int r = p.owner(b);
        ASSERT_TRUE(p.first[r] <= b && b < p.first[r + 1]) << "block " << b << " rank " << r;
      }
      const std::vector<uint64_t> per = rank_counts(p, blocks, counts);
      const double mean = double(total) / ranks;
      for (int r = 0; r < ranks; ++r)
        EXPECT_LE(std::abs(double(per[r]) - mean), double(biggest)) << ranks << " ranks, rank " << r << ", seed " << seed;
    }
  }
}

TEST(Partition, ContiguousRangesBalancedWithinOneBlock2D) { check_contiguous_and_balanced<2>(Vec<2>(1.0, 0.6), 0.02); }
TEST(Partition, ContiguousRangesBalancedWithinOneBlock3D) {
  check_contiguous_and_balanced<3>(Vec<3>(1.0, 0.3, 0.5), 0.05);
}

// Every mirror pair of every face (ghost node and mirror node) has one owner, for partitions into many ranks.
template <int dim>
void check_mirror_pairs_never_cut(const Vec<dim>& size, Real dx) {
  const Grid<dim> g(size, dx);
  const std::vector<uint8_t> allowed = allowed_cuts(g, size);
  std::vector<uint32_t> blocks;
  std::vector<uint64_t> counts;
  random_counts(g, 7, blocks, counts);
  for (int ranks : {2, 5, 16, 64}) {
    const BlockPartition p = balanced_partition(blocks, counts, ranks, g.block_count(), allowed);
    for (int r = 0; r <= ranks; ++r) ASSERT_TRUE(allowed[p.first[r]]);
    int pairs = 0;
    for (int a = 0; a < dim; ++a) {
      const int top = static_cast<int>(std::lround(size[a] / dx));
      size_t nodes = 1;
      for (int b = 0; b < dim; ++b) nodes *= static_cast<size_t>(g.n_nodes[b]);
      for (size_t k = 0; k < nodes; ++k) {
        IVec<dim> i;  // lattice node k, from -ghost on every axis
        for (size_t rest = k, b = dim; b-- > 0; rest /= static_cast<size_t>(g.n_nodes[b]))
          i[b] = static_cast<int>(rest % static_cast<size_t>(g.n_nodes[b])) - Grid<dim>::ghost;
        for (int depth = 1; depth <= Grid<dim>::ghost; ++depth)
          for (const auto& [ghost_node, mirror_node] : {std::pair{-depth, depth}, std::pair{top + depth, top - depth}}) {
            if (i[a] != ghost_node) continue;
            IVec<dim> j = i;
            j[a] = mirror_node;
            if (j[a] + Grid<dim>::ghost >= g.n_nodes[a] || i[a] + Grid<dim>::ghost >= g.n_nodes[a]) continue;
            ++pairs;
            ASSERT_EQ(p.owner(g.block_index(g.block_of(i))), p.owner(g.block_index(g.block_of(j))))
                << "axis " << a << " node " << i.transpose() << " and its mirror " << j.transpose() << ", " << ranks << " ranks";
          }
      }
    }
    EXPECT_GT(pairs, 0);
  }
}

TEST(Partition, WallMirrorPairsShareTheirOwner2D) { check_mirror_pairs_never_cut<2>(Vec<2>(1.0, 0.6), 0.02); }
TEST(Partition, WallMirrorPairsShareTheirOwner3D) { check_mirror_pairs_never_cut<3>(Vec<3>(0.6, 0.3, 0.4), 0.05); }

// Pairs of blocks kept together (keep_together: the mirror pairs of static slip boxes) have one owner, for
// partitions into many ranks; so do the walls' pairs still (keep_together only removes cuts).
TEST(Partition, KeptTogetherBlocksShareTheirOwner) {
  const Grid<2> g(Vec<2>(1.0, 0.6), Real(0.02));
  std::vector<uint8_t> allowed = allowed_cuts(g, Vec<2>(1.0, 0.6));
  const std::vector<uint8_t> walls_only = allowed;
  std::vector<uint32_t> blocks;
  std::vector<uint64_t> counts;
  random_counts(g, 11, blocks, counts);
  std::mt19937 rng(3);
  std::vector<std::pair<size_t, size_t>> pairs;  // a block and one a block row (n_blocks[1]) or one block further
  for (int k = 0; k < 20; ++k) {
    const size_t a = rng() % (g.block_count() - g.n_blocks[1]);
    const size_t b = a + (k % 2 ? 1 : g.n_blocks[1]);
    pairs.push_back(k % 4 < 2 ? std::pair{a, b} : std::pair{b, a});
    keep_together(allowed, a, b);
  }
  for (int ranks : {2, 5, 16, 64}) {
    const BlockPartition p = balanced_partition(blocks, counts, ranks, g.block_count(), allowed);
    for (int r = 0; r <= ranks; ++r) ASSERT_TRUE(walls_only[p.first[r]]);
    for (const auto& [a, b] : pairs) ASSERT_EQ(p.owner(a), p.owner(b)) << "blocks " << a << ", " << b << ", " << ranks << " ranks";
  }
}

TEST(Partition, Imbalance) {
  EXPECT_DOUBLE_EQ(imbalance({10, 10, 10}), 1.0);
  EXPECT_DOUBLE_EQ(imbalance({30, 0, 0}), 3.0);
  EXPECT_DOUBLE_EQ(imbalance({0, 0}), 1.0);
}

}  // namespace
}  // namespace cdmpm
