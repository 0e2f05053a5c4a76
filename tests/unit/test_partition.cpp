// test_partition.cpp - the decomposition of a distributed run (parallel/partition.h): contiguous ranges of the
// global block order, particle counts balanced to within one block's count of the mean (the cut nearest each target
// r N / ranks is at most half a block's count away from it, so a rank's count, the difference of two such prefixes,
// is within one block's count of the mean), and the mirror zone that lets a cut fall between a wall's ghost node
// and its mirror node (parallel/mirror_zone.h; boundary/walls.cpp: node -k mirrors k at the lower face, top + k
// mirrors top - k at the upper one).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "parallel/mirror_zone.h"
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
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::vector<uint32_t> blocks;
    std::vector<uint64_t> counts;
    random_counts(g, seed, blocks, counts);
    uint64_t total = 0, biggest = 0;
    for (const uint64_t n : counts) total += n, biggest = std::max(biggest, n);
    for (int ranks = 1; ranks <= 7; ++ranks) {
      const BlockPartition p = balanced_partition(blocks, counts, ranks, g.block_count());
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

// The mirror zone (parallel/mirror_zone.h): for every node i and every set of axes, the node reached from i by
// reflecting it across the faces of those axes where it is a ghost or a mirror node (-k <-> k at the lower face,
// top + k <-> top - k at the upper one, k = 1 .. ghost; the chains of the fold and unfold) lies in a block of
// D(block of i); and D is symmetric.
template <int dim>
void check_mirror_zone(const Vec<dim>& size, Real dx) {
  const Grid<dim> g(size, dx);
  const MirrorZone<dim> zone(g, size);
  auto in_d = [&](size_t b, size_t c) {
    bool found = false;
    zone.for_each_dependency(g, b, [&](size_t d) { found = found || d == c; });
    return found;
  };
  int chains = 0;
  size_t nodes = 1;
  for (int b = 0; b < dim; ++b) nodes *= static_cast<size_t>(g.n_nodes[b]);
  for (size_t k = 0; k < nodes; ++k) {
    IVec<dim> i;  // lattice node k, from -ghost on every axis
    for (size_t rest = k, b = dim; b-- > 0; rest /= static_cast<size_t>(g.n_nodes[b]))
      i[b] = static_cast<int>(rest % static_cast<size_t>(g.n_nodes[b])) - Grid<dim>::ghost;
    for (int axes = 1; axes < (1 << dim); ++axes) {
      IVec<dim> j = i;
      bool moved = false;
      for (int a = 0; a < dim; ++a) {
        if (!(axes >> a & 1)) continue;
        const int top = static_cast<int>(std::lround(size[a] / dx));
        if (std::abs(i[a]) >= 1 && std::abs(i[a]) <= Grid<dim>::ghost) j[a] = -i[a], moved = true;
        else if (std::abs(i[a] - top) >= 1 && std::abs(i[a] - top) <= Grid<dim>::ghost) j[a] = 2 * top - i[a], moved = true;
      }
      if (!moved) continue;
      bool inside = true;
      for (int a = 0; a < dim; ++a) inside = inside && j[a] + Grid<dim>::ghost >= 0 && j[a] + Grid<dim>::ghost < g.n_nodes[a];
      if (!inside) continue;
      ++chains;
      const size_t bi = g.block_index(g.block_of(i)), bj = g.block_index(g.block_of(j));
      ASSERT_TRUE(in_d(bi, bj)) << "node " << i.transpose() << " reflects to " << j.transpose();
    }
  }
  EXPECT_GT(chains, 0);
  for (size_t b = 0; b < g.block_count(); ++b)
    zone.for_each_dependency(g, b, [&](size_t c) { ASSERT_TRUE(in_d(c, b)) << "blocks " << b << " and " << c; });
}

TEST(Partition, MirrorZoneHoldsEveryFoldChain2D) { check_mirror_zone<2>(Vec<2>(1.0, 0.6), 0.02); }
TEST(Partition, MirrorZoneHoldsEveryFoldChain3D) { check_mirror_zone<3>(Vec<3>(0.6, 0.3, 0.4), 0.05); }

// Pairs of blocks kept together (keep_together: the mirror pairs of static slip boxes) have one owner, for
// partitions into many ranks.
TEST(Partition, KeptTogetherBlocksShareTheirOwner) {
  const Grid<2> g(Vec<2>(1.0, 0.6), Real(0.02));
  std::vector<uint8_t> allowed = every_cut(g.block_count());
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
