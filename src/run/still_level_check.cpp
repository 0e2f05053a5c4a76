// still_level_check.cpp - the still-level warnings of a scene (still_level_check.h).
#include "run/still_level_check.h"

#include <cmath>
#include <sstream>

namespace cdmpm {
namespace {

std::string metres(double v) {
  std::ostringstream os;
  os.precision(4);
  os << v << " m";
  return os.str();
}

// The liquid body whose horizontal extent holds `where` (dim - 1 coordinates), if any.
const BodySpec* liquid_under(const Scene& s, const std::vector<double>& where) {
  for (const BodySpec& b : s.bodies) {
    const Material& m = s.materials[b.material_index];
    if (!m.traits().fluid || m.traits().rigid) continue;
    bool in = true;
    for (size_t a = 0; a < where.size() && in; ++a) in = where[a] >= b.shape.lower(a) && where[a] <= b.shape.upper(a);
    if (in) return &b;
  }
  return nullptr;
}

}  // namespace

std::vector<std::string> still_level_warnings(const Scene& s) {
  std::vector<std::string> out;
  const int up = s.dim - 1;
  const double tolerance = s.domain.dx / 20, g = std::abs(s.gravity[up]);
  for (size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    const Material& m = s.materials[b.material_index];
    if (!m.traits().fluid || m.traits().rigid || b.hydrostatic) continue;
    const double c = m.visit([&](const auto& model) {
      return double(s.dim == 2 ? model.template wave_speed<2>(1) : model.template wave_speed<3>(1));
    });
    const double rho0 = m.density(), K = rho0 * c * c, H = b.liquid_level(up) - b.shape.lower(up);
    const double drop = rho0 * g * H * H / (2 * K);
    if (drop > tolerance)
      out.push_back("bodies[" + std::to_string(i) + "]: hydrostatic is false: the water settles under its own weight "
                    "by about " + metres(drop) + " (rho0 g H^2 / 2K), more than dx / 20 = " + metres(tolerance) +
                    "; remove \"hydrostatic\": false to seed it at rest");
  }
  auto check_level = [&](const std::string& what, const std::vector<double>& where, double level) {
    const BodySpec* b = liquid_under(s, where);
    if (!b) return;
    const double seeded = b->liquid_level(up);
    if (std::abs(level - seeded) > tolerance)
      out.push_back(what + ": still_level " + metres(level) + " differs from the level of the water under it, " +
                    metres(seeded) + " (bodies[" + std::to_string(b - s.bodies.data()) + "]), by more than dx / 20 = " +
                    metres(tolerance));
  };
  for (const ProbeSpec& p : s.probes)
    // (A still_level of 0 asks for the water's absolute top: the float scenes' level gauges.)
    if (p.type == "wave_gauge" && p.json.contains("still_level") && p.json["still_level"].get<double>() != 0)
      check_level(p.path, p.json["position"].get<std::vector<double>>(), p.json["still_level"].get<double>());
  for (const BoundarySpec& b : s.boundaries) {
    if (b.type != "absorbing_layer") continue;
    // The layer's face: its inner edge's middle as the place to compare (the layer's still water).
    std::vector<double> where(s.dim - 1);
    for (int a = 0; a < s.dim - 1; ++a) where[a] = s.domain.size[a] / 2;
    const std::string face = b.json["face"].get<std::string>();
    const int axis = face[0] - 'x';
    const double width = b.json["width"].get<double>();
    where[axis] = face[1] == '+' ? s.domain.size[axis] - width / 2 : width / 2;
    check_level(b.path, where, b.json["still_level"].get<double>());
  }
  return out;
}

}  // namespace cdmpm
