// run_plan.cpp - the decomposition of a distributed run without its particles (run_plan.h).
#include "run/run_plan.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "boundary/boundary.h"
#include "parallel/decomposition.h"
#include "run/run_estimate.h"
#include "sim/bed_layer.h"

namespace cdmpm {
namespace {

template <int dim>
nlohmann::json plan(const Scene& s, const PlanOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  Vec<dim> size;
  for (int a = 0; a < dim; ++a) size[a] = static_cast<Real>(s.domain.size[a]);
  const Grid<dim> grid(size, static_cast<Real>(s.domain.dx));
  std::vector<std::unique_ptr<Boundary<dim>>> boundaries;
  for (const BoundarySpec& b : s.boundaries) boundaries.push_back(make_boundary<dim>(s, b, BoundaryContext<dim>{size, grid.dx, &boundaries}));
  std::vector<Material> materials = s.materials;
  std::vector<uint32_t> blocks;
  std::vector<uint64_t> counts;
  BedLayer<dim> bed;  // of a well-balanced bed, which every rank seeds whole (sim/seeding.h)
  occupied_blocks(seeded_per_block(s, materials, boundaries, grid, &bed), blocks, counts);
  const uint64_t bed_particles = bed.particles.size();
  const BlockPartition part = balanced_partition(blocks, counts, o.ranks, grid.block_count(),
                                                 allowed_cuts(grid.block_count(), joined_blocks(boundaries, grid)));
  const std::vector<RankPlan> ranks = plan_ranks(blocks, counts, part, grid, MirrorZone<dim>(grid, size));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const double per_particle = bytes_per_particle(dim);
  const double rate = o.core_rate > 0 ? o.core_rate : core_rate(dim);
  const double R = o.ranks;
  const double latency = o.ranks > 1 ? o.latency * (4 * (R - 1) + 6 * 2 * std::log2(R)) : 0;
  uint64_t total = 0, most = 0;
  std::vector<uint64_t> particles;
  double most_bytes = 0, most_memory = 0, slowest = 0;
  nlohmann::json per_rank = nlohmann::json::array();
  for (size_t r = 0; r < ranks.size(); ++r) {
    const RankPlan& p = ranks[r];
    const double memory = (p.particles + bed_particles) * per_particle + process_bytes(grid.block_count()) +
                          2 * p.halo_bytes_sent;
    const double step = p.particles / (rate * o.threads) + p.halo_bytes_sent / o.bandwidth + latency;
    particles.push_back(p.particles);
    total += p.particles;
    most = std::max(most, p.particles);
    most_bytes = std::max(most_bytes, p.halo_bytes_sent);
    most_memory = std::max(most_memory, memory);
    slowest = std::max(slowest, step);
    per_rank.push_back({{"rank", r}, {"first_block", part.first[r]}, {"particles", p.particles},
                        {"occupied_blocks", p.occupied_blocks}, {"halo_blocks", p.halo_blocks},
                        {"patches_sent", p.patches_sent}, {"mirror_zone_blocks_sent", p.zone_blocks_sent},
                        {"halo_bytes_per_step", p.halo_bytes_sent},
                        {"memory_bytes", memory}, {"projected_step_seconds", step}});
  }
  return {{"scene", s.name},
          {"dim", dim},
          {"ranks", o.ranks},
          {"threads_per_rank", o.threads},
          {"particles", total},
          {"bed_layer_particles", bed_particles},
          {"occupied_blocks", blocks.size()},
          {"lattice_blocks", grid.block_count()},
          {"imbalance", imbalance(particles)},
          {"largest_rank_particles", most},
          {"largest_halo_bytes_per_step", most_bytes},
          {"largest_memory_bytes", most_memory},
          {"projected_step_seconds", slowest},
          {"assumptions", {{"bytes_per_particle", per_particle}, {"core_rate", rate},
                           {"bandwidth_bytes_per_second", o.bandwidth}, {"latency_seconds", o.latency}}},
          {"plan_seconds", seconds},
          {"per_rank", per_rank}};
}

}  // namespace

nlohmann::json plan_run(const Scene& scene, const PlanOptions& options) {
  return scene.dim == 2 ? plan<2>(scene, options) : plan<3>(scene, options);
}

}  // namespace cdmpm
