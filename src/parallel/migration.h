// migration.h - the particles of a distributed run (MPI build; docs/architecture.md): their order keys, the
// migration after advection to the ranks owning their blocks, and the gather of the whole set to rank 0.
//
// The order rule. One process keeps its particle array sorted by block every Simulation::reorder_interval steps
// (a stable sort by the block of the stencil base node, then the solids moved in front, sim/simulation.cpp), and
// between two sorts the order is that of the last sort. The scatter adds a block's particles in array order, so a
// node's sum depends on that order. Every particle of a distributed run carries a key: its index in the
// one-process array at the last sort. Each rank keeps its particles sorted by key; then the particles of any block
// are in the one-process order. At a sort, each rank sorts its own particles by (block, key), solids first, as one
// process does; since the ranks own contiguous ranges of the block order, the one-process array is rank 0's
// solids, rank 1's solids, ..., then rank 0's fluids, rank 1's fluids, ..., so the new key of a rank's i-th solid is
// (solids on lower ranks) + i and of its j-th fluid (all solids) + (fluids on lower ranks) + j. Keys travel with
// migrating particles; the receiver merges by key. Gathering the particles to rank 0 in key order gives the
// one-process array itself, so the written frames and checkpoints are those of one process.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "parallel/communicator.h"
#include "parallel/partition.h"

namespace cdmpm {

// One particle with its key, as sent between ranks (F, alpha and fz are zero for a fluid).
template <int dim>
struct ParticleRecord {
  uint64_t key, id;
  Real x[dim], v[dim], C[dim * dim], F[dim * dim];
  Real mass, J, alpha, fz;
  uint8_t material, solid;

  static ParticleRecord of(const Particles<dim>& p, size_t q, uint64_t key) {
    ParticleRecord r{};
    r.key = key;
    r.id = p.id[q];
    Eigen::Map<Vec<dim>>(r.x) = p.x[q];
    Eigen::Map<Vec<dim>>(r.v) = p.v[q];
    Eigen::Map<Mat<dim>>(r.C) = p.C[q];
    r.mass = p.mass[q];
    r.J = p.J[q];
    r.material = p.material[q];
    r.solid = q < p.solid_count();
    if (r.solid) {
      Eigen::Map<Mat<dim>>(r.F) = p.F[q];
      r.alpha = p.alpha[q];
      r.fz = p.out_of_plane(q);
    }
    return r;
  }
  // Appends the particle to p (in key order, solids first: every solid key is below every fluid key).
  void append_to(Particles<dim>& p) const {
    const uint64_t next = p.next_id;
    const Vec<dim> xp = Eigen::Map<const Vec<dim>>(x), vp = Eigen::Map<const Vec<dim>>(v);
    const Mat<dim> Cp = Eigen::Map<const Mat<dim>>(C);
    if (solid) p.add_solid(xp, vp, mass, J, material, Cp, Eigen::Map<const Mat<dim>>(F), alpha, fz);
    else p.add_fluid(xp, vp, mass, J, material, Cp);
    p.id[solid ? p.solid_count() - 1 : p.size() - 1] = id;
    p.next_id = next;
  }
};

// The block of particle q's stencil base node (its bin block, grid/particle_bins.h).
template <int dim>
size_t particle_block(const Particles<dim>& p, size_t q, const Grid<dim>& g) {
  return bin_block(p.x[q], g);
}

// The keys of the particles kept by p.permute(kept) (kept ascending: a removal or a departure), in place.
inline void keep_keys(std::vector<uint64_t>& keys, const std::vector<uint32_t>& kept) {
  for (size_t k = 0; k < kept.size(); ++k) keys[k] = keys[kept[k]];
  keys.resize(kept.size());
}

// Rebuilds p (and keys) from records, in key order.
template <int dim>
void rebuild_in_key_order(std::vector<ParticleRecord<dim>>& records, Particles<dim>& p, std::vector<uint64_t>& keys) {
  std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
  Particles<dim> out;
  out.next_id = p.next_id;
  keys.resize(records.size());
  for (size_t i = 0; i < records.size(); ++i) {
    records[i].append_to(out);
    keys[i] = records[i].key;
  }
  p = std::move(out);
}

template <int dim>
std::vector<ParticleRecord<dim>> unpack_records(const std::vector<mpi::Bytes>& buffers) {
  std::vector<ParticleRecord<dim>> records;
  for (const mpi::Bytes& b : buffers) {
    const size_t n = b.size() / sizeof(ParticleRecord<dim>);
    const size_t at = records.size();
    records.resize(at + n);
    std::copy(b.begin(), b.end(), reinterpret_cast<char*>(records.data() + at));
  }
  return records;
}

// Sends every particle whose block another rank owns to that rank and merges the arrivals by key. Collective.
// Returns the number of particles this rank sent.
template <int dim>
size_t migrate(Particles<dim>& p, std::vector<uint64_t>& keys, const Grid<dim>& g, const BlockPartition& part) {
  const int me = mpi::rank();
  const size_t n = p.size();
  std::vector<int> owner(n);
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q) owner[q] = part.owner(particle_block(p, q, g));
  std::vector<mpi::Bytes> out(mpi::size());
  std::vector<uint32_t> kept;
  kept.reserve(n);
  for (size_t q = 0; q < n; ++q) {
    if (owner[q] == me) kept.push_back(static_cast<uint32_t>(q));
    else mpi::put(out[owner[q]], ParticleRecord<dim>::of(p, q, keys[q]));
  }
  const size_t sent = n - kept.size();
  std::vector<mpi::Bytes> in = mpi::exchange(out);
  std::vector<ParticleRecord<dim>> arrivals = unpack_records<dim>(in);
  if (arrivals.empty()) {
    if (sent == 0) return 0;
    p.permute(kept);  // an increasing subset: compacted in place, order kept
    keep_keys(keys, kept);
    return sent;
  }
  arrivals.reserve(arrivals.size() + kept.size());
  for (const uint32_t q : kept) arrivals.push_back(ParticleRecord<dim>::of(p, q, keys[q]));
  rebuild_in_key_order(arrivals, p, keys);
  return sent;
}

