// reference_step.h - a slow, dense, textbook MPM step written from the equations, to check the optimised
// engine step (sim/simulation.cpp) against (tests/engine/test_reference_step.cpp).
//
// Nothing here is shared with the engine's transfers or grid: one dense array of nodes over the whole domain
// lattice (nodes i dx, i in [-ghost, n_cells + ghost] per axis), plain loops over the particles, and the
// quadratic B-spline kernel written out again. Only the constitutive models' own functions are called
// (WeaklyCompressibleWater::kirchhoff, NeoHookeanSplit::kirchhoff, CohesiveCamClay::return_mapping), so a
// refactor that moves the engine's phases around leaves this file unchanged.
//
// One step of size dt, symplectic Euler (Jiang et al. 2016 course notes, sec. 9 and 10; Jiang et al. 2015,
// APIC; Hu et al. 2018, MLS-MPM eq. 17-18 for the force in the affine term):
//   weights   N(r) = 3/4 - r^2 (|r| < 1/2), (3/2 - |r|)^2 / 2 (1/2 <= |r| < 3/2), 0 otherwise  (course notes
//             eq. 123), w_ip = prod_a N(x_pa / dx - i_a), D^-1 = 4 / dx^2;
//   p2g       m_i = sum_p w_ip m_p,
//             (m v)_i = sum_p w_ip [m_p v_p + (m_p C_p - dt V0_p D^-1 tau_p) (x_i - x_p)],
//             V0_p = m_p / rho0 and tau_p the Kirchhoff stress of the particle's state before the step;
//   grid      v_i = (m v)_i / m_i + dt g for m_i > 0; slip domain walls: the normal component of v_i is zeroed
//             at the nodes on or beyond a face (course notes sec. 10);
//   g2p       v_p = sum_i w_ip v_i,  C_p = D^-1 sum_i w_ip v_i (x_i - x_p)^T;
//   update    J_p <- J_p (1 + dt tr C_p); ice: F_trial = (I + dt C_p) F_p, then the Cam-Clay return mapping
//             with p0(alpha_p) (course notes eq. 202; Wolper et al. 2019, sec. 4); x_p <- x_p + dt v_p.
#pragma once

#include <cmath>
#include <vector>

#include "core/particles.h"
#include "material/cohesive_cam_clay.h"
#include "material/neo_hookean_split.h"
#include "material/weakly_compressible_water.h"

namespace cdmpm::reference {

// One material of the reference step, built by the test from the same numbers as its scene.
struct RefMaterial {
  bool ice = false;
  Real rho0 = 1000;
  WeaklyCompressibleWater water;  // water: equation of state and viscosity
  NeoHookeanSplit elastic;        // ice: elasticity
  CohesiveCamClay plastic;        // ice: plasticity (if `plasticity`)
  bool plasticity = true;
  bool plane_strain = false;      // 2D ice: the 3x3 state diag(F, Fz) (material/ice.h)
};

// Quadratic B-spline N(r), r in cells.
inline Real kernel(Real r) {
  r = std::abs(r);
  if (r < Real(0.5)) return Real(0.75) - r * r;
  if (r < Real(1.5)) return Real(0.5) * (Real(1.5) - r) * (Real(1.5) - r);
  return 0;
}

template <int dim>
class DenseStep {
 public:
  static constexpr int ghost = 3;

  // domain [0, size] with spacing dx; gravity g; slip walls on every face if `slip_walls`.
  DenseStep(const Vec<dim>& size, Real dx, const Vec<dim>& g, std::vector<RefMaterial> materials, bool slip_walls)
      : size_(size), dx_(dx), g_(g), materials_(std::move(materials)), slip_walls_(slip_walls) {
    nodes_ = 1;
    for (int a = 0; a < dim; ++a) {
      cells_[a] = static_cast<int>(std::ceil(size[a] / dx - 1e-9));
      extent_[a] = cells_[a] + 1 + 2 * ghost;
      nodes_ *= static_cast<size_t>(extent_[a]);
    }
  }

