// scene_loader.cpp - JSON scene file -> validated Scene (see scene_loader.h and docs/scenes.md).
//
// The file is parsed (rejecting duplicate keys), --set overrides are applied to the json, and the result is
// walked once by a Loader that checks every key against the allowed set of its object, the type and range
// of every value and the cross references (material names, shapes and probes inside the domain), filling
// defaults as it goes. Each check goes through a few generic helpers (number/integer/string/numbers...) so
// all messages share the form "<file>: <json.path>: expected <what>, got <value>".
#include "scene/scene_loader.h"

#include "material/cohesive_cam_clay.h"
#include "material/neo_hookean_split.h"
#include "scene/json_limits.h"
#include "scene/parameters.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>

namespace cdmpm {
namespace {

using json = nlohmann::json;
using Strings = std::vector<std::string>;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string show(const json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

std::string join(const Strings& items, bool quote = false) {
  std::string out;
  for (const auto& it : items) out += (out.empty() ? "" : ", ") + (quote ? '"' + it + '"' : it);
  return out;
}

bool contains(const Strings& items, const std::string& s) {
  return std::find(items.begin(), items.end(), s) != items.end();
}

// Letters, digits and '_' only (usable as a CSV column and as a --set path component).
bool is_identifier(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

// Interval of allowed numbers, open or closed at each end.
struct Range {
  double lo = -kInf, hi = kInf;
  bool lo_open = false, hi_open = false;
  bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi); }
  std::string describe() const {
    if (lo == -kInf && hi == kInf) return "";
    if (hi == kInf) return (lo_open ? " > " : " >= ") + fmt(lo);
    if (lo == -kInf) return (hi_open ? " < " : " <= ") + fmt(hi);
    return std::string(" in ") + (lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + (hi_open ? ")" : "]");
  }
};
Range gt(double lo) { return {lo, kInf, true, false}; }
Range ge(double lo) { return {lo, kInf, false, false}; }

// A json value together with its path in the scene ("bodies[0].shape.min").
struct Node {
  const json& j;
  std::string path;
  std::string child(const std::string& key) const { return path.empty() ? key : path + "." + key; }
  bool has(const std::string& key) const { return j.contains(key); }
  Node operator[](const std::string& key) const { return {j.at(key), child(key)}; }
  Node operator[](size_t i) const { return {j.at(i), path + "[" + std::to_string(i) + "]"}; }
};

std::string box_text(const std::vector<double>& lo, const std::vector<double>& hi) {
  std::string s;
  for (size_t a = 0; a < lo.size(); ++a) s += (a ? " x [" : "[") + fmt(lo[a]) + ", " + fmt(hi[a]) + "]";
  return s;
}

class Loader {
 public:
  explicit Loader(std::string file) : file_(std::move(file)) {}

  Scene load(const json& j) {
    Node root{j, ""};
    // "parameters" is not listed: substitute_parameters has resolved and removed it before loading.
    object(root, {"name", "dim", "domain", "time", "gravity", "materials", "bodies", "boundaries", "sinks",
                  "probes", "output"});
    s_.dim = dim_ = integer(required(root, "dim"), {2, 3});
    s_.name = root.has("name") ? string(root["name"]) : std::filesystem::path(file_).stem().string();
    if (s_.name.empty()) expected(root["name"], "a non-empty string");
    domain(required(root, "domain"));
    time(required(root, "time"));
    s_.gravity = root.has("gravity") ? numbers(root["gravity"], dim_) : std::vector<double>(dim_, 0.0);
    if (!root.has("gravity")) s_.gravity.back() = -9.81;
    materials(required(root, "materials"));
    Node bodies = required(root, "bodies");
    for (size_t i = 0, n = array(bodies, 1, "a non-empty array of bodies"); i < n; ++i) body(bodies[i]);
    if (root.has("boundaries")) {
      Node bs = root["boundaries"];
      for (size_t i = 0, n = array(bs, 0, "an array of boundaries"); i < n; ++i) boundary(bs[i]);
    }
    if (root.has("sinks")) {
      Node ss = root["sinks"];
      for (size_t i = 0, n = array(ss, 0, "an array of sinks"); i < n; ++i) sink(ss[i]);
    }
    probes(root);
    if (root.has("output")) {
      Node o = root["output"];
      object(o, {"frames", "checkpoint_every", "icebergs"});
      s_.output.frames = o.has("frames") ? boolean(o["frames"]) : true;
      s_.output.checkpoint_every = o.has("checkpoint_every") ? integer(o["checkpoint_every"], ge(0)) : 0;
      if (o.has("icebergs")) {
        Node ib = o["icebergs"];
        object(ib, {"flow_axis", "damage_threshold", "min_cells", "stop_after_first"});
        if (ib.has("flow_axis")) s_.output.flow_axis = integer(ib["flow_axis"], {0, double(dim_ - 1)});
        s_.output.damage_threshold = number(ib, "damage_threshold", {0, 1, true, true}, 0.5);
        if (ib.has("min_cells")) s_.output.min_iceberg_cells = integer(ib["min_cells"], ge(1));
        s_.output.stop_after_first = number(ib, "stop_after_first", ge(0), -1.0);
      }
    }
    return std::move(s_);
  }

 private:
  // ---- generic checks -------------------------------------------------------------------------------
  [[noreturn]] void fail(const std::string& path, const std::string& msg) const {
    throw SceneError(file_ + ": " + (path.empty() ? "(root)" : path) + ": " + msg);
  }
  [[noreturn]] void expected(const Node& n, const std::string& what) const {
    fail(n.path, "expected " + what + ", got " + show(n.j));
  }
  // `n` must be an object whose keys are all in `allowed`.
  void object(const Node& n, const Strings& allowed) const {
    if (!n.j.is_object()) expected(n, "an object");
    for (const auto& item : n.j.items())
      if (!contains(allowed, item.key())) fail(n.child(item.key()), "unknown key (allowed: " + join(allowed) + ")");
  }
  Node required(const Node& n, const std::string& key) const {
    if (!n.has(key)) fail(n.child(key), "required key missing");
    return n[key];
  }
  size_t array(const Node& n, size_t min_size, const std::string& what) const {
    if (!n.j.is_array() || n.j.size() < min_size) expected(n, what);
    return n.j.size();
  }
  double number(const Node& n, Range r = {}, const std::string& note = "") const {
    if (!n.j.is_number() || !std::isfinite(n.j.get<double>()) || !r.contains(n.j.get<double>()))
      expected(n, "a number" + r.describe() + note);
    return n.j.get<double>();
  }
  double number(const Node& parent, const std::string& key, Range r, double fallback) const {
    return parent.has(key) ? number(parent[key], r) : fallback;
  }
  int integer(const Node& n, Range r) const {
    if (!n.j.is_number_integer() || !r.contains(n.j.get<double>()) || std::abs(n.j.get<double>()) > INT_MAX)
      expected(n, "an integer" + r.describe());
    return n.j.get<int>();
  }
  bool boolean(const Node& n) const {
    if (!n.j.is_boolean()) expected(n, "true or false");
    return n.j.get<bool>();
  }
  std::string string(const Node& n, const Strings& choices = {}) const {
    if (!n.j.is_string() || (!choices.empty() && !contains(choices, n.j.get<std::string>())))
      expected(n, choices.empty() ? "a string" : "one of " + join(choices, true));
    return n.j.get<std::string>();
  }
  std::vector<double> numbers(const Node& n, size_t count, Range r = {}) const {
    array(n, 0, "an array of " + std::to_string(count) + " numbers" + r.describe());
    if (n.j.size() != count) expected(n, "an array of " + std::to_string(count) + " numbers" + r.describe());
    std::vector<double> v(count);
    for (size_t i = 0; i < count; ++i) v[i] = number(n[i], r);
    return v;
  }
  std::vector<std::array<double, 2>> pairs(const Node& n, size_t min_count) const {
    size_t count = array(n, min_count, "an array of at least " + std::to_string(min_count) + " [x, y] pairs");
    std::vector<std::array<double, 2>> v(count);
    for (size_t i = 0; i < count; ++i) {
      auto p = numbers(n[i], 2);
      v[i] = {p[0], p[1]};
    }
    return v;
  }
  // Reads "min" and "max" of `n` (dim numbers each) and checks min < max on every axis.
  void min_max(const Node& n, std::vector<double>& lo, std::vector<double>& hi) const {
    lo = numbers(required(n, "min"), dim_);
    hi = numbers(required(n, "max"), dim_);
    for (int a = 0; a < dim_; ++a)
      if (!(hi[a] > lo[a])) expected(n["max"], "max > min on every axis (min = " + show(n["min"].j) + ")");
  }
  // Checks that the first x.size() coordinates lie inside the domain (with a relative tolerance).
  void inside(const Node& n, const std::vector<double>& lo, const std::vector<double>& hi,
              const std::string& what) const {
    std::vector<double> zero(lo.size(), 0.0), size(s_.domain.size.begin(), s_.domain.size.begin() + lo.size());
    for (size_t a = 0; a < lo.size(); ++a) {
      double tol = 1e-12 * size[a];
      if (lo[a] < -tol || hi[a] > size[a] + tol)
        fail(n.path, "expected " + what + " inside the domain " + box_text(zero, size) + ", got " +
                         (lo == hi ? show(n.j) : "bounding box " + box_text(lo, hi)));
    }
  }
  int material_ref(const Node& n) const {
    int index = s_.material_index(string(n));
    if (index < 0) {
      Strings names;
      for (const auto& m : s_.materials) names.push_back(m.name);
      expected(n, "the name of a material (" + join(names, true) + ")");
    }
    return index;
  }

  // ---- sections --------------------------------------------------------------------------------------
  void domain(const Node& d) {
    object(d, {"size", "dx"});
    s_.domain.size = numbers(required(d, "size"), dim_, gt(0));
    double smallest = *std::min_element(s_.domain.size.begin(), s_.domain.size.end());
    s_.domain.dx = number(required(d, "dx"), {0, smallest / 4, true, false}, " (at most min(domain.size)/4)");
  }

  void time(const Node& t) {
    object(t, {"end", "frame_interval", "cfl", "wave_cfl", "max_dt"});
    TimeSpec& ts = s_.time;
    ts.end = number(required(t, "end"), gt(0));
    ts.frame_interval = number(required(t, "frame_interval"), {0, ts.end, true, false}, " (at most time.end)");
    ts.cfl = number(t, "cfl", {0, 1, true, false}, 0.4);
    ts.wave_cfl = number(t, "wave_cfl", {0, 1, true, false}, 0.4);
    ts.max_dt = number(t, "max_dt", ge(0), 0.0);
  }

  void materials(const Node& ms) {
    if (!ms.j.is_object() || ms.j.empty()) expected(ms, "an object with at least one material");
    if (ms.j.size() > 256) expected(ms, "at most 256 materials");
    for (const auto& item : ms.j.items()) {
      Node m = ms[item.key()];
      if (!is_identifier(item.key()))
        fail(m.path, "expected a material name of letters, digits and '_', got \"" + item.key() + "\"");
      if (!m.j.is_object()) expected(m, "an object");
      MaterialSpec spec;
      spec.name = item.key();
      spec.type = string(required(m, "type"), {"water", "ice", "rigid"});
      if (spec.type == "rigid") {
        object(m, {"type", "density", "bulk_modulus", "gamma"});
        spec.density = number(required(m, "density"), gt(0));
        spec.bulk_modulus = number(required(m, "bulk_modulus"), gt(0));
        spec.gamma = number(m, "gamma", gt(0), 7.0);
      } else if (spec.type == "water") {
        object(m, {"type", "density", "bulk_modulus", "gamma", "viscosity"});
        spec.density = number(required(m, "density"), gt(0));
        spec.bulk_modulus = number(required(m, "bulk_modulus"), gt(0));
        spec.gamma = number(m, "gamma", gt(0), 7.0);
        spec.viscosity = number(m, "viscosity", ge(0), 0.0);
      } else {
        ice(m, spec);
      }
      s_.materials.push_back(spec);
    }
  }

  // Ice: E, nu, density; M or friction_angle; beta, xi; exactly one of p0, alpha0, tensile_strength.
  void ice(const Node& m, MaterialSpec& spec) {
    object(m, {"type", "density", "youngs_modulus", "poissons_ratio", "M", "friction_angle", "beta", "xi", "p0",
               "alpha0", "tensile_strength", "hardening", "plastic"});
    spec.density = number(required(m, "density"), gt(0));
    spec.youngs_modulus = number(required(m, "youngs_modulus"), gt(0));
    spec.poissons_ratio = number(m, "poissons_ratio", {-1, 0.5, true, true}, 0.3);
    spec.plastic = m.has("plastic") ? boolean(m["plastic"]) : true;
    spec.hardening = m.has("hardening") ? boolean(m["hardening"]) : true;
    const NeoHookeanSplit e = NeoHookeanSplit::from_young_poisson(spec.youngs_modulus, spec.poissons_ratio, dim_);
    if (!spec.plastic) {
      for (const char* key : {"M", "friction_angle", "beta", "xi", "p0", "alpha0", "tensile_strength"})
        if (m.has(key)) fail(m.child(key), "not used when \"plastic\" is false (remove it)");
      return;
    }
    if (m.has("M") == m.has("friction_angle"))
      fail(m.path, "expected exactly one of \"M\" (critical-state slope) or \"friction_angle\" (degrees)");
    if (m.has("M")) {
      spec.M = number(m["M"], gt(0));
    } else {
      // Triaxial-compression Mohr-Coulomb match: M = 6 sin(phi) / (3 - sin(phi)).
      const double phi = number(m["friction_angle"], {0, 90, true, true}) * std::numbers::pi / 180;
      spec.M = 6 * std::sin(phi) / (3 - std::sin(phi));
    }
    spec.beta = number(required(m, "beta"), gt(0));
    spec.xi = number(required(m, "xi"), gt(0));
    const int given = m.has("p0") + m.has("alpha0") + m.has("tensile_strength");
    if (given != 1)
      fail(m.path, "expected exactly one of \"p0\" [Pa], \"alpha0\" or \"tensile_strength\" [Pa] (initial strength)");
    CohesiveCamClay cc;
    cc.M = static_cast<Real>(spec.M), cc.beta = static_cast<Real>(spec.beta), cc.xi = static_cast<Real>(spec.xi);
    const double p0_max = 0.5 * e.kappa;  // the Kirchhoff pressure of the split model never exceeds kappa/2
    const std::string limit = " (the initial p0 must be below kappa/2 = " + fmt(p0_max) + " Pa)";
    if (m.has("p0")) {
      spec.p0 = number(m["p0"], {0, p0_max, true, true}, limit);
    } else if (m.has("alpha0")) {
      spec.p0 = cc.p0_of_alpha(static_cast<Real>(number(m["alpha0"], {-kInf, 0, false, false})), e.kappa);
      if (!(spec.p0 < p0_max)) expected(m["alpha0"], "a value giving p0 < kappa/2 = " + fmt(p0_max) + " Pa");
    } else {
      // The uniaxial strength of the yield surface is proportional to p0.
      const double per_p0 = dim_ == 2 ? cc.uniaxial_strength<2>(1, true) : cc.uniaxial_strength<3>(1, true);
      const double sigma_t = number(m["tensile_strength"], gt(0));
      spec.p0 = sigma_t / per_p0;
      if (!(spec.p0 < p0_max))
        expected(m["tensile_strength"], "a strength below " + fmt(p0_max * per_p0) + " Pa (it needs p0 = " +
                                            fmt(spec.p0) + " Pa, above kappa/2)");
    }
  }

  void body(const Node& b) {
    object(b, {"material", "particles_per_cell", "shape", "holes", "velocity", "velocity_gradient", "hydrostatic",
               "surface_level", "rigid"});
    BodySpec spec;
    spec.material_index = material_ref(required(b, "material"));
    spec.material = s_.materials[spec.material_index].name;
    const bool is_rigid = s_.materials[spec.material_index].type == "rigid";
    if (is_rigid)
      for (const auto& other : s_.bodies)
        if (other.material_index == spec.material_index)
          expected(b["material"], "a rigid material not used by another body (each rigid body needs its own rigid "
                                  "material, which names it in probes)");
    if (b.has("rigid")) {
      if (!is_rigid) fail(b.child("rigid"), "only a body of a rigid material (\"type\": \"rigid\") takes this key");
      rigid_options(b["rigid"], spec);
    }
    Node ppc = required(b, "particles_per_cell");
    spec.particles_per_cell = integer(ppc, ge(1));
    int per_axis = static_cast<int>(std::lround(std::pow(spec.particles_per_cell, 1.0 / dim_)));
    if (std::lround(std::pow(per_axis, dim_)) != spec.particles_per_cell)
      expected(ppc, dim_ == 2 ? "an integer n^2 (1, 4, 9, 16, ...)" : "an integer n^3 (1, 8, 27, 64, ...)");
    spec.shape = shape(required(b, "shape"));
    if (b.has("holes")) {
      Node h = b["holes"];
      for (size_t i = 0, n = array(h, 0, "an array of shapes"); i < n; ++i) spec.holes.push_back(shape(h[i]));
    }
    spec.velocity = b.has("velocity") ? numbers(b["velocity"], dim_) : std::vector<double>(dim_, 0.0);
    if (b.has("velocity_gradient")) {
      Node g = b["velocity_gradient"];
      const std::string what = "an array of " + std::to_string(dim_) + " rows of " + std::to_string(dim_) + " numbers [1/s]";
      if (array(g, 0, what) != static_cast<size_t>(dim_)) expected(g, what);
      for (int r = 0; r < dim_; ++r) {
        auto row = numbers(g[r], dim_);
        spec.velocity_gradient.insert(spec.velocity_gradient.end(), row.begin(), row.end());
      }
    }
    spec.hydrostatic = b.has("hydrostatic") ? boolean(b["hydrostatic"]) : true;
    if (b.has("surface_level")) spec.surface_level = number(b["surface_level"]);
    s_.bodies.push_back(std::move(spec));
  }

  // "rigid": {"tilt": degrees, "hinge": [x, y(, z)], "hold_until": seconds}, all optional.
  void rigid_options(const Node& r, BodySpec& spec) const {
    object(r, {"tilt", "hinge", "hold_until"});
    spec.tilt = number(r, "tilt", {-180, 180, true, true}, 0.0);
    if (r.has("hinge")) {
      spec.hinge = numbers(r["hinge"], dim_);
      inside(r["hinge"], spec.hinge, spec.hinge, "a hinge point");
    }
    spec.hold_until = number(r, "hold_until", ge(0), 0.0);
  }

  ShapeSpec shape(const Node& n) {
    if (!n.j.is_object()) expected(n, "an object");
    ShapeSpec sh;
    sh.type = string(required(n, "type"), dim_ == 2 ? Strings{"box", "ball", "polygon"} : Strings{"box", "ball"});
    std::vector<double> lo, hi;
    if (sh.type == "box") {
      object(n, {"type", "min", "max"});
      min_max(n, sh.min, sh.max);
      lo = sh.min, hi = sh.max;
    } else if (sh.type == "ball") {
      object(n, {"type", "center", "radius"});
      sh.center = numbers(required(n, "center"), dim_);
      sh.radius = number(required(n, "radius"), gt(0));
      for (double c : sh.center) lo.push_back(c - sh.radius), hi.push_back(c + sh.radius);
    } else {
      object(n, {"type", "vertices"});
      sh.vertices = pairs(required(n, "vertices"), 3);
      double area2 = 0;
      lo = {kInf, kInf}, hi = {-kInf, -kInf};
      for (size_t i = 0; i < sh.vertices.size(); ++i) {
        const auto &p = sh.vertices[i], &q = sh.vertices[(i + 1) % sh.vertices.size()];
        area2 += p[0] * q[1] - q[0] * p[1];
        for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
      }
      if (area2 == 0) expected(n["vertices"], "a polygon with nonzero area");
    }
    inside(n, lo, hi, "a shape");
    return sh;
  }

  void boundary(const Node& n) {
    if (!n.j.is_object()) expected(n, "an object");
    BoundarySpec spec;
    spec.type = string(required(n, "type"), {"walls", "half_plane", "box", "bathymetry"});
    Strings keys = {"type", "condition", "friction"};
    Strings extra = spec.type == "walls"        ? Strings{"faces"}
                    : spec.type == "half_plane" ? Strings{"point", "normal"}
                    : spec.type == "box"        ? Strings{"min", "max", "velocity", "ramp_time"}
                    : dim_ == 2                 ? Strings{"points"}
                                                : Strings{"origin", "spacing", "heights"};
    keys.insert(keys.end(), extra.begin(), extra.end());
    object(n, keys);
    std::string condition = n.has("condition") ? string(n["condition"], {"sticky", "slip", "separate"}) : "separate";
    spec.condition = condition == "sticky" ? BoundaryCondition::Sticky
                     : condition == "slip" ? BoundaryCondition::Slip
                                           : BoundaryCondition::Separate;
    spec.friction = number(n, "friction", ge(0), 0.0);
    if (spec.type == "walls") {
      Strings all = {"x-", "x+", "y-", "y+"};
      if (dim_ == 3) all.insert(all.end(), {"z-", "z+"});
      if (!n.has("faces")) spec.faces = all;
      if (n.has("faces")) {
        Node faces = n["faces"];
        for (size_t i = 0, count = array(faces, 1, "a non-empty array of faces"); i < count; ++i) {
          std::string face = string(faces[i], all);
          if (contains(spec.faces, face)) expected(faces[i], "a face not listed before");
          spec.faces.push_back(face);
        }
      }
    } else if (spec.type == "half_plane") {
      spec.point = numbers(required(n, "point"), dim_);
      spec.normal = numbers(required(n, "normal"), dim_);
      double norm = 0;
      for (double c : spec.normal) norm += c * c;
      if (norm == 0) expected(n["normal"], "a nonzero vector");
      for (double& c : spec.normal) c /= std::sqrt(norm);
    } else if (spec.type == "box") {
      min_max(n, spec.min, spec.max);
      spec.velocity = n.has("velocity") ? numbers(n["velocity"], dim_) : std::vector<double>(dim_, 0.0);
      spec.ramp_time = number(n, "ramp_time", ge(0), 0.0);
    } else if (dim_ == 2) {
      Node points = required(n, "points");
      spec.points = pairs(points, 2);
      for (size_t i = 1; i < spec.points.size(); ++i)
        if (!(spec.points[i][0] > spec.points[i - 1][0]))
          expected(points[i], "a point with x > " + fmt(spec.points[i - 1][0]) + " (x strictly increasing)");
    } else {
      spec.origin = numbers(required(n, "origin"), 2);
      spec.spacing = numbers(required(n, "spacing"), 2, gt(0));
      Node heights = required(n, "heights");
      size_t rows = array(heights, 2, "an array of at least 2 rows of heights");
      size_t cols = array(heights[0], 2, "an array of at least 2 heights");
      for (size_t r = 0; r < rows; ++r) spec.heights.push_back(numbers(heights[r], cols));
    }
    s_.boundaries.push_back(std::move(spec));
  }

  void sink(const Node& n) {
    if (!n.j.is_object()) expected(n, "an object");
    object(n, {"min", "max", "material"});
    SinkSpec spec;
    min_max(n, spec.min, spec.max);
    inside(n, spec.min, spec.max, "a sink");
    if (n.has("material")) spec.material_index = material_ref(n["material"]), spec.material = string(n["material"]);
    if (spec.material_index >= 0 && s_.materials[spec.material_index].type == "rigid")
      expected(n["material"], "a material that is not rigid (a sink would remove part of a rigid body)");
    s_.sinks.push_back(std::move(spec));
  }

  void probes(const Node& root) {
    s_.output.probe_interval = s_.time.frame_interval / 10;
    if (!root.has("probes")) return;
    Node p = root["probes"];
    object(p, {"interval", "list"});
    s_.output.probe_interval = number(p, "interval", gt(0), s_.output.probe_interval);
    if (!p.has("list")) return;
    Node list = p["list"];
    for (size_t i = 0, count = array(list, 0, "an array of probes"); i < count; ++i) probe(list[i]);
  }

  void probe(const Node& n) {
    static const Strings kTypes = {"wave_gauge",     "front",          "pressure",     "kinetic_energy",
                                   "gravitational_energy", "elastic_energy", "total_energy", "mass",
                                   "rigid_position", "rigid_velocity", "rigid_angle"};
    if (!n.j.is_object()) expected(n, "an object");
    ProbeSpec spec;
    spec.type = string(required(n, "type"), kTypes);
    Strings keys = spec.type == "pressure"     ? Strings{"position"}
                   : spec.type == "wave_gauge" ? Strings{"position", "still_level", "material"}
                   : spec.type == "front"      ? Strings{"material", "axis", "direction"}
                                               : Strings{"material"};
    keys.insert(keys.end(), {"name", "type"});
    object(n, keys);
    Node name = required(n, "name");
    spec.name = string(name);
    if (!is_identifier(spec.name) || spec.name == "time")
      expected(name, "a non-empty name of letters, digits and '_', other than \"time\"");
    for (const auto& other : s_.probes)
      if (other.name == spec.name) expected(name, "a unique probe name");
    if (n.has("material")) spec.material_index = material_ref(n["material"]), spec.material = string(n["material"]);
    if (spec.type.starts_with("rigid_")) {
      Node mat = required(n, "material");
      if (s_.materials[spec.material_index].type != "rigid") expected(mat, "the name of a rigid material");
      bool used = false;
      for (const auto& b : s_.bodies) used = used || b.material_index == spec.material_index;
      if (!used) expected(mat, "a rigid material that a body is made of");
    }
    if (spec.type == "pressure" || spec.type == "wave_gauge") {
      Node pos = required(n, "position");
      spec.position = numbers(pos, spec.type == "pressure" ? dim_ : dim_ - 1);
      inside(pos, spec.position, spec.position, "a position");
    }
    if (n.has("still_level")) spec.still_level = number(n["still_level"]);
    if (n.has("axis")) spec.axis = integer(n["axis"], {0, double(dim_ - 1)});
    if (n.has("direction")) {
      Node dir = n["direction"];
      if (!dir.j.is_number_integer() || std::abs(dir.j.get<double>()) != 1) expected(dir, "an integer 1 or -1");
      spec.direction = dir.j.get<int>();
    }
    s_.probes.push_back(std::move(spec));
  }

  std::string file_;
  Scene s_;
  int dim_ = 2;
};

// json::parse with duplicate object keys rejected (nlohmann would silently keep the last one).
json parse_rejecting_duplicates(std::istream& in, const std::string& file) {
  struct Frame {
    bool is_array = false;
    size_t index = 0;
    std::string key;
    std::set<std::string> keys;
  };
  std::vector<Frame> stack;
  auto next_value = [&] {
    if (!stack.empty() && stack.back().is_array) ++stack.back().index;
  };
  auto callback = [&](int, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    if (event == E::object_start || event == E::array_start) stack.emplace_back().is_array = event == E::array_start;
    if (event == E::object_end || event == E::array_end) stack.pop_back(), next_value();
    if (event == E::value) next_value();
    if (event == E::key) {
      stack.back().key = parsed.get<std::string>();
      if (!stack.back().keys.insert(stack.back().key).second) {
        std::string path;
        for (const auto& f : stack)
          path += f.is_array ? "[" + std::to_string(f.index) + "]" : (path.empty() ? "" : ".") + f.key;
        throw SceneError(file + ": " + path + ": duplicate key (each key may appear only once in an object)");
      }
    }
    return true;
  };
  return json::parse(in, callback);
}

}  // namespace

void apply_override(json& j, const std::string& text, const std::string& file) {
  auto fail = [&](const std::string& why) { throw SceneError(file + ": --set '" + text + "': " + why); };
  size_t eq = text.find('=');
  if (eq == std::string::npos) fail("expected key.path=value");
  Strings parts;
  std::stringstream key(text.substr(0, eq));
  for (std::string part; std::getline(key, part, '.');) parts.push_back(part);
  if (parts.empty() || text[eq - 1] == '.' || contains(parts, "")) fail("empty component in key path");
  json* cur = &j;
  std::string walked;
  for (size_t k = 0; k < parts.size(); ++k) {
    const std::string& c = parts[k];
    std::string here = walked.empty() ? c : walked + "." + c;
    if (cur->is_array()) {
      if (c.size() > 9 || !std::all_of(c.begin(), c.end(), [](unsigned char ch) { return std::isdigit(ch); }))
        fail((walked.empty() ? "(root)" : walked) + " is an array, expected a numeric index, got '" + c + "'");
      size_t index = std::stoul(c);
      if (index >= cur->size()) fail(here + " does not exist (array has " + std::to_string(cur->size()) + " elements)");
      cur = &(*cur)[index];
    } else if (cur->is_object()) {
      if (k + 1 < parts.size() && !cur->contains(c)) fail(here + " does not exist");
      cur = &(*cur)[c];
    } else {
      fail((walked.empty() ? "(root)" : walked) + " is not an object or array, cannot index it with '" + c + "'");
    }
    walked = here;
  }
  std::string value = text.substr(eq + 1);
  check_json_depth(value, file + ": --set '" + text.substr(0, eq) + "'");
  try {
    *cur = json::parse(value);
  } catch (const json::exception&) {
    *cur = value;
  }
}

Scene scene_from_json(json j, const std::string& path, const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) apply_override(j, o, path);
  nlohmann::json resolved = j;
  std::map<std::string, double> parameters;
  substitute_parameters(resolved, path, &parameters);
  Scene scene = Loader(path).load(resolved);
  check_scene_name(scene.name, path);
  scene.parameters = std::move(parameters);
  scene.path = path;
  scene.json = std::move(j);
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_scene_text(path);
  check_json_depth(text, path);
  std::istringstream in(text);
  json j;
  try {
    j = parse_rejecting_duplicates(in, path);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number such as 1e999
    throw SceneError(path + ": parse error: " + e.what());
  }
  return scene_from_json(std::move(j), path, overrides);
}

}  // namespace cdmpm