// Every rank's particles on rank 0, in key order (the one-process array); an empty set elsewhere. Collective.
template <int dim>
Particles<dim> gather_particles(const Particles<dim>& p, const std::vector<uint64_t>& keys) {
  const size_t n = p.size();
  mpi::Bytes local;
  local.reserve(n * sizeof(ParticleRecord<dim>));
  for (size_t q = 0; q < n; ++q) mpi::put(local, ParticleRecord<dim>::of(p, q, keys[q]));
  std::vector<ParticleRecord<dim>> all = unpack_records<dim>(mpi::gather(local));
  Particles<dim> whole;
  whole.next_id = p.next_id;
  std::vector<uint64_t> whole_keys;
  if (mpi::rank() == 0) rebuild_in_key_order(all, whole, whole_keys);
  return whole;
}

// The keys after a sort (see above): solids on lower ranks, then all solids and fluids on lower ranks. Collective.
template <int dim>
void rekey_after_sort(const Particles<dim>& p, std::vector<uint64_t>& keys) {
  const uint64_t mine[2] = {p.solid_count(), p.size() - p.solid_count()};
  mpi::Bytes b;
  mpi::put(b, mine, 2);
  const std::vector<mpi::Bytes> all = mpi::allgather(b);
  uint64_t solids_below = 0, fluids_below = 0, solids = 0;
  for (int r = 0; r < static_cast<int>(all.size()); ++r) {
    mpi::Reader read{all[r]};
    const uint64_t ns = read.get<uint64_t>(), nf = read.get<uint64_t>();
    if (r < mpi::rank()) solids_below += ns, fluids_below += nf;
    solids += ns;
  }
  keys.resize(p.size());
  for (size_t q = 0; q < p.size(); ++q)
    keys[q] = q < p.solid_count() ? solids_below + q : solids + fluids_below + (q - p.solid_count());
}

}  // namespace cdmpm
