// scene_builders.h - scenes (as JSON) and checks that tests in more than one folder build on: the ice block with
// crevasses, the ice block with hydrofracture, the tank with a section probe, the block that settles, and the tank
// with a floating rigid block with its Archimedes check.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace cdmpm::testing {

// A 2D or 3D block of ice (with a water material beside it) whose body has the `crevasses` given, at dx = 2 m.
inline nlohmann::json crevassed_ice_scene(int dim, const nlohmann::json& crevasses, const std::string& material = "ice") {
  const bool d3 = dim == 3;
  nlohmann::json size = d3 ? nlohmann::json{84.0, 20.0, 24.0} : nlohmann::json{420.0, 120.0};
  nlohmann::json lo = d3 ? nlohmann::json{2.0, 0.0, 0.0} : nlohmann::json{10.0, 0.0};
  nlohmann::json hi = d3 ? nlohmann::json{82.0, 20.0, 20.0} : nlohmann::json{410.0, 100.0};
  nlohmann::json body = {{"material", material}, {"particles_per_cell", d3 ? 1 : 4},
                         {"shape", {{"type", "box"}, {"min", lo}, {"max", hi}}}, {"crevasses", crevasses}};
  return {{"dim", dim},
          {"domain", {{"size", size}, {"dx", 2.0}}},
          {"time", {{"end", 0.1}, {"frame_interval", 0.1}}},
          {"materials",
           {{"ice", {{"type", "ice"}, {"density", 917}, {"youngs_modulus", 1e9}, {"poissons_ratio", 0.3}, {"M", 1.85},
                     {"beta", 0.3}, {"xi", 1}, {"tensile_strength", 1e5}}},
            {"water", {{"type", "water"}, {"density", 1000}, {"bulk_modulus", 1e6}}}}},
          {"bodies", {body}},
          {"boundaries", {{{"type", "walls"}}}}};
}

// A 2D scene with one ice material; `hydrofracture` is added to it unless null.
inline nlohmann::json hydrofracture_ice_scene(const nlohmann::json& hydrofracture, double gravity = -9.81,
                                              bool plastic = true) {
  nlohmann::json ice = {{"type", "ice"}, {"density", 917}, {"youngs_modulus", 1e9}, {"poissons_ratio", 0.3}};
  if (plastic) {
    ice.update({{"M", 1.85}, {"beta", 0.075}, {"xi", 5}, {"tensile_strength", 0.7e6}});
  } else {
    ice["plastic"] = false;
  }
  if (!hydrofracture.is_null()) ice["hydrofracture"] = hydrofracture;
  return {{"dim", 2},
          {"domain", {{"size", {400.0, 300.0}}, {"dx", 10.0}}},
          {"time", {{"end", 0.1}, {"frame_interval", 0.1}}},
          {"gravity", {0.0, gravity}},
          {"materials", {{"ice", ice}}},
          {"bodies", {{{"material", "ice"}, {"particles_per_cell", 1}, {"shape", {{"type", "box"}, {"min", {100, 50}}, {"max", {300, 250}}}}}}},
          {"boundaries", {{{"type", "walls"}}}}};
}

