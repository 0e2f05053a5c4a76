// particle_bins.h - particles binned by grid block, for the race-free, deterministic scatter.
//
// A stable counting sort of particle indices by the block that holds their stencil base node. Blocks of
// one colour (same parity of block coordinates on every axis) are at least two blocks apart on some axis;
// with 4-node blocks and a 3-node stencil their particles write disjoint node sets. Processing colours in a
// fixed order, blocks of a colour in parallel, and a block's particles in index order makes every node sum
// the same terms in the same order whatever the thread count: results are bitwise reproducible.
//
// Only the non-empty blocks are listed (bin j is lattice block blocks[j]), so the cost grows with the
// occupied volume, not the lattice. The sort runs in parallel and stays stable: each thread counts its
// contiguous chunk of particles per bin, a prefix over (bin, thread) gives every thread its write position
// in every bin, and each thread fills its chunk in order, so a bin lists its particles in index order for
// any thread count. The passes after the first work on runs of consecutive particles in the same block.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <omp.h>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"

namespace cdmpm {

// The bin block of a particle at x: the block holding its stencil base node (the one place of this rule).
template <int dim>
size_t bin_block(const Vec<dim>& x, const Grid<dim>& g) {
  const BSplineStencil<dim> s(x * g.inv_dx);
  return g.block_index(g.block_of(s.base));
}

struct ParticleBins {
  std::vector<uint32_t> blocks;       // lattice block index of each bin (non-empty blocks), ascending
  std::vector<uint32_t> start;        // order[start[j] .. start[j+1]) are bin j's particles, ascending
  std::vector<uint32_t> order;        // particle indices sorted by bin (stable)
  std::vector<std::vector<uint32_t>> colour_bins;  // bins of each colour

  size_t bin_count() const { return blocks.size(); }

  template <int dim>
  void build(const Particles<dim>& p, const Grid<dim>& g) {
    const size_t n = p.size();
    if (bin_id_.size() != g.block_count()) bin_id_.assign(g.block_count(), -1);
    int threads = omp_get_max_threads();
    if (runs_.size() < static_cast<size_t>(threads)) runs_.resize(threads);
    // 1. Each thread splits its contiguous chunk of particles into runs of consecutive particles in the same
    //    block. Particles are kept sorted by block (reordered every few steps), so the runs are few: about one
    //    per block, plus one per particle that has crossed into another block since. The later passes work on
    //    runs, so a particle's block is computed once per build, and no per-particle block is stored.
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num(), nt = omp_get_num_threads();
      if (t == 0) threads = nt;  // the chunks below must be the same in every region
      const size_t lo = n * t / nt, hi = n * (t + 1) / nt;
      auto& runs = runs_[t];
      runs.clear();
      for (size_t k = lo; k < hi; ++k) {
        const auto b = static_cast<uint32_t>(bin_block(p.x[k], g));
        if (runs.empty() || runs.back().block != b) runs.push_back({b, static_cast<uint32_t>(k), static_cast<uint32_t>(k)});
        ++runs.back().end;
      }
    }
    // 2. The distinct blocks, ascending, and the map lattice block -> bin.
    blocks.clear();
    for (int t = 0; t < threads; ++t)
      for (const Run& r : runs_[t])
        if (blocks.empty() || blocks.back() != r.block) blocks.push_back(r.block);
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    const size_t nb = blocks.size();
    for (size_t j = 0; j < nb; ++j) bin_id_[blocks[j]] = static_cast<int32_t>(j);
    // 3. Per-thread counts per bin, then write positions per (bin, thread), then a stable parallel fill.
    std::vector<std::vector<uint32_t>> count(threads, std::vector<uint32_t>(nb, 0));
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      auto& c = count[t];
      for (const Run& r : runs_[t]) c[bin_id_[r.block]] += r.end - r.begin;
    }
    start.assign(nb + 1, 0);
    uint32_t at = 0;
    for (size_t j = 0; j < nb; ++j) {
      start[j] = at;
      for (int t = 0; t < threads; ++t) {
        const uint32_t c = count[t][j];
        count[t][j] = at;
        at += c;
      }
    }
    start[nb] = at;
    order.resize(n);
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      auto& c = count[t];
      for (const Run& r : runs_[t]) {
        uint32_t& w = c[bin_id_[r.block]];
        for (uint32_t k = r.begin; k < r.end; ++k) order[w++] = k;
      }
    }
    for (const uint32_t b : blocks) bin_id_[b] = -1;
    colour_bins.assign(1u << dim, {});
    for (size_t j = 0; j < nb; ++j) colour_bins[g.block_colour(blocks[j])].push_back(static_cast<uint32_t>(j));
  }

 private:
  struct Run {
    uint32_t block, begin, end;  // particles [begin, end) lie in lattice block `block`
  };
  std::vector<int32_t> bin_id_;          // per lattice block: its bin during build, -1 otherwise
  std::vector<std::vector<Run>> runs_;   // per thread: the runs of its chunk (kept to reuse their storage)
};

}  // namespace cdmpm
