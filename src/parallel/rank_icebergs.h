// rank_icebergs.h - iceberg detection across the ranks of a distributed run (MPI build), with the definition and the
// bits of one process (probe/icebergs.h), without gathering the ice: an iceberg may span ranks.
//
// 1. Homes. An ice cell c (cell size dx, probe/icebergs.h) is home to the rank owning the block of node c (its lower
//    corner; clamped to the lattice). A particle lies on the owner of its stencil base node's block
//    (grid/particle_bins.h), node c - 1 or c on each axis, so only the particles within half a cell of a cut are away
//    from their cell's home: they are sent there as records (x, volume, damage, order key: 40 B in 2D, 48 B in 3D).
// 2. Parts. Each rank finds the components of its home cells (IceBodyFinder: a cell's damage summed in order-key
//    order, the one-process order; components' sums exact), with the rim: its intact cells that have a face
//    neighbour homed elsewhere. Components off the rim below min_particles are dropped there.
// 3. Merge. Rank 0 gathers the parts (per component its count, exact sums of volume and moment, box and lowest key:
//    ~540 B per exact sum; per rim cell its coordinates and component), joins components across the rims, sums,
//    sorts and numbers them (merge_ice_parts), and sends every rank the bodies and the body of each of its
//    components.
// 4. Labels. Each rank labels the particles of its parts and sends the labels of the records back to their owners.
// Traffic and rank 0's memory grow with the cuts' surface (rim cells) and the number of components, not with the ice.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "grid/grid.h"
#include "parallel/communicator.h"
#include "parallel/domain.h"
#include "parallel/reduction.h"
#include "probe/icebergs.h"

