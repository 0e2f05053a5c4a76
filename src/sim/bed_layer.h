// bed_layer.h - the well-balanced bed: a layer of fixed water particles inside a sloping slip bed, so that the
// water above it keeps the whole kernel support that a lake at rest needs (the fixed "dummy" wall particles of
// SPH, Adami, Hu & Adams 2012, J. Comput. Phys. 231, 7057, with the hydrostatic wall pressure of their eq. 27).
//
// Why: a grid node near the bed otherwise misses the stress of the water that the bed cuts from its support.
// The discrete force sum_p V_p p_p grad w_ip is then the pressure integral over the cut support, whose
// integration by parts leaves the surface term integral_bed p w_i n dA, of the size of the hydrostatic pressure
// itself (p ~ rho g d, d up to 135 m, where the balance of a node is rho g dx). The slip condition takes the normal
// part of it on the nodes inside the solid, but not on the free nodes just above the bed, nor the part along
// the bed that the lattice of particles meeting a sloping bed in steps leaves: a lake at rest over the Eqip
// Sermia profile ran at 21 m/s after 10 s, particles 10 m deep in the bed (docs/water.md#the-well-balanced-bed).
// Mirror images of the particles across the bed's tangent plane were tried and measured first: they fill the
// support but not on the particles' lattice, and the pressure (10^6 Pa) times that quadrature's error still
// drove the lake to 3 m/s.
//
// The layer: every lattice point of a water body's particle lattice that lies inside a bed within
// 3 dx |n|_1 of its surface (Boundary::in_bed_layer) holds a fixed particle of the body's water, seeded like the
// water (sim/seeding.cpp): hydrostatic pressure below the body's surface level, rho0 |g| d, continued into the bed
// (the hydrostatic extrapolation of the wall pressure). The layer and the water are one lattice, so the
// particle quadrature of the support is the same as in open water, and at rest the force on every node
// balances its weight as in the interior. The layer's particles never move and keep their pressure; each step
// they scatter (p2g, after the water) their mass, their stress and the momentum of the water's velocity where they
// are: v_b is the mass-weighted mean of the velocities of the nodes of their stencil after a scatter of the
// water's mass and momentum alone (p2g with dt = 0; with the stress impulse in it, the layer would add a share of
// the water's force a second time, which measured as a growing motion: 3.5 m/s after 20 s), along the bed
// (v - (v.n) n), so the layer neither drags the water along a slip bed nor pushes it through it. (v_b = 0
// held the lake as still, but is a no-slip drag on a flow along the bed.) The extra scatter costs one more p2g
// per step in scenes with a bed layer.
// They are not written, advected or counted in probes or energies. The slip condition on the nodes inside the bed
// still stops the water's motion into it. Limit: the layer's pressure is the still water's; a wave's dynamic
// pressure at the bed is carried by the slip condition alone, as before.
// Deterministic: v_b is a per-particle gather; the layer is scattered like the particles, in a fixed order. A
// distributed run gives the same bits: each rank holds the layer particles of its blocks, reads the owners' complete
// sums on the nodes of other ranks, and its scatter adds after the water's as here (parallel/bed_part.h).
#pragma once

#include <vector>

#include "core/bspline.h"
#include "core/particles.h"
#include "grid/grid.h"
#include "grid/particle_bins.h"

namespace cdmpm {

template <int dim>
struct BedLayer {
  Particles<dim> particles;
  std::vector<Vec<dim>> normal;  // the bed's unit normal at each particle
  ParticleBins bins;

  bool empty() const { return particles.size() == 0; }

  // The velocity of each layer particle: the mass-weighted mean of the nodes of its stencil (momentum / mass after
  // a scatter of the water without stress), along the bed.
  void take_velocity(const Grid<dim>& g) {
    const size_t n = particles.size();
#pragma omp parallel for schedule(static)
    for (size_t q = 0; q < n; ++q) {
      const BSplineStencil<dim> s(particles.x[q] * g.inv_dx);
      Real m = 0;
      Vec<dim> mv = Vec<dim>::Zero();
      for_each_stencil_node<dim>([&](const IVec<dim>& o) {
        const size_t node = g.find(IVec<dim>(s.base + o));
        if (node == Grid<dim>::npos) return;
        const Real w = s.weight(o);
        m += w * g.mass[node];
        mv += w * g.momentum[node];
      });
      Vec<dim> v = m > 0 ? Vec<dim>(mv / m) : Vec<dim>::Zero();
      particles.v[q] = v - v.dot(normal[q]) * normal[q];
    }
  }
};

}  // namespace cdmpm
