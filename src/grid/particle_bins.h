// particle_bins.h - particles binned by grid block, for the race-free, deterministic scatter.
//
// A stable counting sort of particle indices by the block that holds their stencil base node. Blocks of
// one colour (same parity of block coordinates on every axis) are at least two blocks apart on some axis;
// with 4-node blocks and a 3-node stencil their particles write disjoint node sets. Processing colours in a
// fixed order, blocks of a colour in parallel, and a block's particles in index order makes every node sum
// the same terms in the same order whatever the thread count: results are bitwise reproducible.
#pragma once

#include <cstdint>
#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"

namespace cdmpm {

struct ParticleBins {
  std::vector<uint32_t> order;         // particle indices sorted by block (stable)
  std::vector<uint32_t> block_start;   // order[block_start[b] .. block_start[b+1]) are block b's
  std::vector<std::vector<uint32_t>> colour_blocks;  // non-empty blocks of each colour

  template <int dim>
  void build(const Particles<dim>& p, const Grid<dim>& g) {
    const size_t n = p.size(), nb = g.block_count();
    std::vector<uint32_t> block(n);
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < n; ++k) {
      const BSplineStencil<dim> s(p.x[k] * g.inv_dx);
      block[k] = static_cast<uint32_t>(g.block_index(g.block_of(s.base)));
    }
    block_start.assign(nb + 1, 0);
    for (size_t k = 0; k < n; ++k) ++block_start[block[k] + 1];
    for (size_t b = 0; b < nb; ++b) block_start[b + 1] += block_start[b];
    order.resize(n);
    std::vector<uint32_t> fill(block_start.begin(), block_start.end() - 1);
    for (size_t k = 0; k < n; ++k) order[fill[block[k]]++] = static_cast<uint32_t>(k);
    colour_blocks.assign(1u << dim, {});
    for (size_t b = 0; b < nb; ++b)
      if (block_start[b + 1] > block_start[b]) colour_blocks[g.block_colour(b)].push_back(static_cast<uint32_t>(b));
  }
};

}  // namespace cdmpm
