// partition.h - the decomposition of a distributed run (docs/architecture.md): every rank owns a contiguous range
// of the global block order (the lattice block index of grid/grid.h, row-major over blocks, last axis fastest: a
// valid space-filling curve), and the particles whose stencil base node lies in its blocks (grid/particle_bins.h).
// The cuts between ranks are placed so that the particle counts balance: cut r is the block boundary whose count of
// particles before it is closest to r N / ranks, so each rank's count is within one block's particle count of the
// mean N / ranks.
//
// Any block boundary may be a cut, also one between a wall's ghost node and its mirror node: the ranks then share
// the blocks of the mirror pairs before the fold (parallel/mirror_zone.h).
// The mirror pairs of static slip boxes (boundary/box_obstacle.cpp) are kept on one rank instead, pair by pair
// (keep_together): the cuts between the blocks of a ghost node inside the box and of its mirror node outside it are
// forbidden (`allowed`, empty when every cut is allowed).
// Pure functions of their inputs: every rank computes the same partition from the same counts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "grid/grid.h"

namespace cdmpm {

struct BlockPartition {
  std::vector<uint32_t> first;  // rank r owns blocks [first[r], first[r + 1]); first[ranks] = block count

  int ranks() const { return static_cast<int>(first.size()) - 1; }
  // The rank owning block b (the non-empty range holding it).
  int owner(size_t b) const {
    return static_cast<int>(std::upper_bound(first.begin(), first.end(), static_cast<uint32_t>(b)) - first.begin()) - 1;
  }
};

// Sorts a list of block indices and drops repeats (both sides of an exchange list its blocks ascending).
inline void sort_unique(std::vector<uint32_t>& blocks) {
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
}

// Per cut position c = 0 .. block_count (blocks < c before the cut): 1 if a cut may lie there; all allowed.
inline std::vector<uint8_t> every_cut(size_t block_count) { return std::vector<uint8_t>(block_count + 1, 1); }

// Forbids every cut between blocks a and b (in either order), so that one rank owns both.
inline void keep_together(std::vector<uint8_t>& allowed, size_t a, size_t b) {
  for (size_t c = std::min(a, b) + 1; c <= std::max(a, b); ++c) allowed[c] = 0;
}

// Where cuts may lie when each pair of `joined` must have one owner (empty: anywhere).
inline std::vector<uint8_t> allowed_cuts(size_t block_count, const std::vector<std::array<size_t, 2>>& joined) {
  std::vector<uint8_t> allowed;
  if (!joined.empty()) allowed = every_cut(block_count);
  for (const auto& [a, b] : joined) keep_together(allowed, a, b);
  return allowed;
}

// The occupied blocks (ascending) and their counts, from per-block counts.
inline void occupied_blocks(const std::vector<uint32_t>& per_block, std::vector<uint32_t>& blocks,
                            std::vector<uint64_t>& counts) {
  blocks.clear(), counts.clear();
  for (size_t b = 0; b < per_block.size(); ++b)
    if (per_block[b] > 0) blocks.push_back(static_cast<uint32_t>(b)), counts.push_back(per_block[b]);
}

// The partition of `block_count` blocks over `ranks` ranks for particle counts `counts` of blocks `blocks`
// (ascending, distinct), cutting only where `allowed` says so (empty: anywhere).
inline BlockPartition balanced_partition(const std::vector<uint32_t>& blocks, const std::vector<uint64_t>& counts,
                                         int ranks, size_t block_count, const std::vector<uint8_t>& allowed = {}) {
  BlockPartition p;
  p.first.assign(static_cast<size_t>(ranks) + 1, 0);
  p.first[ranks] = static_cast<uint32_t>(block_count);
  uint64_t total = 0;
  for (const uint64_t n : counts) total += n;
  // prefix(c) = particles in blocks < c, piecewise constant between occupied blocks.
  size_t j = 0;          // occupied blocks before the current cut candidate
  uint64_t before = 0;   // their particles
  size_t c = 0;
  for (int r = 1; r < ranks; ++r) {
    const double target = double(total) * r / ranks;
    // Advance c over allowed positions while that brings the prefix closer to the target.
    size_t best = c;
    uint64_t best_before = before;
    size_t cj = j;
    uint64_t cb = before;
    for (size_t d = c; d <= block_count; ++d) {
      while (cj < blocks.size() && blocks[cj] < d) cb += counts[cj++];
      if (!allowed.empty() && !allowed[d]) continue;
      if (std::abs(double(cb) - target) < std::abs(double(best_before) - target)) best = d, best_before = cb;
      if (double(cb) >= target) break;
    }
    c = best;
    before = best_before;
    while (j < blocks.size() && blocks[j] < c) ++j;
    p.first[r] = static_cast<uint32_t>(c);
  }
  return p;
}

// Particles per rank under partition p, and the imbalance max / mean (1 for an empty run).
inline std::vector<uint64_t> rank_counts(const BlockPartition& p, const std::vector<uint32_t>& blocks,
                                         const std::vector<uint64_t>& counts) {
  std::vector<uint64_t> per(p.ranks(), 0);
  for (size_t j = 0; j < blocks.size(); ++j) per[p.owner(blocks[j])] += counts[j];
  return per;
}
inline double imbalance(const std::vector<uint64_t>& per_rank) {
  uint64_t total = 0, most = 0;
  for (const uint64_t n : per_rank) total += n, most = std::max(most, n);
  return total == 0 ? 1.0 : double(most) * double(per_rank.size()) / double(total);
}

}  // namespace cdmpm
