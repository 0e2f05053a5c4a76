// domain.h - the state of a distributed run on one rank (MPI build; docs/architecture.md): the partition of the
// block order (parallel/partition.h), the order keys of this rank's particles (parallel/migration.h), the halo
// exchanges (parallel/halo_exchange.h), and the dynamic load balancing: at each particle sort (every
// Simulation::reorder_interval steps) the particle imbalance max / mean over the ranks is measured and, above
// rebalance_threshold (mpirun option of `cdmpm run`: --rebalance, default 1.1), the blocks are partitioned again for
// the current counts and the particles migrate; a well-balanced bed's fixed layer is split again for the new cuts
// (parallel/bed_part.h). The imbalance measured at each sort (before any new partition) is
// recorded: the last, the largest, and the largest after the first new partition (summary.json "distributed").
// None of this changes a result: a run gives the same bits on any number of ranks and with any threshold.
// The first partition is made before the particles exist (sim/simulation.cpp: the scene's particles counted per
// block, then each rank seeds only its own), so no rank holds the whole scene; a resumed run partitions the share
// of the checkpoint each rank read, for the counts over all ranks, and migrates the particles to their owners.
#pragma once

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <utility>
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
  // The decomposition before any particle is placed. `joined`: pairs of blocks that one rank must own together
  // (the mirror pairs of static slip boxes, Boundary::mirror_node_pairs; the walls' pairs are shared instead,
  // parallel/mirror_zone.h).
  Domain(const Grid<dim>& g, const Vec<dim>& domain_size, const std::vector<std::array<size_t, 2>>& joined = {})
      : zone_(g, domain_size), allowed_(allowed_cuts(g.block_count(), joined)) {}

  // The first partition, from the number of particles the scene seeds in every block (`per_block`, indexed by
  // block; the same on every rank: seeding is a pure function of the scene, sim/seeding.h).
  void partition_seeded(const std::vector<uint32_t>& per_block, const Grid<dim>& g) {
    std::vector<uint32_t> blocks;
    std::vector<uint64_t> counts;
    occupied_blocks(per_block, blocks, counts);
    part_ = balanced_partition(blocks, counts, mpi::size(), g.block_count(), allowed_);
  }
  // This rank's seeded particles (those of its blocks under partition_seeded's cuts): their keys are their ids,
  // their indices in the one-process array. `bed`: the whole bed layer of the well-balanced beds, binned
  // (sim/bed_layer.h; kept by reference), or null if there is none.
  void adopt_seeded(const Particles<dim>& p, const Grid<dim>& g, const BedLayer<dim>* bed) {
    keys_ = p.id;
    split_bed(g, bed);
  }
  // The particles a checkpoint gave this rank (any share of the whole, `keys` ascending): the blocks are partitioned
  // for the counts over all ranks, and the particles migrate to their owners.
  void adopt_loaded(Particles<dim>& p, std::vector<uint64_t> keys, const Grid<dim>& g, const BedLayer<dim>* bed) {
    keys_ = std::move(keys);
    std::vector<uint32_t> blocks;
    std::vector<uint64_t> counts;
    global_block_counts(p, g, blocks, counts);
    part_ = balanced_partition(blocks, counts, mpi::size(), g.block_count(), allowed_);
    migrate(p, keys_, g, part_);
    split_bed(g, bed);
  }

  // The rank owning the block of a particle at x (its stencil base node's block, grid/particle_bins.h).
  int owner_at(const Vec<dim>& x, const Grid<dim>& g) const { return part_.owner(bin_block(x, g)); }

  // The sort of a reorder step (as one process: stable by block, solids first), the new keys, and a new partition
  // if the imbalance passed the threshold. Leaves bins built for the current particles.
  void sort(Particles<dim>& p, const Grid<dim>& g, ParticleBins& bins) {
    bins.build(p, g);
    p.permute(std::move(bins.order));
    rekey_after_sort(p, keys_);
    bins.build(p, g);
    std::vector<uint32_t> all_blocks;
    std::vector<uint64_t> all_counts;
    global_block_counts(bins, all_blocks, all_counts);
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

  Particles<dim> gather(const Particles<dim>& p) const { return gather_particles(p, keys_); }

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
  // The particle count of every occupied block over all ranks (blocks ascending, distinct), from this rank's bins.
  static void global_block_counts(const ParticleBins& bins, std::vector<uint32_t>& blocks, std::vector<uint64_t>& counts) {
    mpi::Bytes mine;
    for (size_t j = 0; j < bins.bin_count(); ++j)
      mpi::put(mine, bins.blocks[j]), mpi::put(mine, uint64_t(bins.start[j + 1] - bins.start[j]));
    std::vector<std::pair<uint32_t, uint64_t>> all;
    for (const mpi::Bytes& b : mpi::allgather(mine)) {
      mpi::Reader read{b};
      while (!read.done()) {
        const uint32_t block = read.get<uint32_t>();
        all.emplace_back(block, read.get<uint64_t>());
      }
    }
    std::sort(all.begin(), all.end());  // ranks may hold particles of one block (loaded particles, before migration)
    blocks.clear(), counts.clear();
    for (const auto& [block, n] : all) {
      if (!blocks.empty() && blocks.back() == block) counts.back() += n;
      else blocks.push_back(block), counts.push_back(n);
    }
  }
  static void global_block_counts(const Particles<dim>& p, const Grid<dim>& g, std::vector<uint32_t>& blocks,
                                  std::vector<uint64_t>& counts) {
    ParticleBins bins;
    bins.build(p, g);
    global_block_counts(bins, blocks, counts);
  }
  // This rank's part of the bed layer under the current partition (parallel/bed_part.h).
  void split_bed(const Grid<dim>& g, const BedLayer<dim>* bed) {
    if (!bed || bed->empty()) return;
    bed_ = std::make_unique<BedPart<dim>>(*bed);
    bed_->update(part_, g);
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