  void step(Particles<dim>& p, Real dt) const {
    const Real Dinv = 4 / (dx_ * dx_);
    std::vector<Real> m(nodes_, 0.0);
    std::vector<Vec<dim>> mv(nodes_, Vec<dim>::Zero());
    // p2g
    for (size_t q = 0; q < p.size(); ++q) {
      const RefMaterial& mat = materials_[p.material[q]];
      const Real V0 = p.mass[q] / mat.rho0;
      Mat<dim> tau;
      if (!mat.ice) {
        tau = mat.water.kirchhoff<dim>(p.J[q], p.C[q]);
      } else if (mat.plane_strain) {  // plane strain: the in-plane block of the 3x3 state's stress
        Mat<3> F3 = Mat<3>::Zero();
        F3.template topLeftCorner<dim, dim>() = p.F[q];
        F3(2, 2) = p.out_of_plane(q);
        tau = mat.elastic.kirchhoff<3>(F3).template topLeftCorner<dim, dim>();
      } else {
        tau = mat.elastic.kirchhoff<dim>(p.F[q]);
      }
      const Mat<dim> affine = p.mass[q] * p.C[q] - dt * V0 * Dinv * tau;
      for_each_node(p.x[q], [&](size_t k, Real w, const Vec<dim>& xi) {
        m[k] += w * p.mass[q];
        mv[k] += w * (p.mass[q] * p.v[q] + affine * (xi - p.x[q]));
      });
    }
    // grid update
    std::vector<Vec<dim>> v(nodes_, Vec<dim>::Zero());
    for (size_t k = 0; k < nodes_; ++k) {
      if (m[k] <= 0) continue;
      v[k] = mv[k] / m[k] + dt * g_;
      if (!slip_walls_) continue;
      const Vec<dim> xi = position(k);
      for (int a = 0; a < dim; ++a)
        if (xi[a] <= 1e-3 * dx_ || xi[a] >= size_[a] - 1e-3 * dx_) v[k][a] = 0;
    }
    // g2p, constitutive update, advection
    for (size_t q = 0; q < p.size(); ++q) {
      Vec<dim> vp = Vec<dim>::Zero();
      Mat<dim> B = Mat<dim>::Zero();
      for_each_node(p.x[q], [&](size_t k, Real w, const Vec<dim>& xi) {
        vp += w * v[k];
        B += w * v[k] * (xi - p.x[q]).transpose();
      });
      p.v[q] = vp;
      p.C[q] = Dinv * B;
      p.J[q] *= 1 + dt * p.C[q].trace();
      const RefMaterial& mat = materials_[p.material[q]];
      if (mat.ice) {
        Mat<dim> F = (Mat<dim>::Identity() + dt * p.C[q]) * p.F[q];
        const Real p0 = mat.plastic.p0_of_alpha(p.alpha[q], mat.elastic.kappa);
        if constexpr (dim == 2) {
          if (mat.plasticity && mat.plane_strain) mat.plastic.return_mapping_plane_strain(F, p.Fz[q], p.alpha[q], p0, mat.elastic);
          else if (mat.plasticity) mat.plastic.return_mapping<dim>(F, p.alpha[q], p0, mat.elastic);
        } else if (mat.plasticity) {
          mat.plastic.return_mapping<dim>(F, p.alpha[q], p0, mat.elastic);
        }
        p.F[q] = F;
      }
      p.x[q] += dt * p.v[q];
    }
  }

 private:
  Vec<dim> size_;
  Real dx_;
  Vec<dim> g_;
  std::vector<RefMaterial> materials_;
  bool slip_walls_;
  IVec<dim> cells_, extent_;
  size_t nodes_;

  size_t index(const IVec<dim>& i) const {
    size_t k = 0;
    for (int a = 0; a < dim; ++a) k = k * extent_[a] + static_cast<size_t>(i[a] + ghost);
    return k;
  }
  Vec<dim> position(size_t k) const {
    Vec<dim> x;
    for (int a = dim - 1; a >= 0; --a) {
      x[a] = (static_cast<int>(k % extent_[a]) - ghost) * dx_;
      k /= extent_[a];
    }
    return x;
  }
  // Calls f(node, w_ip, x_i) for the 3^dim nodes i = floor(x/dx - 1/2) + {0,1,2}^dim around position x.
  template <class Fn>
  void for_each_node(const Vec<dim>& x, Fn&& f) const {
    IVec<dim> base;
    for (int a = 0; a < dim; ++a) base[a] = static_cast<int>(std::floor(x[a] / dx_ - 0.5));
    for (int o = 0; o < (dim == 2 ? 9 : 27); ++o) {
      IVec<dim> i;
      for (int a = 0, r = o; a < dim; ++a, r /= 3) i[a] = base[a] + r % 3;
      Real w = 1;
      Vec<dim> xi;
      for (int a = 0; a < dim; ++a) {
        xi[a] = i[a] * dx_;
        w *= kernel(x[a] / dx_ - i[a]);
      }
      f(index(i), w, xi);
    }
  }
};

}  // namespace cdmpm::reference
