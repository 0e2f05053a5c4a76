// bench_scenes.h - the scenes of the benchmark cases (bench_step.cpp), built as scene json and validated
// like a user scene. Every body is a whole number of cells, every domain side too, so the slip walls lie on
// grid planes and the mirror folding runs as in real scenes.
//
//   water2d, water3d  A still square (cube) of water, side 1 m, in the corner of a domain about 1.25 times
//                     larger, pre-compressed hydrostatically under gravity: every step costs the same.
//   ice2d, ice3d      A square (cube) of Cam Clay ice, side 1 m, centred in the domain, no gravity, pulled
//                     apart in homogeneous uniaxial extension at 100 /s along x (the lateral axes contract by
//                     the elastic ratio, as in scenes/ice_bar_2d.json). Its strength is the residual one
//                     (p0 = 1e-4 kappa: uniaxial tensile strength 45 kPa, yield strain 4.5e-5). One step
//                     strains it by 100 /s x dt = 6.6e-5 at dx = 2 mm (dt = 0.4 dx / c, c = 1.21 km/s; the
//                     finest grid of the sizes, ice2d at 1M), more on coarser grids, so it yields in
//                     the first step and, loaded on in the same direction, in every step after: every
//                     particle goes through the whole return mapping (SVD, projection onto the yield surface,
//                     hardening update) every step. The counter yielding_fraction checks it (1 when all yield).
//   calving2d         A glacier front at rest: an ice slab 0.5 m long and 1 m thick against the left wall,
//                     next to a 1.5 m basin of water 0.5 m deep, both in their hydrostatic state under
//                     gravity (40 % ice, 60 % water particles). The ice is as strong as the sliding-block
//                     glacier's (tensile strength 1 MPa, far above its weight's stress), so it stays elastic:
//                     every ice particle runs the return mapping's SVD and yield check, none projects.
//
// Water is the water2d material of docs/water.md (rho 1000, K 1 MPa, gamma 7, mu 1e-3 Pa s); ice has
// rho 917, E 1 GPa, nu 0.3, M 1.85. Particles per cell: 4 in 2D, 8 in 3D.
#pragma once

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/scene_loader.h"

namespace cdmpm::bench {

using nlohmann::json;

inline int particles_per_cell(int dim) { return dim == 2 ? 4 : 8; }

// Cells per metre, a multiple of `multiple` (2: half metres are whole cells), giving about `particles`
// particles in bodies of total volume `volume` [m^dim].
inline int cells_per_metre(int dim, long particles, double volume, int multiple = 1) {
  const double c = std::pow(double(particles) / particles_per_cell(dim) / volume, 1.0 / dim);
  return std::max(4, multiple * static_cast<int>(std::lround(c / multiple)));
}

inline json box(const std::vector<double>& lo, const std::vector<double>& hi) {
  return {{"type", "box"}, {"min", lo}, {"max", hi}};
}

inline json body(const char* material, int dim, const json& shape) {
  return {{"material", material}, {"particles_per_cell", particles_per_cell(dim)}, {"shape", shape}};
}

inline json water_material() {
  return {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1.0e6}, {"gamma", 7}, {"viscosity", 1.0e-3}};
}

inline json ice_material(double tensile_strength, double beta, double xi) {
  return {{"type", "ice"},   {"density", 917}, {"youngs_modulus", 1.0e9}, {"poissons_ratio", 0.3},
          {"M", 1.85},       {"beta", beta},   {"xi", xi},                {"tensile_strength", tensile_strength}};
}

// A scene of `bodies` in the domain [0, size] of spacing dx, slip walls on every face, gravity along -vertical
// if `gravity`, no frames.
inline Scene bench_scene(const std::string& name, int dim, double dx, const std::vector<double>& size, bool gravity,
                         const json& materials, const json& bodies) {
  std::vector<double> g(dim, 0.0);
  if (gravity) g[dim - 1] = -9.81;
  const json j = {{"name", name},
                  {"dim", dim},
                  {"domain", {{"size", size}, {"dx", dx}}},
                  {"time", {{"end", 1.0}, {"frame_interval", 0.1}}},
                  {"gravity", g},
                  {"materials", materials},
                  {"bodies", bodies},
                  {"boundaries", {{{"type", "walls"}, {"condition", "slip"}}}},
                  {"output", {{"frames", false}}}};
  return scene_from_json(j, "<" + name + ">");
}

inline Scene water_block(int dim, long particles) {
  const int cells = cells_per_metre(dim, particles, 1.0);
  const double dx = 1.0 / cells;
  const std::vector<double> size(dim, std::ceil(1.25 * cells) * dx);
  return bench_scene(dim == 2 ? "water2d" : "water3d", dim, dx, size, true, {{"water", water_material()}},
                     json::array({body("water", dim, box(std::vector<double>(dim, 0.0), std::vector<double>(dim, 1.0)))}));
}

inline Scene ice_block(int dim, long particles) {
  const int cells = cells_per_metre(dim, particles, 1.0);
  const double dx = 1.0 / cells, pad = std::ceil(0.125 * cells) * dx;
  const std::vector<double> size(dim, 1.0 + 2 * pad);
  // Uniaxial stress in extension: lateral rate -nu r in 3D, -nu / (1 - nu) r in 2D (plane strain).
  const double rate = 100, nu = 0.3, lateral = -(dim == 2 ? nu / (1 - nu) : nu) * rate;
  json gradient = json::array();
  for (int r = 0; r < dim; ++r) {
    std::vector<double> row(dim, 0.0);
    row[r] = r == 0 ? rate : lateral;
    gradient.push_back(row);
  }
  json ice = body("ice", dim, box(std::vector<double>(dim, pad), std::vector<double>(dim, 1.0 + pad)));
  ice["velocity_gradient"] = gradient;
  // A tensile strength below the residual one: p0 starts at the floor 1e-4 kappa.
  return bench_scene(dim == 2 ? "ice2d" : "ice3d", dim, dx, size, false, {{"ice", ice_material(1.0e3, 0.3, 3)}},
                     json::array({ice}));
}

inline Scene calving_2d(long particles) {
  const int cells = cells_per_metre(2, particles, 0.5 * 1.0 + 1.5 * 0.5, 2);
  const double dx = 1.0 / cells;
  return bench_scene("calving2d", 2, dx, {2.0, std::ceil(1.25 * cells) * dx}, true,
                     {{"ice", ice_material(1.0e6, 0.1, 5)}, {"water", water_material()}},
                     json::array({body("ice", 2, box({0, 0}, {0.5, 1.0})), body("water", 2, box({0.5, 0}, {2.0, 0.5}))}));
}

}  // namespace cdmpm::bench
