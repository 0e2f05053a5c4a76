// bed_part.h - a well-balanced bed's layer of fixed particles (sim/bed_layer.h) in a distributed run (MPI build;
// docs/architecture.md, "Distributed runs"): every rank seeds the whole layer; each keeps the layer particles whose
// bin block (the block of their stencil base node) it owns, in the whole layer's order, again at every new
// partition (the layer never moves, the cuts do). A block's layer particles are then those of one process in its
// order, so the layer's patches are one process's.
//
// The layer's velocity (BedLayer::take_velocity) reads the mass and momentum of every node of its particles'
// stencils after a scatter of the water with dt = 0. After the halo sum the own nodes are complete; the stencil of a
// layer particle in a block b also reaches the blocks b + {0,1}^dim of higher ranks, where this rank holds partial
// sums or nothing. Their owners send those blocks complete (HaloExchange::complete), as the velocities are copied to
// the halo after the grid update. One process activates every block a layer particle touches, also where no water
// is: so does every rank, its own (`own_touched`) and those its layer particles touch, holding +0 where one process
// does. The lists follow from the whole layer and the partition alone, so every rank computes its part of them
// without an exchange.
#pragma once

#include <algorithm>
#include <vector>

#include "grid/grid.h"
#include "parallel/communicator.h"
#include "parallel/partition.h"
#include "sim/bed_layer.h"

namespace cdmpm {

template <int dim>
class BedPart {
 public:
  // `whole`: the whole layer, binned (Simulation's). Kept by reference: it outlives the run's domain.
  explicit BedPart(const BedLayer<dim>& whole) : whole_(whole) {}

  // This rank's layer and the exchanged blocks for partition `part` (recomputed only when the cuts moved).
  void update(const BlockPartition& part, const Grid<dim>& g) {
    if (part.first == first_) return;
    first_ = part.first;
    const int me = mpi::rank(), ranks = mpi::size();
    const ParticleBins& bins = whole_.bins;
    std::vector<uint32_t> kept;
    to_.assign(ranks, {});
    from_.assign(ranks, {});
    own_touched_.clear();
    for (uint32_t j = 0; j < bins.bin_count(); ++j) {
      const int r = part.owner(bins.blocks[j]);
      if (r == me) kept.insert(kept.end(), bins.order.begin() + bins.start[j], bins.order.begin() + bins.start[j + 1]);
      const IVec<dim> c = g.block_coords(bins.blocks[j]);
      for (int m = 0; m < (1 << dim); ++m) {
        const size_t nb = g.upper_neighbour(c, m);
        if (nb == Grid<dim>::npos) continue;
        const int o = part.owner(nb);
        if (o == r) continue;
        if (r == me) from_[o].push_back(static_cast<uint32_t>(nb));
        if (o == me) to_[r].push_back(static_cast<uint32_t>(nb)), own_touched_.push_back(static_cast<uint32_t>(nb));
      }
    }
    for (auto& list : to_) sort_unique(list);
    for (auto& list : from_) sort_unique(list);
    sort_unique(own_touched_);
    std::sort(kept.begin(), kept.end());
    mine_.particles = whole_.particles.extract(kept);
    mine_.normal.resize(kept.size());
    for (size_t i = 0; i < kept.size(); ++i) mine_.normal[i] = whole_.normal[kept[i]];
    mine_.bins.build(mine_.particles, g);
  }

  // This rank's layer particles, binned.
  BedLayer<dim>& mine() { return mine_; }
  // Own blocks that other ranks' layer particles touch (active as in one process).
  const std::vector<uint32_t>& own_touched() const { return own_touched_; }
  // Per rank r: the own blocks r's layer particles touch (sent complete to r), and r's blocks this rank's touch.
  const std::vector<std::vector<uint32_t>>& to() const { return to_; }
  const std::vector<std::vector<uint32_t>>& from() const { return from_; }

 private:
  const BedLayer<dim>& whole_;
  std::vector<uint32_t> first_;  // the partition's cuts that the lists below are for
  BedLayer<dim> mine_;
  std::vector<uint32_t> own_touched_;
  std::vector<std::vector<uint32_t>> to_, from_;
};

}  // namespace cdmpm
