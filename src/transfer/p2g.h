// p2g.h - particle-to-grid transfer of mass and momentum (APIC) with the internal-force impulse.
//
// For each particle p and stencil node i with weight w_ip (Jiang et al. 2015, eq. 8; Hu et al. 2018,
// MLS-MPM eq. 17-18):
//   m_i   += w_ip m_p
//   (mv)_i += w_ip [ m_p v_p + (m_p C_p - dt V0_p D^-1 tau_p) (x_i - x_p) ]
// where C_p is the APIC affine matrix, tau_p the Kirchhoff stress, V0_p the reference volume and
// D^-1 = 4/dx^2 for quadratic B-splines. The stress term is the explicit force -dt sum_p V0_p tau_p grad w_ip
// in its moving-least-squares form. With dt = 0 this is the pure APIC transfer, which conserves mass,
// linear and angular momentum exactly.
//
// Which particles scatter is the field's choice: the shared field takes every material without `contact`; the
// solids' field (Field::solid) takes the deformable materials with `contact` (ice; sim/field_contact.h). The
// particles of a rigid body in contact are in neither: they scatter into their body's own field
// (sim/rigid_contact.h).
//
// Race-free and deterministic: blocks of one colour run in parallel, colours in sequence (particle_bins.h).
// Each block's particles scatter into a dense patch that is then added to the sparse grid (block_patch.h).
#pragma once

#include <array>
#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/stress.h"
#include "transfer/block_patch.h"

namespace cdmpm {

// The velocity field a scatter fills (see the header).
enum class Field : uint8_t { shared, solid };

// Whether material m scatters into field f.
inline bool scatters_into(const Material& m, Field f) {
  return f == Field::shared ? !m.contact() : m.contact() && !m.traits().rigid;
}

// Scatters the particles of bin j into acc (zero on entry): the patch contribution of one block.
template <int dim>
void scatter_bin(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins,
                 const Grid<dim>& g, uint32_t j, Real dt, PatchAccumulator<dim>& acc, Field field = Field::shared) {
  const Real Dinv = Real(4) * g.inv_dx * g.inv_dx;
  const BlockPatch<dim> patch(g, bins.blocks[j]);
  std::array<uint8_t, 256> in_field{};  // per material id (uint8_t): scatters into this field
  for (size_t mi = 0; mi < materials.size() && mi < in_field.size(); ++mi) in_field[mi] = scatters_into(materials[mi], field);
  for (uint32_t k = bins.start[j]; k < bins.start[j + 1]; ++k) {
    const uint32_t q = bins.order[k];
    if (!in_field[p.material[q]]) continue;
    const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
    const Real m = p.mass[q];
    Mat<dim> affine = m * p.C[q];
    if (dt != 0) {
      const Material& mat = materials[p.material[q]];
      affine -= (dt * reference_volume(mat, m) * Dinv) * kirchhoff_stress(mat, p, q);
    }
    // Affine term in units of dx: (x_i - x_p) = dx (o - fx), so node i's share is
    // w_i (m v - A fx + A o) with A = affine * dx.
    affine *= g.dx;
    scatter_to_patch<dim>(acc, s, patch.base_index(s), m, m * p.v[q] - affine * s.fx, affine);
  }
}

// Adds a block's patch contribution to the active grid nodes it covers.
template <int dim>
void add_patch(Grid<dim>& g, uint32_t block, const PatchRecords<dim>& node) {
  const BlockPatch<dim> patch(g, block);
  patch.for_each_node([&](int n, size_t k) {
    g.mass[k] += node[n][0];
    g.momentum[k] += node[n].template segment<dim>(1);
  });
}

// The scatter, colour by colour; after_colour(c) runs after the blocks of colour c (a distributed run adds there
// the contributions of colour c that other ranks computed, parallel/halo_exchange.h).
template <int dim, class AfterColour>
void p2g(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins, Grid<dim>& g,
         Real dt, AfterColour&& after_colour, Field field = Field::shared) {
  for (size_t c = 0; c < bins.colour_bins.size(); ++c) {
    const auto& colour = bins.colour_bins[c];
#pragma omp parallel for schedule(dynamic, 4)
    for (size_t ci = 0; ci < colour.size(); ++ci) {
      const uint32_t j = colour[ci];
      PatchAccumulator<dim> acc;
      scatter_bin(p, materials, bins, g, j, dt, acc, field);
      add_patch(g, bins.blocks[j], acc.node);
    }
    after_colour(static_cast<int>(c));
  }
}

template <int dim>
void p2g(const Particles<dim>& p, const std::vector<Material>& materials, const ParticleBins& bins, Grid<dim>& g,
         Real dt) {
  p2g(p, materials, bins, g, dt, [](int) {});
}

}  // namespace cdmpm
