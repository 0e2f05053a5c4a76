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
// any thread count.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <omp.h>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"

namespace cdmpm {

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
    // The block of particle k, recomputed in each pass rather than stored (4 B per particle less at peak).
    auto block_of = [&](size_t k) {
      const BSplineStencil<dim> s(p.x[k] * g.inv_dx);
      return static_cast<uint32_t>(g.block_index(g.block_of(s.base)));
    };
    int threads = omp_get_max_threads();
    std::vector<std::vector<uint32_t>> seen(threads);
    // 1. Each thread lists the blocks where its run of particles changes block (particles are kept sorted by
    //    block, so these lists are short).
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num(), nt = omp_get_num_threads();
      if (t == 0) threads = nt;  // the chunks below must be the same in every region
      const size_t lo = n * t / nt, hi = n * (t + 1) / nt;
      uint32_t last = UINT32_MAX;
      for (size_t k = lo; k < hi; ++k) {
        const uint32_t b = block_of(k);
        if (b != last) seen[t].push_back(last = b);
      }
    }
    // 2. The distinct blocks, ascending, and the map lattice block -> bin.
    blocks.clear();
    for (const auto& s : seen) blocks.insert(blocks.end(), s.begin(), s.end());
    seen.clear();
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    const size_t nb = blocks.size();
    for (size_t j = 0; j < nb; ++j) bin_id_[blocks[j]] = static_cast<int32_t>(j);
    // 3. Per-thread counts per bin, then write positions per (bin, thread), then a stable parallel fill.
    std::vector<std::vector<uint32_t>> count(threads, std::vector<uint32_t>(nb, 0));
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num(), nt = omp_get_num_threads();
      const size_t lo = n * t / nt, hi = n * (t + 1) / nt;
      auto& c = count[t];
      for (size_t k = lo; k < hi; ++k) ++c[bin_id_[block_of(k)]];
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
      const int t = omp_get_thread_num(), nt = omp_get_num_threads();
      const size_t lo = n * t / nt, hi = n * (t + 1) / nt;
      auto& c = count[t];
      for (size_t k = lo; k < hi; ++k) order[c[bin_id_[block_of(k)]]++] = static_cast<uint32_t>(k);
    }
    for (const uint32_t b : blocks) bin_id_[b] = -1;
    colour_bins.assign(1u << dim, {});
    for (size_t j = 0; j < nb; ++j) colour_bins[g.block_colour(blocks[j])].push_back(static_cast<uint32_t>(j));
  }

 private:
  std::vector<int32_t> bin_id_;  // per lattice block: its bin during build, -1 otherwise
};

}  // namespace cdmpm
