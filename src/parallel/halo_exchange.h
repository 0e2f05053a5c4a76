// halo_exchange.h - the grid exchanges of a distributed step (MPI build; docs/architecture.md, sim/phases.h):
//
// 1. Halo sum (p2g). In one process a node's mass and momentum are 0 + (patch of the colour-0 bin block that
//    touches it) + (colour-1 patch) + ... in colour order, skipping colours with no such bin (at most one bin
//    block of each colour touches a node; bin block b touches blocks b + {0,1}^dim; transfer/p2g.h,
//    block_patch.h). Every rank first computes the patch of each of its bin blocks that touches a block it does not
//    own and sends that patch, whole and not summed with anything, to the owners of those blocks. The owner then
//    scatters colour by colour as one process does and, after its own blocks of colour c, adds the received patches
//    of colour c: each owned node gets exactly the one-process sum, in the one-process order, with absent colours
//    skipped (no explicit zeros, which would turn -0.0 into +0.0). Contributions only flow up the block order
//    (b + {0,1}^dim >= b), so from lower ranks to higher ones. The owner also activates its blocks that only the
//    received patches touch.
// 3. Mirror zone (after the halo sum, before the fold; parallel/mirror_zone.h). A cut may separate a wall's ghost
//    node from its mirror node. The owner of an active block b in a wall's zone sends it, complete, to every other
//    rank owning a block of D(b): first the list of those blocks (before the grid is activated, so the receiver
//    activates exactly the blocks active in one process), then after the halo sum their mass and momentum, which
//    replace the receiver's partial values. Every rank then holds complete inputs for the fold, grid update and
//    unfold of its own blocks, and computes them as one process does.
// 2. Velocity copy (before g2p). After the grid update and the unfold, which run on complete sums (3.), each owner sends the velocities of its blocks that another
//    rank holds as halo (the blocks the received patches touched) to that rank, which copies them into its halo.
// Both sides list the exchanged blocks in ascending block order, so a message is the blocks' nodes, nothing else.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "parallel/communicator.h"
#include "parallel/mirror_zone.h"
#include "parallel/partition.h"
#include "transfer/p2g.h"

namespace cdmpm {

template <int dim>
class HaloExchange {
 public:
  // p2g of this rank's particles with the halo sum (1. above) and the mirror zone (3.); activates the grid first.
  void p2g(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins, Grid<dim>& g,
           Real dt, const BlockPartition& part, const MirrorZone<dim>& zone) {
    const int me = mpi::rank(), ranks = mpi::size();
    // The bins whose patch reaches blocks of other ranks, and those ranks.
    std::vector<uint32_t> boundary;
    std::vector<std::vector<int>> dest;
    ghost_from_.assign(ranks, {});
    for (uint32_t j = 0; j < bins.bin_count(); ++j) {
      const IVec<dim> c = g.block_coords(bins.blocks[j]);
      std::vector<int> to;
      for (int m = 0; m < (1 << dim); ++m) {
        const size_t nb = g.upper_neighbour(c, m);
        if (nb == Grid<dim>::npos) continue;
        const int r = part.owner(nb);
        if (r == me) continue;
        ghost_from_[r].push_back(static_cast<uint32_t>(nb));
        if (std::find(to.begin(), to.end(), r) == to.end()) to.push_back(r);
      }
      if (!to.empty()) {
        boundary.push_back(j);
        dest.push_back(std::move(to));
      }
    }
    for (auto& list : ghost_from_) sort_unique(list);
    std::vector<PatchAccumulator<dim>> acc(boundary.size());
#pragma omp parallel for schedule(dynamic, 4)
    for (size_t i = 0; i < boundary.size(); ++i) scatter_bin(p, materials, bins, g, boundary[i], dt, acc[i]);
    std::vector<mpi::Bytes> out(ranks);
    for (size_t i = 0; i < boundary.size(); ++i)
      for (const int r : dest[i]) {
        mpi::put(out[r], bins.blocks[boundary[i]]);
        mpi::put(out[r], acc[i].node.data(), acc[i].node.size());
        halo_bytes_ += sizeof(uint32_t) + sizeof(acc[i].node);
      }
    received_ = mpi::exchange(out);
    // The received patches by colour, and the own blocks they touch.
    incoming_.assign(1u << dim, {});
    shared_to_.assign(ranks, {});
    std::vector<uint32_t> extra;
    for (int s = 0; s < static_cast<int>(received_.size()); ++s) {
      const mpi::Bytes& b = received_[s];
      for (size_t at = 0; at < b.size(); at += sizeof(uint32_t) + sizeof(PatchRecords<dim>)) {
        uint32_t block;
        std::copy(b.data() + at, b.data() + at + sizeof block, reinterpret_cast<char*>(&block));
        incoming_[g.block_colour(block)].push_back({block, b.data() + at + sizeof block});
        const IVec<dim> c = g.block_coords(block);
        for (int m = 0; m < (1 << dim); ++m) {
          const size_t nb = g.upper_neighbour(c, m);
          if (nb == Grid<dim>::npos || part.owner(nb) != me) continue;
          extra.push_back(static_cast<uint32_t>(nb));
          shared_to_[s].push_back(static_cast<uint32_t>(nb));
        }
      }
    }
    for (auto& list : shared_to_) sort_unique(list);
    sort_unique(extra);
    announce_zone(bins, g, part, zone, extra);
    g.activate(bins.blocks, extra);
    cdmpm::p2g(p, materials, bins, g, dt, [&](int colour) {
      const auto& in = incoming_[colour];
#pragma omp parallel for schedule(static)
      for (size_t i = 0; i < in.size(); ++i) {
        PatchRecords<dim> node;
        std::copy(in[i].data, in[i].data + sizeof node, reinterpret_cast<char*>(node.data()));
        add_patch(g, in[i].block, node);
      }
    });
    share_zone(g);
  }

