// seeding.h - the initial particles of a scene: every body's shape filled on a lattice, in its initial state.
//
// Particles sit on the lattice (k + 1/2) dx / n, n = ppc^(1/dim) per axis, so bodies that share a face tile
// without gaps or overlaps. A lattice point is left empty if it lies in a hole of the body, in one of its
// surface crevasses (shape/crevasse_field.h: a slot cut down from the column's top ice), inside a rigid body
// (for the other bodies: a pool around a block) or inside the solid of any boundary (terrain, obstacles:
// Boundary::is_solid; a fluid body's points in the bed layer of a well-balanced bed fill that layer instead,
// sim/bed_layer.h). With `hydrostatic` (default) bodies start in equilibrium under gravity, d being the
// depth below the body's surface level, each material in its own initial state (InitialState of its model):
//   fluids: pre-compressed to the pressure of a column at rest, dp/dd = rho0 |g| / J(p) (about rho0 |g| d);
//   solids: lithostatic state sigma_v = -rho0 |g| d, sigma_h = k sigma_v, d measured from the body's own top in
//           each lattice column (unless surface_level is given); k = lateral_stress_ratio, 0 by default (a
//           laterally free slab on a bed: uniaxial, in equilibrium with a free vertical face), 1 cryostatic
//           (isotropic: the deviatoric stress relaxed by creep, as deep in a glacier; a free face is then out of
//           balance by the full overburden and the ice near it responds elastically from the first step).
// The particle's current volume is (dx/n)^dim; its reference volume is that over J, its mass rho0 times that.
// Solid-state bodies are seeded first, so that adding their particles is an append (core/particles.h).
// Particles get consecutive ids in seeding order: a particle's id is its index in the one-process array.
// A distributed run seeds twice (sim/simulation.cpp): once keeping nothing, to count the particles of every block
// for the first partition, then keeping only the particles of this rank's blocks (`keep`), so no rank ever holds
// the whole scene; the bed layer of a well-balanced bed is kept whole on every rank (a layer of particles along
// the bed, split later: parallel/bed_part.h).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "boundary/boundary.h"
#include "core/particles.h"
#include "scene/scene.h"
#include "sim/bed_layer.h"

namespace cdmpm {

// Which particles a process keeps, asked with each particle's index in the one-process array (its id) and its
// position; empty: all.
template <int dim>
using SeedFilter = std::function<bool(uint64_t index, const Vec<dim>& x)>;

// Seeds every body of the scene; sets each material's half particle spacing. Throws SceneError naming a body
// that seeds no particle. With `bed`, the lattice points of fluid bodies in a boundary's bed layer
// (Boundary::in_bed_layer) are seeded into it, in the same state (sim/bed_layer.h). With `keep`, only the particles
// it accepts are added, with their ids. Returns the number of particles the scene seeds (kept or not), which is
// particles.next_id after.
template <int dim>
uint64_t seed_bodies(const Scene& scene, std::vector<Material>& materials,
                     const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries, Particles<dim>& particles,
                     BedLayer<dim>* bed = nullptr, const SeedFilter<dim>& keep = {});

}  // namespace cdmpm
