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
//    received patches touch. Several particle sets (the particles, then a well-balanced bed's fixed layer,
//    parallel/bed_part.h) are summed one after the other, as one process's successive p2g calls: each set's
//    patches travel apart and are added in the colour slots of that set's scatter, onto the complete sums of the
//    sets before it, so a node is (set 0 in colour order) + (set 1 in colour order) + ..., the one-process sum.
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

// One set of particles for the scatter, with its bins: the water and solids, or a bed layer's fixed particles.
template <int dim>
struct ScatterSet {
  const Particles<dim>* particles;
  const ParticleBins* bins;
};

template <int dim>
class HaloExchange {
 public:
  // p2g of this rank's particle sets, one after the other, with the halo sum (1. above) and the mirror zone (3.):
  // each set adds onto the complete sums of the sets before it, as one process's successive p2g calls do (so a
  // node is (set 0's patches in colour order) + (set 1's in colour order) + ...). Activates the grid first: the
  // blocks touched by the sets' bins and by `more_bins` (bin blocks of particles not scattered here whose stencil
  // nodes one process activates too, e.g. the bed layer's in the scatter with dt = 0), the own blocks that the
  // received patches touch, and `more_own` (own blocks other ranks' unscattered particles touch).
  void p2g(const std::vector<ScatterSet<dim>>& sets, const std::vector<Material>& materials, Grid<dim>& g, Real dt,
           const BlockPartition& part, const MirrorZone<dim>& zone, const std::vector<uint32_t>& more_bins = {},
           const std::vector<uint32_t>& more_own = {}) {
    const int ranks = mpi::size();
    ghost_from_.assign(ranks, {});
    received_.assign(sets.size(), {});
    for (size_t s = 0; s < sets.size(); ++s) received_[s] = send_patches(sets[s], materials, g, dt, part);
    for (auto& list : ghost_from_) sort_unique(list);
    // The received patches by set and colour, and the own blocks they touch.
    incoming_.assign(sets.size(), std::vector<std::vector<Incoming>>(1u << dim));
    shared_to_.assign(ranks, {});
    std::vector<uint32_t> extra = more_own, binned = more_bins;
    for (size_t s = 0; s < sets.size(); ++s) {
      take_patches(received_[s], incoming_[s], g, part, extra);
      binned.insert(binned.end(), sets[s].bins->blocks.begin(), sets[s].bins->blocks.end());
    }
    for (auto& list : shared_to_) sort_unique(list);
    sort_unique(extra);
    sort_unique(binned);
    announce_zone(binned, g, part, zone, extra);
    g.activate(binned, extra);
    for (size_t s = 0; s < sets.size(); ++s)
      cdmpm::p2g(*sets[s].particles, materials, *sets[s].bins, g, dt, [&](int colour) {
        const auto& in = incoming_[s][colour];
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < in.size(); ++i) {
          PatchRecords<dim> node;
          std::copy(in[i].data, in[i].data + sizeof node, reinterpret_cast<char*>(node.data()));
          add_patch(g, in[i].block, node);
        }
      });
    complete(g, zone_to_, zone_from_);
  }

  // After a halo sum: sends the (complete) mass and momentum of this rank's blocks to[r] to rank r, and replaces
  // those of the blocks from[r] (rank r's) with the ones received from r. Both lists ascending, blocks active on
  // both sides. The mirror zone's copies (3. above) and the bed layer's ghost nodes (parallel/bed_part.h).
  void complete(Grid<dim>& g, const std::vector<std::vector<uint32_t>>& to,
                const std::vector<std::vector<uint32_t>>& from) {
    const int ranks = mpi::size();
    constexpr size_t n = Grid<dim>::block_nodes;
    std::vector<mpi::Bytes> out(ranks);
    for (int r = 0; r < ranks; ++r)
      for (const uint32_t b : to[r]) {
        const size_t k = active_storage(g, b);
        mpi::put(out[r], g.mass.data() + k, n);
        mpi::put(out[r], g.momentum.data() + k, n);
        halo_bytes_ += n * (sizeof(Real) + sizeof(Vec<dim>));
      }
    const std::vector<mpi::Bytes> in = mpi::exchange(out);
    for (int r = 0; r < ranks; ++r) {
      if (in[r].size() != from[r].size() * n * (sizeof(Real) + sizeof(Vec<dim>)))
        mpi::abort("complete blocks from rank " + std::to_string(r) + ": " + std::to_string(in[r].size()) +
                       " bytes, expected " + std::to_string(from[r].size()) + " blocks",
                   1);
      mpi::Reader read{in[r]};
      for (const uint32_t b : from[r]) {
        const size_t k = active_storage(g, b);
        read.get(g.mass.data() + k, n);
        read.get(g.momentum.data() + k, n);
      }
    }
  }

  // The velocity copy (2. above), after the unfold.
  void share_velocities(Grid<dim>& g) {
    const int ranks = mpi::size();
    std::vector<mpi::Bytes> out(ranks);
    for (int r = 0; r < ranks; ++r)
      for (const uint32_t b : shared_to_[r]) {
        mpi::put(out[r], g.momentum.data() + active_storage(g, b), Grid<dim>::block_nodes);
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
      for (const uint32_t b : list) read.get(g.momentum.data() + active_storage(g, b), Grid<dim>::block_nodes);
    }
  }

  // Bytes sent by this rank in both exchanges since the start.
  double halo_bytes() const { return halo_bytes_; }

 private:
  struct Incoming {
    uint32_t block;
    const char* data;  // the patch records, in received_
  };
  // 1. above, sending side, for one set: the patch of each bin whose blocks reach other ranks' blocks, whole, to
  // those ranks (their blocks noted in ghost_from_); returns what the other ranks sent here.
  std::vector<mpi::Bytes> send_patches(const ScatterSet<dim>& set, const std::vector<Material>& materials,
                                       const Grid<dim>& g, Real dt, const BlockPartition& part) {
    const int me = mpi::rank(), ranks = mpi::size();
    const ParticleBins& bins = *set.bins;
    std::vector<uint32_t> boundary;
    std::vector<std::vector<int>> dest;
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
    std::vector<PatchAccumulator<dim>> acc(boundary.size());
#pragma omp parallel for schedule(dynamic, 4)
    for (size_t i = 0; i < boundary.size(); ++i)
      scatter_bin(*set.particles, materials, bins, g, boundary[i], dt, acc[i]);
    std::vector<mpi::Bytes> out(ranks);
    for (size_t i = 0; i < boundary.size(); ++i)
      for (const int r : dest[i]) {
        mpi::put(out[r], bins.blocks[boundary[i]]);
        mpi::put(out[r], acc[i].node.data(), acc[i].node.size());
        halo_bytes_ += sizeof(uint32_t) + sizeof(acc[i].node);
      }
    return mpi::exchange(out);
  }

  // 1. above, receiving side, for one set: the received patches by colour, the own blocks they touch (to `extra`
  // and, per sender, shared_to_).
  void take_patches(const std::vector<mpi::Bytes>& received, std::vector<std::vector<Incoming>>& by_colour,
                    const Grid<dim>& g, const BlockPartition& part, std::vector<uint32_t>& extra) {
    const int me = mpi::rank();
    for (int s = 0; s < static_cast<int>(received.size()); ++s) {
      const mpi::Bytes& b = received[s];
      for (size_t at = 0; at < b.size(); at += sizeof(uint32_t) + sizeof(PatchRecords<dim>)) {
        uint32_t block;
        std::copy(b.data() + at, b.data() + at + sizeof block, reinterpret_cast<char*>(&block));
        by_colour[g.block_colour(block)].push_back({block, b.data() + at + sizeof block});
        const IVec<dim> c = g.block_coords(block);
        for (int m = 0; m < (1 << dim); ++m) {
          const size_t nb = g.upper_neighbour(c, m);
          if (nb == Grid<dim>::npos || part.owner(nb) != me) continue;
          extra.push_back(static_cast<uint32_t>(nb));
          shared_to_[s].push_back(static_cast<uint32_t>(nb));
        }
      }
    }
  }

  // The storage of block b, which an exchange needs active.
  static size_t active_storage(const Grid<dim>& g, uint32_t b) {
    const size_t k = g.block_storage(b);
    if (k == Grid<dim>::npos) mpi::abort("exchanged block " + std::to_string(b) + " is not active", 1);
    return k;
  }

  // 3. above, first part: the active own blocks of the mirror zone to the ranks owning blocks of their D, and
  // theirs to `extra` (the blocks to activate besides those of the particles).
  void announce_zone(const std::vector<uint32_t>& binned, const Grid<dim>& g, const BlockPartition& part,
                     const MirrorZone<dim>& zone, std::vector<uint32_t>& extra) {
    const int me = mpi::rank(), ranks = mpi::size();
    std::vector<uint32_t> mine = extra;  // this rank's active blocks: extra holds only own blocks so far
    for (const uint32_t b : binned) {
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

  std::vector<std::vector<mpi::Bytes>> received_;  // per set: this step's received patches (incoming_ points into them)
  std::vector<std::vector<std::vector<Incoming>>> incoming_;  // per set and colour
  std::vector<std::vector<uint32_t>> ghost_from_;  // per rank: its blocks that this rank holds as halo, ascending
  std::vector<std::vector<uint32_t>> shared_to_;   // per rank: this rank's blocks that rank holds as halo, ascending
  std::vector<std::vector<uint32_t>> zone_to_;     // per rank: this rank's mirror-zone blocks sent there (3.)
  std::vector<std::vector<uint32_t>> zone_from_;   // per rank: that rank's mirror-zone blocks received here (3.)
  double halo_bytes_ = 0;
};

}  // namespace cdmpm
