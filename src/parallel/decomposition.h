// decomposition.h - the decomposition of a scene before any particle exists (docs/architecture.md): the particles
// the scene seeds in every block (a seeding pass that keeps none, sim/seeding.h), the blocks one rank must own
// together (the mirror pairs of static slip boxes, parallel/partition.h), and, for a partition of those counts,
// what each rank would hold and send in a step (RankPlan, plan_ranks). A distributed run partitions its first
// particles from these counts (sim/simulation.cpp); `cdmpm run --dry-run --ranks N` reports the plan for any N
// without allocating the particles (run/run_plan.h). No MPI here: both builds compile it.
//
// The traffic of a step, as parallel/halo_exchange.h sends it: every occupied bin block b of rank r whose upper
// neighbours b + {0,1}^dim include blocks of other ranks sends its whole patch (block_patch.h: (4 + 2)^dim nodes,
// 4 + sizeof(PatchRecords) bytes) to each of those ranks; the receiver holds those blocks as halo, and their
// owners send back the velocities of every halo block (block_nodes x sizeof(Vec)); and the owner of each active
// block b of a wall's mirror zone sends its mass and momentum to every other rank owning a block of D(b)
// (parallel/mirror_zone.h; the active blocks of a rank: its blocks that any occupied block's patch reaches). Not
// counted: the bed layer's ghost nodes (parallel/bed_part.h) and the migration of particles.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "boundary/boundary.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "parallel/mirror_zone.h"
#include "parallel/partition.h"
#include "sim/seeding.h"
#include "transfer/block_patch.h"

namespace cdmpm {

// The number of particles the scene seeds in every block of g (indexed by block; nothing is kept, so the cost is
// 4 bytes per lattice block). Sets the materials' half spacings as seeding does; with `bed`, seeds the bed layer
// of the well-balanced beds into it (sim/bed_layer.h).
template <int dim>
std::vector<uint32_t> seeded_per_block(const Scene& scene, std::vector<Material>& materials,
                                       const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries,
                                       const Grid<dim>& g, BedLayer<dim>* bed = nullptr) {
  std::vector<uint32_t> per_block(g.block_count(), 0);
  Particles<dim> none;
  seed_bodies<dim>(scene, materials, boundaries, none, bed, [&](uint64_t, const Vec<dim>& x) {
    ++per_block[bin_block(x, g)];
    return false;
  });
  return per_block;
}

// The pairs of blocks one rank must own together: those of the boundaries' mirror node pairs (parallel/partition.h).
template <int dim>
std::vector<std::array<size_t, 2>> joined_blocks(const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries,
                                                 const Grid<dim>& g) {
  std::vector<std::array<size_t, 2>> joined;
  for (const auto& b : boundaries)
    for (const auto& [i, j] : b->mirror_node_pairs(g)) joined.push_back({g.block_index(g.block_of(i)), g.block_index(g.block_of(j))});
  return joined;
}

// What one rank holds and sends in a step under a partition.
struct RankPlan {
  uint64_t particles = 0;
  uint64_t occupied_blocks = 0;  // own blocks holding particles (bins)
  uint64_t halo_blocks = 0;      // other ranks' blocks its patches reach (held as halo)
  uint64_t patches_sent = 0;     // (bin block, destination rank) pairs
  uint64_t zone_blocks_sent = 0;  // (mirror-zone block, destination rank) pairs
  double halo_bytes_sent = 0;    // patches, mirror-zone blocks and the velocities of its blocks other ranks hold as
                                 // halo, per step
};

// The plan of every rank for occupied `blocks` (ascending) holding `counts` particles, under `part`, with the walls'
// mirror zone `zone`.
template <int dim>
std::vector<RankPlan> plan_ranks(const std::vector<uint32_t>& blocks, const std::vector<uint64_t>& counts,
                                 const BlockPartition& part, const Grid<dim>& g, const MirrorZone<dim>& zone) {
  std::vector<RankPlan> plan(part.ranks());
  constexpr double patch_bytes = sizeof(uint32_t) + sizeof(PatchRecords<dim>);
  constexpr double velocity_bytes = Grid<dim>::block_nodes * sizeof(Vec<dim>);
  constexpr double zone_bytes = Grid<dim>::block_nodes * (sizeof(Real) + sizeof(Vec<dim>));
  // Per rank: the other ranks' blocks it holds as halo, and its own active blocks.
  std::vector<std::vector<uint32_t>> halo(part.ranks()), active(part.ranks());
  for (size_t j = 0; j < blocks.size(); ++j) {
    const int r = part.owner(blocks[j]);
    plan[r].particles += counts[j];
    ++plan[r].occupied_blocks;
    const IVec<dim> c = g.block_coords(blocks[j]);
    int to[1 << dim], destinations = 0;
    for (int m = 0; m < (1 << dim); ++m) {
      const size_t nb = g.upper_neighbour(c, m);
      if (nb == Grid<dim>::npos) continue;
      const int o = part.owner(nb);
      active[o].push_back(static_cast<uint32_t>(nb));
      if (o == r) continue;
      halo[r].push_back(static_cast<uint32_t>(nb));
      bool seen = false;
      for (int k = 0; k < destinations; ++k) seen = seen || to[k] == o;
      if (!seen) to[destinations++] = o;
    }
    plan[r].patches_sent += destinations;
    plan[r].halo_bytes_sent += destinations * patch_bytes;
  }
  for (int r = 0; r < part.ranks(); ++r) {
    sort_unique(halo[r]);
    plan[r].halo_blocks = halo[r].size();
    for (const uint32_t b : halo[r]) plan[part.owner(b)].halo_bytes_sent += velocity_bytes;
    sort_unique(active[r]);
    for (const uint32_t b : active[r]) {
      if (!zone.holds(g, b)) continue;
      std::vector<int> to;
      zone.for_each_dependency(g, b, [&](size_t d) {
        const int o = part.owner(d);
        if (o != r && std::find(to.begin(), to.end(), o) == to.end()) to.push_back(o);
      });
      plan[r].zone_blocks_sent += to.size();
      plan[r].halo_bytes_sent += to.size() * zone_bytes;
    }
  }
  return plan;
}

}  // namespace cdmpm
