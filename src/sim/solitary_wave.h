// solitary_wave.h - the initial state of a solitary wave in a fluid body (body key "solitary_wave"): the
// Boussinesq solitary wave over still water of depth h (Boussinesq 1872; Synolakis 1987, eq. 2):
//   free surface   eta(x) = H sech^2(k (x - x0)),   k = sqrt(3 H / (4 h^3)),
//   speed          c = sqrt(g (h + H)),
//   velocity       u(x) = s c eta / (h + eta) along x (depth-uniform; s = +1 or -1, the direction), and
//                  w(x, z) = -(z - z_bed) du/dx, the vertical velocity that makes the depth-uniform u satisfy
//                  continuity on a flat bed z_bed = still_level - h.
// The body fills its shape only below still_level + eta(x) and is pre-compressed hydrostatically from that
// surface. x is the first axis (in 3D the wave's crest runs along y).
#pragma once

#include <cmath>

#include "scene/scene_reader.h"

namespace cdmpm {

struct SolitaryWave {
  double height = 0;       // H [m]
  double depth = 0;        // h [m], the still-water depth the wave travels in
  double crest = 0;        // x0 [m], the crest's position at t = 0
  double still_level = 0;  // height of the still water surface [m]
  double direction = 1;    // +1: towards +x, -1: towards -x

  // "solitary_wave": {"height", "depth", "crest", "still_level" (default: depth), "direction" (default 1)}.
  // H/h <= 0.78, the highest solitary wave (McCowan 1894); the crest inside the domain.
  static SolitaryWave parse(const SceneReader& r, const Node& n) {
    r.object(n, {"height", "depth", "crest", "still_level", "direction"});
    SolitaryWave s;
    s.depth = r.number(r.required(n, "depth"), gt(0));
    s.height = r.number(r.required(n, "height"), {0, 0.78 * s.depth, true, false},
                        " (0 < H <= 0.78 depth, the highest solitary wave)");
    s.crest = r.number(r.required(n, "crest"), {0, r.domain().at(0)}, " (inside the domain along x)");
    s.still_level = r.number(n, "still_level", gt(0), s.depth);
    if (n.has("direction")) s.direction = r.integer(n["direction"], {-1, 1});
    if (s.direction == 0) r.expected(n["direction"], "1 or -1");
    return s;
  }
  double k() const { return std::sqrt(3 * height / (4 * depth * depth * depth)); }
  double celerity(double g) const { return std::sqrt(g * (depth + height)); }
  double eta(double x) const {
    const double s = 1 / std::cosh(k() * (x - crest));
    return height * s * s;
  }
  double surface(double x) const { return still_level + eta(x); }
  // Horizontal and vertical velocity at (x, z) for gravity g.
  double u(double x, double g) const {
    const double e = eta(x);
    return direction * celerity(g) * e / (depth + e);
  }
  double w(double x, double z, double g) const {
    const double e = eta(x);
    const double deta_dx = -2 * k() * e * std::tanh(k() * (x - crest));
    const double du_dx = direction * celerity(g) * depth / ((depth + e) * (depth + e)) * deta_dx;
    return -(z - (still_level - depth)) * du_dx;
  }
};

}  // namespace cdmpm