namespace cdmpm {

namespace rank_icebergs_detail {

template <int dim>
void put_part(mpi::Bytes& b, const IcePart<dim>& part) {
  mpi::put(b, uint64_t(part.components.size()));
  const auto put_sum = [&](ExactSum s) {
    s.normalize();
    mpi::put(b, s.chunks().data(), s.chunks().size());
    mpi::put(b, s.flags());
  };
  for (const IceComponent<dim>& c : part.components) {
    mpi::put(b, c.particles), mpi::put(b, c.first), mpi::put(b, c.lo), mpi::put(b, c.hi), mpi::put(b, uint8_t(c.rim));
    put_sum(c.volume);
    for (int d = 0; d < dim; ++d) put_sum(c.moment[d]);
  }
  mpi::put(b, uint64_t(part.rim.size()));
  for (const auto& [cell, k] : part.rim) mpi::put(b, cell), mpi::put(b, k);
}

template <int dim>
IcePart<dim> get_part(const mpi::Bytes& b) {
  mpi::Reader r{b};
  IcePart<dim> part;
  const auto get_sum = [&](ExactSum& s) {
    r.get(s.chunks().data(), s.chunks().size());
    s.set_flags(r.get<uint8_t>());
  };
  part.components.resize(r.get<uint64_t>());
  for (IceComponent<dim>& c : part.components) {
    c.particles = r.get<uint64_t>(), c.first = r.get<uint64_t>();
    c.lo = r.get<Eigen::Matrix<double, dim, 1>>(), c.hi = r.get<Eigen::Matrix<double, dim, 1>>();
    c.rim = r.get<uint8_t>() != 0;
    get_sum(c.volume);
    for (int d = 0; d < dim; ++d) get_sum(c.moment[d]);
  }
  part.rim.resize(r.get<uint64_t>());
  for (auto& [cell, k] : part.rim) cell = r.get<typename IcePart<dim>::Cell>(), k = r.get<int32_t>();
  return part;
}

}  // namespace rank_icebergs_detail

// This rank's detection traffic since the start (summary.json distributed): detections run, records sent to other
// homes, and (rank 0) the largest number of bytes the merge gathered in one detection.
struct RankIcebergTraffic {
  long long detections = 0;
  double records_sent = 0;
  double merge_bytes_max = 0;
};
inline RankIcebergTraffic rank_iceberg_traffic;

// find_ice_bodies (probe/icebergs.h) over every rank's particles: x, volume, damage, is_ice of this rank's particles,
// `keys` their order keys. Collective. Returns the bodies (the same on every rank) and fills `label` (if non-null)
// with the body of each of this rank's particles, or -1. Throws std::invalid_argument, on every rank, if any ice
// position is not finite.
template <int dim>
std::vector<IceBody<dim>> find_ice_bodies_on_ranks(const std::vector<Vec<dim>>& x, const std::vector<Real>& volume,
                                                   const std::vector<Real>& damage, const std::vector<uint8_t>& is_ice,
                                                   const std::vector<uint64_t>& keys, const Domain<dim>& domain,
                                                   const Grid<dim>& g, Real spacing, int flow_axis, Real damage_threshold,
                                                   size_t min_particles, std::vector<int>* label) {
  using Cell = typename IcePart<dim>::Cell;
  const size_t n = x.size();
  check_ice_body_arguments<dim>(n, volume, damage, is_ice, g.dx, flow_axis);
  if (keys.size() != n) throw std::invalid_argument("find_ice_bodies_on_ranks: one order key per particle");
  if (label) label->assign(n, -1);
  const int me = mpi::rank(), ranks = mpi::size();
  const auto home = [&](const Cell& c) {
    IVec<dim> node;
    for (int a = 0; a < dim; ++a)
      node[a] = static_cast<int>(std::clamp<int64_t>(c[a], -Grid<dim>::ghost, g.n_nodes[a] - 1 - Grid<dim>::ghost));
    return domain.partition().owner(g.block_index(g.block_of(node)));
  };
  // 1. This rank's ice of its home cells, and the records sent to other homes.
  std::vector<Vec<dim>> lx;
  std::vector<Real> lvolume, ldamage;
  std::vector<uint64_t> lkey;
  std::vector<size_t> mine;  // this rank's particle of each local entry (own entries first)
  std::vector<mpi::Bytes> send(static_cast<size_t>(ranks));
  std::vector<std::vector<size_t>> sent(static_cast<size_t>(ranks));
  double nonfinite = 0;
  const auto keep = [&](const Vec<dim>& xp, Real v, Real d, uint64_t k) {
    lx.push_back(xp), lvolume.push_back(v), ldamage.push_back(d), lkey.push_back(k);
  };
  for (size_t p = 0; p < n; ++p) {
    if (!is_ice[p]) continue;
    if (!x[p].allFinite()) {
      ++nonfinite;
      continue;
    }
    Cell c;
    for (int a = 0; a < dim; ++a) c[a] = ice_cell_coord(x[p][a], g.dx);
    const int h = home(c);
    if (h == me) {
      keep(x[p], volume[p], damage[p], keys[p]);
      mine.push_back(p);
    } else {
      mpi::Bytes& b = send[static_cast<size_t>(h)];
      mpi::put(b, x[p]), mpi::put(b, volume[p]), mpi::put(b, damage[p]), mpi::put(b, keys[p]);
      sent[static_cast<size_t>(h)].push_back(p);
      ++rank_iceberg_traffic.records_sent;
    }
  }
  ++rank_iceberg_traffic.detections;
  if (global::sum(nonfinite) > 0) throw std::invalid_argument("find_ice_bodies: non-finite ice particle position");
  const std::vector<mpi::Bytes> received = mpi::exchange(send);
  std::vector<size_t> from(static_cast<size_t>(ranks) + 1, lx.size());  // local entries [from[r], from[r+1]) came from r
  for (int r = 0; r < ranks; ++r) {
    from[static_cast<size_t>(r)] = lx.size();
    for (mpi::Reader rd{received[static_cast<size_t>(r)]}; !rd.done();) {
      const Vec<dim> xp = rd.get<Vec<dim>>();
      const Real v = rd.get<Real>(), d = rd.get<Real>();
      keep(xp, v, d, rd.get<uint64_t>());
    }
  }
  from[static_cast<size_t>(ranks)] = lx.size();
  // 2. This rank's part.
  const std::vector<uint8_t> lice(lx.size(), 1);
  IceBodyFinder<dim> finder(lx, lvolume, ldamage, lice, &lkey, g.dx, damage_threshold);
  IcePart<dim> part;
  if (finder.bin_cells()) {
    finder.occupy();
    finder.unite();
    const auto elsewhere = [&](const Cell& c) { return home(c) != me; };
    part = finder.part(min_particles, &elsewhere);
  } else {
    part.component.assign(lx.size(), -1);
  }
  // 3. The merge on rank 0; every rank gets the bodies and its components' bodies.
  mpi::Bytes mine_bytes;
  rank_icebergs_detail::put_part(mine_bytes, part);
  const std::vector<mpi::Bytes> parts_bytes = mpi::gather(mine_bytes);
  std::vector<mpi::Bytes> reply(static_cast<size_t>(ranks));
  if (me == 0) {
    double bytes = 0;
    for (const mpi::Bytes& b : parts_bytes) bytes += double(b.size());
    rank_iceberg_traffic.merge_bytes_max = std::max(rank_iceberg_traffic.merge_bytes_max, bytes);
    std::vector<IcePart<dim>> parts;
    for (const mpi::Bytes& b : parts_bytes) parts.push_back(rank_icebergs_detail::get_part<dim>(b));
    std::vector<std::vector<int>> body_of;
    const std::vector<IceBody<dim>> bodies = merge_ice_parts<dim>(parts, spacing, flow_axis, min_particles, body_of);
    for (int r = 0; r < ranks; ++r) {
      mpi::Bytes& b = reply[static_cast<size_t>(r)];
      mpi::put(b, uint64_t(bodies.size()));
      mpi::put(b, bodies.data(), bodies.size());
      mpi::put(b, body_of[static_cast<size_t>(r)].data(), body_of[static_cast<size_t>(r)].size());
    }
  }
  const std::vector<mpi::Bytes> answer = mpi::exchange(reply);
  mpi::Reader rd{answer[0]};
  std::vector<IceBody<dim>> bodies(rd.get<uint64_t>());
  rd.get(bodies.data(), bodies.size());
  std::vector<int> body_of(part.components.size());
  rd.get(body_of.data(), body_of.size());
  // 4. Labels: of this rank's own entries here, of the records back to their owners.
  const auto body = [&](size_t i) { return part.component[i] < 0 ? -1 : body_of[static_cast<size_t>(part.component[i])]; };
  if (label)
    for (size_t i = 0; i < mine.size(); ++i) (*label)[mine[i]] = body(i);
  std::vector<mpi::Bytes> back(static_cast<size_t>(ranks));
  for (int r = 0; r < ranks; ++r)
    for (size_t i = from[static_cast<size_t>(r)]; i < from[static_cast<size_t>(r) + 1]; ++i)
      mpi::put(back[static_cast<size_t>(r)], int32_t(body(i)));
  const std::vector<mpi::Bytes> labels = mpi::exchange(back);
  if (label)
    for (int r = 0; r < ranks; ++r) {
      mpi::Reader lr{labels[static_cast<size_t>(r)]};
      for (size_t p : sent[static_cast<size_t>(r)]) (*label)[p] = lr.get<int32_t>();
    }
  return bodies;
}

}  // namespace cdmpm
