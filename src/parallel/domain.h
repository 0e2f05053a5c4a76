// domain.h - the state of a distributed run on one rank (MPI build; docs/architecture.md): the partition of the
// block order (parallel/partition.h), the order keys of this rank's particles (parallel/migration.h), the halo
// exchanges (parallel/halo_exchange.h), and the dynamic load balancing: at each particle sort (every
// Simulation::reorder_interval steps) the particle imbalance max / mean over the ranks is measured and, above
// rebalance_threshold (mpirun option of `cdmpm run`: --rebalance, default 1.1), the blocks are partitioned again for
// the current counts and the particles migrate; a well-balanced bed's fixed layer is split again for the new cuts
// (parallel/bed_part.h). The imbalance measured at each sort (before any new partition) is
// recorded: the last, the largest, and the largest after the first new partition (summary.json "distributed").
// None of this changes a result: a run gives the same bits on any number of ranks and with any threshold.
#pragma once

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "parallel/bed_part.h"
#include "parallel/communicator.h"
#include "parallel/halo_exchange.h"
#include "parallel/migration.h"
#include "parallel/mirror_zone.h"
#include "parallel/partition.h"

namespace cdmpm {

// Above this max / mean particle imbalance a sort step partitions the blocks again (set by `cdmpm run --rebalance`).
inline double rebalance_threshold = 1.1;

template <int dim>
class Domain {
 public:
  // Every rank has seeded the whole scene identically: the first partition is computed from all particles, and
  // each rank keeps those in its blocks (keys: the seeding order, the one-process array before its first sort).
  // `joined`: pairs of blocks that one rank must own together (the mirror pairs of static slip boxes,
  // Boundary::mirror_node_pairs; the walls' pairs are shared instead, parallel/mirror_zone.h). `bed`: the whole
  // bed layer of the well-balanced beds, binned (sim/bed_layer.h; kept by reference), or null if there is none.
  Domain(Particles<dim>& p, const Grid<dim>& g, const Vec<dim>& domain_size,
         const std::vector<std::array<size_t, 2>>& joined = {}, const BedLayer<dim>* bed = nullptr)
      : zone_(g, domain_size) {
    if (!joined.empty()) allowed_ = every_cut(g.block_count());
    for (const auto& [a, b] : joined) keep_together(allowed_, a, b);
    std::vector<uint32_t> blocks;
    std::vector<uint64_t> counts;
    count_blocks(p, g, blocks, counts);
    part_ = balanced_partition(blocks, counts, mpi::size(), g.block_count(), allowed_);
    keys_.resize(p.size());
    std::iota(keys_.begin(), keys_.end(), uint64_t(0));
    std::vector<uint32_t> kept;
    for (size_t q = 0; q < p.size(); ++q)
      if (part_.owner(particle_block(p, q, g)) == mpi::rank()) kept.push_back(static_cast<uint32_t>(q));
    if (kept.size() != p.size()) {
      p.permute(kept);
      keep_keys(keys_, kept);
    }
    if (bed && !bed->empty()) {
      bed_ = std::make_unique<BedPart<dim>>(*bed);
      bed_->update(part_, g);
    }
  }

