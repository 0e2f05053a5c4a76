// j_bar.h - the J-bar pressure of a fluid (the volumetric part of F-bar: de Souza Neto et al. 1996; in MPM,
// e.g. Coombs et al. 2018): each particle's stress is taken at the mean volume ratio of the particles of its
// material in its cell, not at its own J.
//
// With 4 (2D) or 8 (3D) particles per cell, each advancing its own J from the grid's velocity (material/water.h),
// the water must keep more volume constraints than the grid has velocities, and at the acoustic time step the
// excess locks the flow around a body: the particles' pressures split into patterns from one particle row to
// the next (+-5 kPa at 1 m depth beside a rising 0.4 m block at dx = 5 cm), which the grid does not see as force
// but which hold the shared velocity field back (docs/water.md, "Buoyancy: J-bar and FLIP"). The mean over a
// cell leaves one constraint per cell and material:
//   Jbar_p = sum_{q in cell(p), material(q) = material(p)} V0_q J_q / sum V0_q,
// the cell being the particles of one stencil base node (the cell-sized region [base + 1/2, base + 3/2) dx around
// node base + 1, so all of them lie in one bin: particle_bins.h), V0_q = m_q / rho0 (m_q with one material).
// The state J of each particle is unchanged; only the stress of p2g uses Jbar. So nothing resists one particle's J
// where the flow converges on it more than on its cell: beside the corners of a rising block at dx = D/32 single
// particles reach J = 0.80 by 0.2 s, and the time step, set by the stiffest particle's own J, halves
// (docs/changelog.md, "Buoyancy coupling", 2026-12-05: the stall at D/32).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/material.h"

namespace cdmpm {

// Jbar of every particle of a material with j_bar (its own J for the others).
template <int dim>
void cell_mean_J(const Particles<dim>& p, const std::vector<Material>& materials, const Grid<dim>& g,
                 const ParticleBins& bins, std::vector<Real>& Jbar) {
  Jbar = p.J;
  const size_t nb = bins.bin_count();
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t j = 0; j < nb; ++j) {
    // (cell within the bin's block, material, particle), sorted: each run of one cell and material is averaged in
    // the order of its particles, whatever the thread.
    std::vector<std::array<uint64_t, 2>> keys;
    for (uint32_t k = bins.start[j]; k < bins.start[j + 1]; ++k) {
      const uint32_t q = bins.order[k];
      if (!materials[p.material[q]].j_bar()) continue;
      const BSplineStencil<dim> s(p.x[q] * g.inv_dx);
      uint64_t cell = 0;
      for (int a = 0; a < dim; ++a) cell = (cell << 16) | (static_cast<uint64_t>(s.base[a]) & 0xFFFF);  // one block: distinct
      keys.push_back({(cell << 8) | p.material[q], q});
    }
    std::sort(keys.begin(), keys.end());
    for (size_t a = 0; a < keys.size();) {
      size_t b = a;
      double vj = 0, v = 0;
      for (; b < keys.size() && keys[b][0] == keys[a][0]; ++b) {
        const size_t q = keys[b][1];
        vj += double(p.mass[q]) * p.J[q], v += p.mass[q];
      }
      for (size_t c = a; c < b; ++c) Jbar[keys[c][1]] = static_cast<Real>(vj / v);
      a = b;
    }
  }
}

}  // namespace cdmpm