  // The velocity copy (2. above), after the unfold.
  void share_velocities(Grid<dim>& g) {
    const int ranks = mpi::size();
    std::vector<mpi::Bytes> out(ranks);
    for (int r = 0; r < ranks; ++r)
      for (const uint32_t b : shared_to_[r]) {
        const size_t k = g.block_storage(b);
        if (k == Grid<dim>::npos) mpi::abort("halo block " + std::to_string(b) + " is not active on its owner", 1);
        mpi::put(out[r], g.momentum.data() + k, Grid<dim>::block_nodes);
        halo_bytes_ += Grid<dim>::block_nodes * sizeof(Vec<dim>);
      }
    const std::vector<mpi::Bytes> in = mpi::exchange(out);
    for (int r = 0; r < ranks; ++r) {
      const auto& list = ghost_from_[r];
      if (in[r].size() != list.size() * Grid<dim>::block_nodes * sizeof(Vec<dim>))
        mpi::abort("velocity halo from rank " + std::to_string(r) + " has " + std::to_string(in[r].size()) +
                       " bytes, expected " + std::to_string(list.size()) + " blocks",
                   1);
      mpi::Reader read{in[r]};
      for (const uint32_t b : list) read.get(g.momentum.data() + g.block_storage(b), Grid<dim>::block_nodes);
    }
  }

  // Bytes sent by this rank in both exchanges since the start.
  double halo_bytes() const { return halo_bytes_; }

 private:
  struct Incoming {
    uint32_t block;
    const char* data;  // the patch records, in received_
  };
  // 3. above, first part: the active own blocks of the mirror zone to the ranks owning blocks of their D, and
  // theirs to `extra` (the blocks to activate besides those of the particles).
  void announce_zone(const ParticleBins& bins, const Grid<dim>& g, const BlockPartition& part, const MirrorZone<dim>& zone,
                     std::vector<uint32_t>& extra) {
    const int me = mpi::rank(), ranks = mpi::size();
    std::vector<uint32_t> mine = extra;  // this rank's active blocks: extra holds only own blocks so far
    for (const uint32_t b : bins.blocks) {
      const IVec<dim> c = g.block_coords(b);
      for (int m = 0; m < (1 << dim); ++m) {
        const size_t nb = g.upper_neighbour(c, m);
        if (nb != Grid<dim>::npos && part.owner(nb) == me) mine.push_back(static_cast<uint32_t>(nb));
      }
    }
    sort_unique(mine);
    zone_to_.assign(ranks, {});
    for (const uint32_t b : mine)
      if (zone.holds(g, b))
        zone.for_each_dependency(g, b, [&](size_t d) {
          const int r = part.owner(d);
          if (r != me) zone_to_[r].push_back(b);
        });
    std::vector<mpi::Bytes> out(ranks);
    for (int r = 0; r < ranks; ++r) {
      sort_unique(zone_to_[r]);
      mpi::put(out[r], zone_to_[r].data(), zone_to_[r].size());
    }
    const std::vector<mpi::Bytes> in = mpi::exchange(out);
    zone_from_.assign(ranks, {});
    for (int r = 0; r < ranks; ++r) {
      zone_from_[r].resize(in[r].size() / sizeof(uint32_t));
      mpi::Reader{in[r]}.get(zone_from_[r].data(), zone_from_[r].size());
      extra.insert(extra.end(), zone_from_[r].begin(), zone_from_[r].end());
    }
    sort_unique(extra);
  }

  // 3. above, second part: the complete mass and momentum of the announced blocks.
  void share_zone(Grid<dim>& g) {
    const int ranks = mpi::size();
    constexpr size_t n = Grid<dim>::block_nodes;
    std::vector<mpi::Bytes> out(ranks);
    for (int r = 0; r < ranks; ++r)
      for (const uint32_t b : zone_to_[r]) {
        const size_t k = g.block_storage(b);
        mpi::put(out[r], g.mass.data() + k, n);
        mpi::put(out[r], g.momentum.data() + k, n);
        halo_bytes_ += n * (sizeof(Real) + sizeof(Vec<dim>));
      }
    const std::vector<mpi::Bytes> in = mpi::exchange(out);
    for (int r = 0; r < ranks; ++r) {
      mpi::Reader read{in[r]};
      for (const uint32_t b : zone_from_[r]) {
        const size_t k = g.block_storage(b);
        read.get(g.mass.data() + k, n);
        read.get(g.momentum.data() + k, n);
      }
    }
  }

  static void sort_unique(std::vector<uint32_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }

  std::vector<mpi::Bytes> received_;               // this step's received patches (incoming_ points into them)
  std::vector<std::vector<Incoming>> incoming_;    // per colour
  std::vector<std::vector<uint32_t>> ghost_from_;  // per rank: its blocks that this rank holds as halo, ascending
  std::vector<std::vector<uint32_t>> shared_to_;   // per rank: this rank's blocks that rank holds as halo, ascending
  std::vector<std::vector<uint32_t>> zone_to_;     // per rank: this rank's mirror-zone blocks sent there (3.)
  std::vector<std::vector<uint32_t>> zone_from_;   // per rank: that rank's mirror-zone blocks received here (3.)
  double halo_bytes_ = 0;
};

}  // namespace cdmpm
