// wave_bounds.h - what a run's waves can physically do, known from the scene alone, so that the wave and hazard
// products (waves.csv, the summary's celerity, the hazard map's arrival times) never report what no wave did:
//
//   h_max    the deepest still water: the highest top of the fluid bodies above the domain's floor [m];
//   c_max    the fastest free-surface wave: 2 sqrt(g h_max). A long wave runs at sqrt(g h) in linear theory and a
//            crest of amplitude a at about sqrt(g (h + a)) (a solitary wave; its height is bounded by a < 0.8 h);
//            2 sqrt(g h_max) is that speed for a = 3 h_max: a margin over any crest over any path of the domain;
//   sources  where waves start: the horizontal bounding boxes of the bodies that are not fluid (ice, rigid
//            blocks), whose motion from t = 0 on is what raises waves. A wave reaches a point at horizontal
//            distance d from the nearest source no earlier than t_min = d / c_max. A scene with no such body, or
//            with a moving obstacle (a wave maker), has no bounded source: t_min = 0 everywhere (the water itself
//            starts with the wave: a solitary wave, a mound, a dam break);
//   floor    the smallest crest a gauge resolves: dx / 1000. A gauge reads the top particle of its grid column
//            (probe/wave_gauge.cpp); in still water that top moves by about 3e-4 dx (the lake at rest over the
//            Eqip Sermia profile at dx = 10 m: 2-3 mm in 20 s), so a rise below dx / 1000 is not a wave the run
//            resolved;
//   arrival_floor  the least rise that counts as the arrival of a wave on the hazard map: dx / 100, the scale of
//            a free-surface disturbance a grid of spacing dx represents (hazard/hazard_map.h).
#pragma once

#include <vector>

#include "scene/scene.h"

namespace cdmpm {

struct WaveBounds {
  double gravity = 9.81;     // |g| [m/s^2]
  double h_max = 0;          // [m]
  double c_max = 0;          // [m/s]; 0 when the scene has no fluid
  double floor = 0;          // [m], a gauge's least crest
  double arrival_floor = 0;  // [m], the hazard map's least arrival threshold
  bool bounded_source = false;
  // Each source: its horizontal lower and upper corner (dim - 1 coordinates each).
  std::vector<std::pair<std::vector<double>, std::vector<double>>> sources;

  // The earliest time [s] a wave can reach the horizontal position `where` (dim - 1 coordinates): 0 without a
  // bounded source.
  double earliest_arrival(const std::vector<double>& where) const;
  // Whether a celerity c [m/s] is physically possible: 0 < c <= c_max.
  bool possible_celerity(double c) const { return c > 0 && c <= c_max; }
};

WaveBounds wave_bounds(const Scene& scene);

}  // namespace cdmpm