// A tank of still depth h, length L (and width W in 3D), with the water over 0 <= x < w raised by a, the
// section probe "s" given by `section` and grid spacing dx.
inline nlohmann::json section_tank(int dim, double h, double a, double w, double L, double W, double dx,
                                   const nlohmann::json& section) {
  constexpr double g = 9.81, rho = 1000;
  auto vec = [&](double x, double y, double z) {
    return dim == 2 ? nlohmann::json{x, z} : nlohmann::json{x, y, z};
  };
  nlohmann::json probe = section;
  probe["name"] = "s";
  probe["type"] = "section";
  return {{"dim", dim},
          {"domain", {{"size", vec(L, W, 1.5 * h)}, {"dx", dx}}},
          {"time", {{"end", 1.0}, {"frame_interval", 1.0}, {"cfl", 0.4}, {"wave_cfl", 0.4}}},
          {"gravity", vec(0, 0, -g)},
          {"materials", {{"water", {{"type", "water"}, {"density", rho}, {"bulk_modulus", 1e6 * h}, {"gamma", 7}}}}},
          {"bodies", {{{"material", "water"}, {"particles_per_cell", dim == 2 ? 4 : 8},
                       {"shape", {{"type", "box"}, {"min", vec(0, 0, 0)}, {"max", vec(w, W, h + a)}}}},
                      {{"material", "water"}, {"particles_per_cell", dim == 2 ? 4 : 8},
                       {"shape", {{"type", "box"}, {"min", vec(w, 0, 0)}, {"max", vec(L, W, h)}}}}}},
          {"boundaries", {{{"type", "walls"}, {"condition", "slip"}}}},
          {"probes", {{"list", {probe}}}},
          {"output", {{"frames", false}}}};
}

// A 400 m long, 50 m high block of ice on a slip bed, seeded with the lateral stress ratio k and settled for
// `settle` s (none if 0).
inline nlohmann::json settle_block(double k, double settle) {
  constexpr double H = 50, W = 400, rho = 917;
  nlohmann::json time = {{"end", 1.0}, {"frame_interval", 1.0}};
  if (settle > 0) time["settle"] = settle;
  return {{"dim", 2},
          {"domain", {{"size", {W + 200.0, 100.0}}, {"dx", 5.0}}},
          {"time", time},
          {"materials", {{"ice", {{"type", "ice"}, {"density", rho}, {"youngs_modulus", 1e9}, {"poissons_ratio", 0.3},
                                  {"M", 1.85}, {"beta", 0.1}, {"xi", 5}, {"tensile_strength", 1e6}}}}},
          {"bodies", {{{"material", "ice"}, {"particles_per_cell", 4}, {"lateral_stress_ratio", k},
                       {"shape", {{"type", "box"}, {"min", {100.0, 0.0}}, {"max", {100.0 + W, H}}}}}}},
          {"boundaries", {{{"type", "walls"}, {"condition", "slip"}, {"faces", {"y-"}}}}}};
}

// A 2 m wide tank of still water 0.5 m deep (dx = 0.025 m) with a rigid block of density 920, 0.4 m wide, between
// heights y0 and y1.
inline nlohmann::json float_tank(double y0, double y1) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "dim": 2,
    "domain": {"size": [2.0, 1.0], "dx": 0.025},
    "time": {"end": 6, "frame_interval": 0.5},
    "materials": {
      "water": {"type": "water", "density": 1000, "bulk_modulus": 4e5, "viscosity": 1e-3},
      "block": {"type": "rigid", "density": 920, "bulk_modulus": 4e5}
    },
    "bodies": [
      {"material": "block", "particles_per_cell": 4, "shape": {"type": "box", "min": [0.8, 0], "max": [1.2, 0]}},
      {"material": "water", "particles_per_cell": 4, "shape": {"type": "box", "min": [0, 0], "max": [2.0, 0.5]}}
    ],
    "boundaries": [{"type": "walls", "condition": "slip", "faces": ["x-", "x+", "y-"]}]
  })");
  j["bodies"][0]["shape"]["min"][1] = y0;
  j["bodies"][0]["shape"]["max"][1] = y1;
  return j;
}

// The block of float_tank, of height H_b, floats at the draft of Archimedes' principle, (920 / 1000) H_b, within
// 5 %, and is then at rest (its largest speed small against the heave speed sqrt(g d)).
inline void expect_archimedes_draft(double draft, double speed, double H_b) {
  constexpr double g = 9.81;
  const double expected = 920.0 / 1000.0 * H_b;
  std::printf("draft %.5f m (Archimedes %.5f m), largest speed over the last second %.5f m/s\n", draft, expected, speed);
  EXPECT_NEAR(draft, expected, 0.05 * expected);
  EXPECT_LT(speed, 0.05 * std::sqrt(g * expected));
}

}  // namespace cdmpm::testing
