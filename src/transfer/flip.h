// flip.h - a FLIP share in the velocity update of g2p (Brackbill & Ruppel 1986; in MPM with APIC's affine
// transfer: Fei et al. 2021, "Revisiting integration in the material point method").
//
// APIC replaces a particle's velocity at every step by the grid's, v_p = sum_i w_ip v_i^{n+1} (g2p.h): what the
// grid cannot represent (a shear layer a cell thick, a kink at a material interface) is smoothed away once per
// step, a numerical viscosity of order dx^2 / dt. At the acoustic time step of weakly compressible water, dt ~
// dx / c, that is of order c dx: a 0.4 m block in a pool at dx = 5 cm rises through a creeping (Stokes) flow
// that fills the pool (docs/water.md, "Buoyancy: J-bar and FLIP"). FLIP adds only the grid's change of velocity:
//   v_p <- (1 - a) sum_i w_ip v_i^{n+1} + a [v_p + sum_i w_ip (v_i^{n+1} - v_i^n)]
//        = sum_i w_ip v_i^{n+1} + a u_p,   u_p = v_p - sum_i w_ip v_i^n,
// with a = the material's `flip` and v_i^n the grid velocity of the transfer alone (p2g with dt = 0, the
// boundaries' fold and unfold, no force). u_p is what the grid did not see of the particle's velocity; it is taken
// before g2p (flip_residual) and added after it (flip_blend). C_p stays APIC's. a = 0 is APIC unchanged.
// Momentum: p2g conserves it, so sum_p m_p u_p = sum_p m_p v_p - sum_i m_i v_i^n = 0 (up to the boundaries'
// fold and unfold): the FLIP share adds no momentum, it keeps on the particles what the grid smoothed away.
//
// XPIC(m) (Hammerquist & Nairn 2017, CMAME 318, "A new method for material point method particle updates
// that reduces noise and enhances stability"; the material key `xpic`). Plain FLIP keeps all of
// u_p, including the part no grid field can represent (the transfer's null space), which grows into noise. XPIC
// keeps instead the part that the grid's consistent mass matrix represents: with S the g2p map (V = S v) and S+
// PIC's lumped p2g map (v = m^-1 S^T W V), the consistent projection of the particle velocities V is
// v* = (S+ S)^-1 S+ V = sum_k (I - S+ S)^(k-1) S+ V, truncated after m terms:
//   D_1 = S+ V,   D_k = D_{k-1} - S+ S D_{k-1},   v* = D_1 + ... + D_m,
//   u_p = sum_i w_ip (v*_i - v_i^n) = sum_i w_ip (D_1 + ... + D_m - v^n)_i,
// the particle's velocity V_p of FLIP replaced by S v*. v^n stays the transfer of p2g (APIC's, with C_p), so
// u_p keeps cancelling p2g's own transfer; the recurrence is PIC's (no C_p), as in the paper. (Starting it from
// APIC's v^n instead is unstable: APIC's round trip keeps a grid-scale mode that S+ S nearly removes, so the
// series amplifies it, by 1 + A per step at m = 2, A = 1 - (S+ S's symbol) up to 0.98 for the grid-scale modes
// in 2D.) m = 1 is PIC's velocity with APIC's affine C_p; as m grows u_p tends to FLIP's without its null-space
// part. Each order costs a PIC p2g and a g2p of all particles (the filter acts on the one velocity field); the
// terms are added to u_p per material, up to its own order (xpic_accumulate). xpic_filter below runs the
// recurrence, from Simulation::flip_transfer.
#pragma once

#include <vector>

#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"
#include "material/material.h"
#include "transfer/g2p.h"

namespace cdmpm {

// u_p = v_p - sum_i w_ip v_i for the particles of materials with a FLIP share (0 for the others), v_i the grid
// velocity now held in g.momentum.
template <int dim>
void flip_residual(const Particles<dim>& p, const std::vector<Material>& materials, const Grid<dim>& g,
                   const ParticleBins& bins, std::vector<Vec<dim>>& u) {
  u.assign(p.size(), Vec<dim>::Zero());
  gather_velocity(p, g, bins, [&](uint32_t q, const Vec<dim>& v, const Mat<dim>&, const auto&) {
    const Material& m = materials[p.material[q]];
    if (m.flip() > 0) u[q] = (m.xpic() == 0 ? p.v[q] : Vec<dim>::Zero()) - v;  // XPIC: + S v*, xpic_accumulate
  });
}

// z_p = sum_i w_ip v_i for every particle (PIC's interpolation S v), v_i in g.momentum.
template <int dim>
void interpolate_velocity(const Particles<dim>& p, const Grid<dim>& g, const ParticleBins& bins,
                          std::vector<Vec<dim>>& z) {
  z.resize(p.size());
  gather_velocity(p, g, bins, [&](uint32_t q, const Vec<dim>& v, const Mat<dim>&, const auto&) { z[q] = v; });
}

// u_p += z_p (z = S D_k, the k-th term of the XPIC recurrence at the particles) for the particles whose
// material's XPIC order is at least k.
template <int dim>
void xpic_accumulate(const Particles<dim>& p, const std::vector<Material>& materials, int k,
                     const std::vector<Vec<dim>>& z, std::vector<Vec<dim>>& u) {
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q)
    if (materials[p.material[q]].xpic() >= k) u[q] += z[q];
}

// Work arrays of the XPIC recurrence, kept between steps.
template <int dim>
struct XpicScratch {
  std::vector<Vec<dim>> D, z;  // D_k per node; S D_k per particle, the velocities the particles carry through S+
  std::vector<Mat<dim>> zero_C;  // no affine part in S+
};

// The XPIC recurrence up to `order`: D_1 = S+ V, D_k = D_{k-1} - S+ S D_{k-1}, each S D_k added to u_p of the
// materials of order k or more (u_p holding -sum_i w_ip v_i^n for them, flip_residual). transfer() must leave
// S+ of the particles' present v in g.momentum: a transfer-only p2g into the cleared grid, the boundaries' fold,
// v = mv / m, their unfold. The particles' C is swapped out for zeros throughout, their v for S D_k in turn.
template <int dim, class Transfer>
void xpic_filter(Particles<dim>& p, const std::vector<Material>& materials, Grid<dim>& g, const ParticleBins& bins,
                 int order, Transfer&& transfer, XpicScratch<dim>& s, std::vector<Vec<dim>>& u) {
  if (s.zero_C.size() != p.size()) s.zero_C.assign(p.size(), Mat<dim>::Zero());
  std::swap(p.C, s.zero_C);
  transfer();  // S+ V
  s.D = g.momentum;  // D_1
  for (int k = 1;; ++k) {
    interpolate_velocity(p, g, bins, s.z);  // S D_k
    xpic_accumulate(p, materials, k, s.z, u);
    if (k == order) break;
    std::swap(p.v, s.z);
    transfer();  // g.momentum: S+ S D_k
    std::swap(p.v, s.z);
    const size_t nodes = s.D.size();
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < nodes; ++i) g.momentum[i] = s.D[i] -= g.momentum[i];  // D_{k+1}
  }
  std::swap(p.C, s.zero_C);
}

// After g2p: v_p += a u_p.
template <int dim>
void flip_blend(Particles<dim>& p, const std::vector<Material>& materials, const std::vector<Vec<dim>>& u) {
  const size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q)
    if (const Real a = materials[p.material[q]].flip(); a > 0) p.v[q] += a * u[q];
}

}  // namespace cdmpm
