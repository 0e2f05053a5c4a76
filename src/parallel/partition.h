// partition.h - the decomposition of a distributed run (docs/architecture.md): every rank owns a contiguous range
// of the global block order (the lattice block index of grid/grid.h, row-major over blocks, last axis fastest: a
// valid space-filling curve), and the particles whose stencil base node lies in its blocks (grid/particle_bins.h).
// The cuts between ranks are placed so that the particle counts balance: cut r is the allowed block boundary whose
// count of particles before it is closest to r N / ranks, so with every cut allowed each rank's count is within
// one block's particle count of the mean N / ranks.
//
// Allowed cuts: a cut may not separate the two nodes of a mirror pair of the slip walls (boundary/mirror.h,
// walls.cpp): a ghost node beyond a domain face and its mirror inside lie in blocks 0 and 1 along the face's axis
// at the lower face, and in the blocks of nodes top - 3 .. top + 3 at the upper face (top = the face's node). Their
// fold and unfold then run on the one rank that owns both, after the halo sum, with the same inputs as in one
// process. Every face is treated so, whatever its boundary (a conservative choice: it keeps at most two or three
// block layers at each face together). The mirror pairs of static slip boxes (boundary/box_obstacle.cpp) are kept
// together the same way, pair by pair (keep_together): the cuts between the blocks of a ghost node inside the box
// and of its mirror node outside it are forbidden.
// Pure functions of their inputs: every rank computes the same partition from the same counts.
#pragma once

#include <algorithm>
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

// Per cut position c = 0 .. block_count (blocks < c before the cut): 1 if a cut may lie there (see above).
template <int dim>
std::vector<uint8_t> allowed_cuts(const Grid<dim>& g, const Vec<dim>& domain_size) {
  const size_t nb = g.block_count();
  std::vector<int> cover(nb + 2, 0);  // difference array of the forbidden intervals (lo, hi]
  auto forbid = [&](size_t lo, size_t hi) {
    if (hi <= lo) return;
    ++cover[lo + 1];
    --cover[hi + 1];
  };
  constexpr int ghost = Grid<dim>::ghost;
  for (int a = 0; a < dim; ++a) {
    const int top = static_cast<int>(std::lround(domain_size[a] * g.inv_dx));
    const int last = g.n_blocks[a] - 1;
    // Block coordinates along axis a that the mirror pairs of each face join: [lo, hi].
    const int ranges[2][2] = {{0, std::min(1, last)},
                              {std::clamp((top - ghost + ghost) >> Grid<dim>::block_shift, 0, last),
                               std::clamp((top + ghost + ghost) >> Grid<dim>::block_shift, 0, last)}};
    for (const auto& range : ranges) {
      // Every block with coordinate range[0] along a, paired with the block at range[1] on the same line.
      IVec<dim> c = IVec<dim>::Zero();
      while (true) {
        c[a] = range[0];
        const size_t lo = g.block_index(c);
        c[a] = range[1];
        forbid(lo, g.block_index(c));
        int b = dim - 1;  // next line: the other axes, last fastest
        for (; b >= 0; --b) {
          if (b == a) continue;
          if (++c[b] < g.n_blocks[b]) break;
          c[b] = 0;
        }
        if (b < 0) break;
      }
    }
  }
  std::vector<uint8_t> allowed(nb + 1);
  int depth = 0;
  for (size_t c = 0; c <= nb; ++c) {
    depth += cover[c];
    allowed[c] = depth == 0;
  }
  allowed[0] = allowed[nb] = 1;
  return allowed;
}

// Forbids every cut between blocks a and b (in either order), so that one rank owns both.
inline void keep_together(std::vector<uint8_t>& allowed, size_t a, size_t b) {
  for (size_t c = std::min(a, b) + 1; c <= std::max(a, b); ++c) allowed[c] = 0;
}

// The partition of `block_count` blocks over `ranks` ranks for particle counts `counts` of blocks `blocks`
// (ascending, distinct), cutting only where `allowed` (allowed_cuts) says so.
inline BlockPartition balanced_partition(const std::vector<uint32_t>& blocks, const std::vector<uint64_t>& counts,
                                         int ranks, size_t block_count, const std::vector<uint8_t>& allowed) {
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
      if (!allowed[d]) continue;
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