  // The sort of a reorder step (as one process: stable by block, solids first), the new keys, and a new partition
  // if the imbalance passed the threshold. Leaves bins built for the current particles.
  void sort(Particles<dim>& p, const Grid<dim>& g, ParticleBins& bins) {
    bins.build(p, g);
    p.permute(std::move(bins.order));
    rekey_after_sort(p, keys_);
    bins.build(p, g);
    std::vector<uint64_t> counts(bins.bin_count());
    for (size_t j = 0; j < counts.size(); ++j) counts[j] = bins.start[j + 1] - bins.start[j];
    // Every rank's (block, count) pairs; blocks of different ranks are distinct and ascend with the rank.
    mpi::Bytes mine;
    for (size_t j = 0; j < counts.size(); ++j) mpi::put(mine, bins.blocks[j]), mpi::put(mine, counts[j]);
    std::vector<uint32_t> all_blocks;
    std::vector<uint64_t> all_counts;
    for (const mpi::Bytes& b : mpi::allgather(mine)) {
      mpi::Reader read{b};
      while (!read.done()) all_blocks.push_back(read.get<uint32_t>()), all_counts.push_back(read.get<uint64_t>());
    }
    last_imbalance_ = imbalance(rank_counts(part_, all_blocks, all_counts));
    max_imbalance_ = std::max(max_imbalance_, last_imbalance_);
    if (repartitions_ > 0) max_imbalance_repartitioned_ = std::max(max_imbalance_repartitioned_, last_imbalance_);
    if (mpi::size() == 1 || last_imbalance_ <= rebalance_threshold) return;
    const BlockPartition next = balanced_partition(all_blocks, all_counts, mpi::size(), g.block_count(), allowed_);
    if (next.first == part_.first) return;
    part_ = next;
    ++repartitions_;
    migrated_ += migrate(p, keys_, g, part_);
    bins.build(p, g);
    if (bed_) bed_->update(part_, g);
  }

  // After advection: particles to the ranks owning their blocks.
  void migrate_particles(Particles<dim>& p, const Grid<dim>& g) { migrated_ += migrate(p, keys_, g, part_); }

  // After the sinks removed particles (p.permute(kept)): their keys go with them (sim/sinks.h).
  void removed(const std::vector<uint32_t>& kept) { keep_keys(keys_, kept); }

  // The order keys of this rank's particles (their indices in the one-process array at the last sort), ascending.
  const std::vector<uint64_t>& keys() const { return keys_; }

  Particles<dim> gather(const Particles<dim>& p, bool solids_only = false) const {
    return gather_particles(p, keys_, solids_only);
  }

  // p2g with the halo exchanges (parallel/halo_exchange.h). With a bed layer as one process does it
  // (Simulation::advance): the water's scatter with dt = 0, complete on the layer's stencils (bed_part.h), gives the
  // layer's velocity; then the water's scatter and the layer's after it.
  void p2g(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins, Grid<dim>& g,
           Real dt) {
    if (!bed_) return halo.p2g({{&p, &bins}}, materials, g, dt, part_, zone_);
    BedLayer<dim>& layer = bed_->mine();
    halo.p2g({{&p, &bins}}, materials, g, Real(0), part_, zone_, layer.bins.blocks, bed_->own_touched());
    halo.complete(g, bed_->to(), bed_->from());
    layer.take_velocity(g);
    halo.p2g({{&p, &bins}, {&layer.particles, &layer.bins}}, materials, g, dt, part_, zone_);
  }

  HaloExchange<dim> halo;
  const BlockPartition& partition() const { return part_; }
  // The particle imbalance max / mean over the ranks at the last sort, the largest at any sort, and the largest at
  // the sorts after the first new partition (0 if there was none).
  double last_imbalance() const { return last_imbalance_; }
  double max_imbalance() const { return max_imbalance_; }
  double max_imbalance_repartitioned() const { return max_imbalance_repartitioned_; }
  long long repartitions() const { return repartitions_; }
  double migrated() const { return migrated_; }

 private:
  static void count_blocks(const Particles<dim>& p, const Grid<dim>& g, std::vector<uint32_t>& blocks,
                           std::vector<uint64_t>& counts) {
    ParticleBins bins;
    bins.build(p, g);
    blocks = bins.blocks;
    counts.resize(bins.bin_count());
    for (size_t j = 0; j < counts.size(); ++j) counts[j] = bins.start[j + 1] - bins.start[j];
  }

  MirrorZone<dim> zone_;
  std::unique_ptr<BedPart<dim>> bed_;  // this rank's part of the bed layer (null without one)
  std::vector<uint8_t> allowed_;  // where cuts may lie (partition.h; empty: anywhere)
  BlockPartition part_;
  std::vector<uint64_t> keys_;
  double last_imbalance_ = 1, max_imbalance_ = 1, max_imbalance_repartitioned_ = 0;
  long long repartitions_ = 0;
  double migrated_ = 0;
};

}  // namespace cdmpm
