// scene_loader.cpp - JSON scene file -> validated Scene (see scene_loader.h and docs/scenes.md).
//
// The file is parsed (rejecting duplicate keys), --set overrides are applied to the json, and the result is
// walked once by a Loader that checks every key against the allowed set of its object, the type and range
// of every value and the cross references (material names, shapes and probes inside the domain), filling
// defaults as it goes. The top-level sections are read here; each material model, shape, boundary and probe
// reads its own keys through its registry (material/material.h, shape/shape.h, boundary/boundary.h,
// probe/probe.h), so a type that is not registered cannot get past the loader. Every check goes through
// scene/scene_reader.h, so all messages share the form "<file>: <json.path>: expected <what>, got <value>".
#include "scene/scene_loader.h"

#include "boundary/boundary.h"
#include "probe/probe.h"
#include "scene/json_limits.h"
#include "scene/parameters.h"
#include "terrain/terrain_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <variant>

namespace cdmpm {
namespace {

using json = nlohmann::json;

class Loader {
 public:
  Loader(const std::string& file, const json& j) : r_(file, dim_of(file, j)), dim_(r_.dim()) {}

  Scene load(const json& j) {
    Node root{j, ""};
    // "parameters" is not listed: substitute_parameters has resolved and removed it before loading.
    r_.object(root, {"name", "dim", "domain", "time", "gravity", "materials", "bodies", "boundaries", "sinks",
                     "probes", "output", "georeference", "hazard"});
    s_.dim = dim_;
    s_.name = root.has("name") ? r_.string(root["name"]) : std::filesystem::path(r_.file()).stem().string();
    if (s_.name.empty()) r_.expected(root["name"], "a non-empty string");
    domain(r_.required(root, "domain"));
    // Without frames, the frame interval only paces the checkpoints and the default probe interval: it may exceed
    // time.end (one at the end). output.frames itself is checked by output() below.
    const auto out = j.find("output");
    const bool frames = !(out != j.end() && out->is_object() && out->contains("frames") && (*out)["frames"].is_boolean() &&
                          !(*out)["frames"].get<bool>());
    time(r_.required(root, "time"), frames);
    // At most 1000 m/s^2 on any axis (100 g): larger values are input mistakes, not planets.
    s_.gravity = root.has("gravity") ? r_.numbers(root["gravity"], dim_, {-1e3, 1e3}) : std::vector<double>(dim_, 0.0);
    if (!root.has("gravity")) s_.gravity.back() = -9.81;
    materials(r_.required(root, "materials"));
    Node bodies = r_.required(root, "bodies");
    for (size_t i = 0, n = r_.array(bodies, 1, "a non-empty array of bodies"); i < n; ++i) body(bodies[i]);
    if (root.has("boundaries")) {
      Node bs = root["boundaries"];
      for (size_t i = 0, n = r_.array(bs, 0, "an array of boundaries"); i < n; ++i) boundary(bs[i]);
      for (const auto& [face, path] : faces_needed_)
        if (!contains(faces_closed_, face))
          r_.fail(path, "expected a face that a \"walls\" boundary closes (list it in its faces), got \"" + face + "\"");
    }
    if (root.has("sinks")) {
      Node ss = root["sinks"];
      for (size_t i = 0, n = r_.array(ss, 0, "an array of sinks"); i < n; ++i) sink(ss[i]);
    }
    probes(root);
    if (root.has("output")) output(root["output"]);
    if (root.has("georeference")) georeference(root["georeference"]);
    hazard(root);
    return std::move(s_);
  }

 private:
  // "dim" first: every other section is read for it.
  static int dim_of(const std::string& file, const json& j) {
    SceneReader r(file, 2);
    Node root{j, ""};
    if (!j.is_object()) r.expected(root, "an object");
    return r.integer(r.required(root, "dim"), {2, 3});
  }

  int material_ref(const Node& n) const {
    int index = s_.material_index(r_.string(n));
    if (index < 0) {
      Strings names;
      for (const auto& m : s_.materials) names.push_back(m.name);
      r_.expected(n, "the name of a material (" + join(names, true) + ")");
    }
    return index;
  }

  void domain(const Node& d) {
    r_.object(d, {"size", "dx"});
    s_.domain.size = r_.numbers(r_.required(d, "size"), dim_, gt(0));
    double smallest = *std::min_element(s_.domain.size.begin(), s_.domain.size.end());
    s_.domain.dx = r_.number(r_.required(d, "dx"), {0, smallest / 4, true, false}, " (at most min(domain.size)/4)");
    r_.set_domain(s_.domain.size);
  }

  void time(const Node& t, bool frames) {
    r_.object(t, {"end", "frame_interval", "cfl", "wave_cfl", "max_dt", "settle", "settle_damping", "multi_rate"});
    TimeSpec& ts = s_.time;
    ts.end = r_.number(r_.required(t, "end"), gt(0));
    ts.frame_interval = frames ? r_.number(r_.required(t, "frame_interval"), {0, ts.end, true, false}, " (at most time.end)")
                               : r_.number(r_.required(t, "frame_interval"), gt(0));
    ts.cfl = r_.number(t, "cfl", {0, 1, true, false}, 0.4);
    ts.wave_cfl = r_.number(t, "wave_cfl", {0, 1, true, false}, 0.4);
    ts.max_dt = r_.number(t, "max_dt", ge(0), 0.0);
    ts.settle = r_.number(t, "settle", {0, 1e4, false, false}, 0.0);
    if (t.has("settle_damping")) {
      if (ts.settle == 0) r_.fail(t.child("settle_damping"), "needs \"settle\" > 0");
      ts.settle_damping = r_.number(t["settle_damping"], gt(0));
    } else if (ts.settle > 0) {
      ts.settle_damping = 10 / ts.settle;
    }
    ts.multi_rate = r_.boolean(t, "multi_rate", false);
    if (ts.multi_rate) multi_rate_path_ = t.child("multi_rate");
  }

  void materials(const Node& ms) {
    if (!ms.j.is_object() || ms.j.empty()) r_.expected(ms, "an object with at least one material");
    if (ms.j.size() > 256) r_.expected(ms, "at most 256 materials");
    for (const auto& item : ms.j.items()) {
      Node m = ms[item.key()];
      if (!is_identifier(item.key()))
        r_.fail(m.path, "expected a material name of letters, digits and '_', got \"" + item.key() + "\"");
      s_.materials.push_back(parse_material(r_, m, item.key()));
      // Hydrofracture's water pressure rho_w g (z_w - z) needs the scene's gravity, down the last (vertical) axis.
      if (auto* ice = std::get_if<Ice>(&s_.materials.back().model); ice && ice->hydrofracture.on) {
        const double g = -s_.gravity.back();
        for (int a = 0; a + 1 < dim_; ++a)
          if (s_.gravity[a] != 0) r_.fail(m.child("hydrofracture"), "needs gravity along the last (vertical) axis only");
        if (!(g > 0)) r_.fail(m.child("hydrofracture"), "needs gravity pointing down the last axis (gravity's last entry < 0)");
        ice->hydrofracture.gravity = static_cast<Real>(g);
      }
    }
    // Ice in a field of its own (sim/field_contact.h) and a rigid body in contact (sim/rigid_contact.h): the rigid
    // contact meets the shared field only, so the body would pass through that ice.
    const auto contact_of = [&](bool rigid) {
      for (const Material& m : s_.materials)
        if (m.contact() && m.traits().rigid == rigid) return m.name;
      return std::string();
    };
    const std::string ice = contact_of(false), rigid = contact_of(true);
    if (!ice.empty() && !rigid.empty())
      r_.fail(ms[ice].child("contact"), "a rigid body in contact (materials." + rigid +
                                            ".contact) meets the shared field only (sim/rigid_contact.h), not the ice's own "
                                            "field; give \"contact\" to the rigid bodies or to the ice, not both");
    if (s_.time.multi_rate && ice.empty())
      r_.fail(multi_rate_path_, "sub-steps the solids' own field, which no material has: give an ice material "
                                "\"contact\": true, or remove \"multi_rate\"");
  }

  void body(const Node& b) {
    r_.object(b, {"material", "particles_per_cell", "shape", "holes", "velocity", "velocity_gradient", "hydrostatic",
                  "lateral_stress_ratio", "surface_level", "rigid", "solitary_wave", "crevasses"});
    BodySpec spec;
    spec.material_index = material_ref(r_.required(b, "material"));
    spec.material = s_.materials[spec.material_index].name;
    const bool is_rigid = s_.materials[spec.material_index].traits().rigid;
    if (is_rigid && s_.time.settle > 0)
      r_.expected(b["material"], "no rigid body in a scene with time.settle (the settling damps the particles' "
                                 "velocities, not a rigid body's motion)");
    if (is_rigid)
      for (const auto& other : s_.bodies)
        if (other.material_index == spec.material_index)
          r_.expected(b["material"], "a rigid material not used by another body (each rigid body needs its own rigid "
                                     "material, which names it in probes)");
    if (b.has("rigid")) {
      if (!is_rigid) r_.fail(b.child("rigid"), "only a body of a rigid material (\"type\": \"rigid\") takes this key");
      rigid_options(b["rigid"], spec);
    }
    Node ppc = r_.required(b, "particles_per_cell");
    spec.particles_per_cell = r_.integer(ppc, ge(1));
    int per_axis = static_cast<int>(std::lround(std::pow(spec.particles_per_cell, 1.0 / dim_)));
    if (std::lround(std::pow(per_axis, dim_)) != spec.particles_per_cell)
      r_.expected(ppc, dim_ == 2 ? "an integer n^2 (1, 4, 9, 16, ...)" : "an integer n^3 (1, 8, 27, 64, ...)");
    spec.shape = parse_shape(r_, r_.required(b, "shape"));
    if (b.has("holes")) {
      Node h = b["holes"];
      for (size_t i = 0, n = r_.array(h, 0, "an array of shapes"); i < n; ++i) spec.holes.push_back(parse_shape(r_, h[i]));
    }
    spec.velocity = b.has("velocity") ? r_.numbers(b["velocity"], dim_) : std::vector<double>(dim_, 0.0);
    if (b.has("velocity_gradient")) velocity_gradient(b["velocity_gradient"], spec);
    spec.hydrostatic = r_.boolean(b, "hydrostatic", true);
    if (b.has("lateral_stress_ratio")) {
      if (!s_.materials[spec.material_index].traits().solid_state || is_rigid)
        r_.fail(b.child("lateral_stress_ratio"), "only a body of a deformable solid material (\"type\": \"ice\") takes this key");
      if (!spec.hydrostatic) r_.fail(b.child("lateral_stress_ratio"), "needs \"hydrostatic\": true (a body seeded unloaded has no lithostatic stress)");
      spec.lateral_stress_ratio = r_.number(b["lateral_stress_ratio"], {0, 1, false, false});
    }
    if (b.has("surface_level")) spec.surface_level = r_.number(b["surface_level"]);
    if (b.has("solitary_wave")) solitary_wave(b, spec);
    if (b.has("crevasses")) crevasses(b["crevasses"], spec);
    s_.bodies.push_back(std::move(spec));
  }

  void velocity_gradient(const Node& g, BodySpec& spec) const {
    const std::string what = "an array of " + std::to_string(dim_) + " rows of " + std::to_string(dim_) + " numbers [1/s]";
    if (r_.array(g, 0, what) != static_cast<size_t>(dim_)) r_.expected(g, what);
    for (int row = 0; row < dim_; ++row) {
      auto values = r_.numbers(g[row], dim_);
      spec.velocity_gradient.insert(spec.velocity_gradient.end(), values.begin(), values.end());
    }
  }

  // A fluid body only; its shape must reach the crest, and it takes no surface_level (the wave sets it).
  void solitary_wave(const Node& b, BodySpec& spec) const {
    Node n = b["solitary_wave"];
    if (!s_.materials[spec.material_index].traits().fluid)
      r_.fail(n.path, "only a body of a fluid material (\"type\": \"water\") takes this key");
    if (b.has("surface_level")) r_.fail(b.child("surface_level"), "not allowed together with \"solitary_wave\"");
    spec.solitary = SolitaryWave::parse(r_, n);
    const double crest_top = spec.solitary->still_level + spec.solitary->height;
    if (spec.shape.upper(dim_ - 1) < crest_top)
      r_.expected(n, "a wave whose crest (still_level + height = " + format_number(crest_top) +
                     " m) lies within the body's shape (top " + format_number(spec.shape.upper(dim_ - 1)) + " m)");
  }

  // A body of a breakable solid (ice) only (shape/crevasse_field.h).
  void crevasses(const Node& n, BodySpec& spec) const {
    const auto traits = s_.materials[spec.material_index].traits();
    if (!traits.solid_state || traits.rigid)
      r_.fail(n.path, "only a body of an ice material (\"type\": \"ice\") takes this key");
    spec.crevasses = CrevasseField::parse(r_, n, spec.shape);
    if (n.has("water_material")) {  // checked also when dry: it names a fluid (shape/crevasse_field.h)
      const Node w = n["water_material"];
      const int k = material_ref(w);
      const auto t = s_.materials[k].traits();
      if (!t.fluid || t.rigid) r_.expected(w, "the name of a fluid material (\"type\": \"water\")");
      spec.crevasses->water_material_index = k;
    }
  }

  // "rigid": {"tilt": degrees, "hinge": [x, y(, z)], "hold_until": seconds, "motion": [[t, degrees], ...]}, all
  // optional; a motion needs a hinge and takes the place of tilt and hold_until (its first angle is the tilt).
  // Or "track": {"file": path, "origin": [x, z]}: a recorded source the particles follow (io/source_track.h), alone.
  void rigid_options(const Node& r, BodySpec& spec) const {
    r_.object(r, {"tilt", "hinge", "hold_until", "motion", "track"});
    if (r.has("track")) return track_options(r, spec);
    spec.tilt = r_.number(r, "tilt", {-180, 180, true, true}, 0.0);
    if (r.has("hinge")) {
      spec.hinge = r_.numbers(r["hinge"], dim_);
      r_.inside(r["hinge"], spec.hinge, spec.hinge, "a hinge point");
    }
    spec.hold_until = r_.number(r, "hold_until", ge(0), 0.0);
    if (!r.has("motion")) return;
    const Node m = r["motion"];
    if (spec.hinge.empty()) r_.expected(m, "no motion on a body without a hinge (the motion is a tilt about it)");
    if (r.has("tilt") || r.has("hold_until"))
      r_.expected(m, "a motion without \"tilt\" and \"hold_until\" (its first angle is the tilt)");
    spec.motion = r_.pairs(m, 2);
    for (size_t i = 0; i < spec.motion.size(); ++i) {
      const auto& [t, degrees] = spec.motion[i];
      if (i == 0 && t != 0) r_.expected(m[0], "a first time of 0 s");
      if (i > 0 && !(t > spec.motion[i - 1][0])) r_.expected(m[i], "times increasing from one pair to the next");
      if (!(degrees > -180 && degrees < 180)) r_.expected(m[i], "an angle in (-180, 180) degrees");
    }
    spec.tilt = spec.motion[0][1];
  }

  // "track": {"file": path relative to the scene, "origin": [x, z] (the scene point, along the flow and up, of the
  // track's (0, 0); default zeros)}: the body's particles follow the recorded displacements (io/source_track.h).
  void track_options(const Node& r, BodySpec& spec) const {
    for (const char* key : {"tilt", "hinge", "hold_until", "motion"})
      if (r.has(key)) r_.fail(r.child(key), "not allowed together with \"track\" (the track gives the whole motion)");
    const Node t = r["track"];
    r_.object(t, {"file", "origin"});
    if (s_.materials[spec.material_index].contact())
      r_.fail(r.child("track"), "a body in the shared field: its material (materials." + spec.material +
                                    ") must not have \"contact\" (a replayed source pushes the water through the grid)");
    auto track = std::make_shared<SourceTrack>();
    try {
      *track = read_source_track(terrain_path(r_.file(), r_.string(r_.required(t, "file"))));
    } catch (const SceneError& e) {
      throw SceneError(r_.file() + ": " + t.child("file") + ": " + e.what());
    }
    if (t.has("origin")) {
      const std::vector<double> o = r_.numbers(t["origin"], 2);
      track->origin = {o[0], o[1]};
    }
    spec.track = std::move(track);
  }

  // Checked by building it once (each boundary type reads its own keys); the faces it closes or needs closed
  // (an absorbing layer lies in front of a face that walls close) are checked once all are read.
  void boundary(const Node& n) {
    if (dim_ == 2) boundary_faces(make_boundary<2>(r_, n, BoundaryContext<2>{context_size<2>(), static_cast<Real>(s_.domain.dx)}), n);
    else boundary_faces(make_boundary<3>(r_, n, BoundaryContext<3>{context_size<3>(), static_cast<Real>(s_.domain.dx)}), n);
    s_.boundaries.push_back({n.j.at("type").get<std::string>(), n.j, n.path});
  }
  template <class B>
  void boundary_faces(const B& b, const Node& n) {
    for (const std::string& f : b->closed_faces()) faces_closed_.push_back(f);
    if (const std::string f = b->needs_closed_face(); !f.empty()) faces_needed_.push_back({f, n.child("face")});
  }
  template <int dim>
  Vec<dim> context_size() const {
    Vec<dim> v;
    for (int a = 0; a < dim; ++a) v[a] = static_cast<Real>(s_.domain.size[a]);
    return v;
  }

  void sink(const Node& n) {
    if (!n.j.is_object()) r_.expected(n, "an object");
    r_.object(n, {"min", "max", "material"});
    SinkSpec spec;
    r_.min_max(n, spec.min, spec.max);
    r_.inside(n, spec.min, spec.max, "a sink");
    if (n.has("material")) spec.material_index = material_ref(n["material"]), spec.material = r_.string(n["material"]);
    if (spec.material_index >= 0 && s_.materials[spec.material_index].traits().rigid)
      r_.expected(n["material"], "a material that is not rigid (a sink would remove part of a rigid body)");
    s_.sinks.push_back(std::move(spec));
  }

  void probes(const Node& root) {
    s_.output.probe_interval = s_.time.frame_interval / 10;
    if (!root.has("probes")) return;
    Node p = root["probes"];
    r_.object(p, {"interval", "list"});
    s_.output.probe_interval = r_.number(p, "interval", gt(0), s_.output.probe_interval);
    if (!p.has("list")) return;
    Node list = p["list"];
    for (size_t i = 0, count = r_.array(list, 0, "an array of probes"); i < count; ++i) probe(list[i]);
  }

  // Checked by building it once (each probe type reads its own keys).
  void probe(const Node& n) {
    const std::string name = dim_ == 2 ? make_probe<2>(r_, n, s_)->name() : make_probe<3>(r_, n, s_)->name();
    s_.probes.push_back({name, n.j.at("type").get<std::string>(), n.j, n.path});
  }

  void output(const Node& o) {
    r_.object(o, {"frames", "compress", "positions", "checkpoint_every", "icebergs", "snapshots"});
    if (o.has("snapshots")) snapshots(o["snapshots"]);
    s_.output.frames = r_.boolean(o, "frames", true);
    s_.output.compress = r_.boolean(o, "compress", true);
    s_.output.float32_positions = o.has("positions") && r_.string(o["positions"], {"float64", "float32"}) == "float32";
    s_.output.checkpoint_every = o.has("checkpoint_every") ? r_.integer(o["checkpoint_every"], ge(0)) : 0;
    if (!o.has("icebergs")) return;
    Node ib = o["icebergs"];
    r_.object(ib, {"flow_axis", "damage_threshold", "min_cells", "stop_after_first"});
    if (ib.has("flow_axis")) s_.output.flow_axis = r_.integer(ib["flow_axis"], {0, double(dim_ - 1)});
    s_.output.damage_threshold = r_.number(ib, "damage_threshold", {0, 1, true, true}, 0.5);
    if (ib.has("min_cells")) s_.output.min_iceberg_cells = r_.integer(ib["min_cells"], ge(1));
    s_.output.stop_after_first = r_.number(ib, "stop_after_first", ge(0), -1.0);
  }

  // "output.snapshots": {"times": [s, ...] (probe sample times, increasing, at most 10^4; those after time.end are
  // not reached), "start": [m] (dim - 1),
  // "spacing": m > 0, "count": [n] (dim - 1, each in [1, 10^5]), "still_level": m}: the points inside the domain,
  // at most 10^8 values per quantity over all times.
  void snapshots(const Node& n) {
    r_.object(n, {"times", "start", "spacing", "count", "still_level"});
    if (std::none_of(s_.materials.begin(), s_.materials.end(), [](const Material& m) { return m.traits().fluid; }))
      r_.fail(n.path, "expected a scene with a fluid material (snapshots measure the water)");
    SnapshotSpec spec;
    Node times = r_.required(n, "times");
    const double interval = s_.output.probe_interval, end = s_.time.end;
    const size_t ntimes = r_.array(times, 1, "a non-empty array of times [s]");
    if (ntimes > 10000) r_.expected(times, "at most 10000 times");
    for (size_t i = 0; i < ntimes; ++i) {
      const double t = r_.number(times[i], ge(0));
      const double k = std::round(t / interval);
      if (std::abs(t - k * interval) > 1e-9 * interval && std::abs(t - end) > 1e-9 * interval)
        r_.expected(times[i], "a probe sample time (a multiple of the probe interval " + format_number(interval) +
                                  " s, or time.end): snapshots are taken at probe samples, so they change no time step");
      if (!spec.times.empty() && !(t > spec.times.back())) r_.expected(times[i], "a time after the previous one");
      spec.times.push_back(t);
    }
    spec.start = r_.numbers(r_.required(n, "start"), dim_ - 1);
    spec.spacing = r_.number(r_.required(n, "spacing"), gt(0));
    Node count = r_.required(n, "count");
    const std::vector<double> c = r_.numbers(count, dim_ - 1, {1, 1e5});
    double points = 1;
    std::vector<double> last(dim_ - 1);
    for (int a = 0; a < dim_ - 1; ++a) {
      if (c[a] != std::floor(c[a])) r_.expected(count, "whole numbers of points in [1, 100000]");
      spec.count.push_back(static_cast<int>(c[a]));
      points *= c[a];
      last[a] = spec.start[a] + (c[a] - 1) * spec.spacing;
    }
    r_.inside(n["start"], spec.start, last, "a grid of points (start + (count - 1) spacing)");
    if (points * double(spec.times.size()) > 1e8)
      r_.expected(count, "at most 10^8 values per quantity (points x times), got " + format_number(points) + " points x " +
                             std::to_string(spec.times.size()) + " times");
    if (n.has("still_level")) spec.still_level = r_.number(n["still_level"], {0, s_.domain.size.back()}, " (inside the domain's height)");
    s_.output.snapshots = std::move(spec);
  }

  // "georeference": {"easting": m, "northing": m, "azimuth": degrees in [0, 360) (2D only), "crs": EPSG code or WKT
  // (geo/crs.h), "time_origin": "YYYY-MM-DDThh:mm:ss[Z]" (UTC)}.
  void georeference(const Node& g) {
    const Strings common = {"easting", "northing", "crs", "time_origin"};
    Strings keys = common;
    if (dim_ == 2) keys.push_back("azimuth");
    r_.object(g, keys);
    GeoreferenceSpec& geo = s_.georeference;
    geo.given = true;
    geo.easting = r_.number(r_.required(g, "easting"));
    geo.northing = r_.number(r_.required(g, "northing"));
    if (dim_ == 2) geo.azimuth = r_.number(g, "azimuth", {0, 360, false, true}, 90.0);
    if (g.has("crs")) {
      const std::string text = r_.string(g["crs"]);
      try {
        geo.crs = resolve_crs(text);
      } catch (const std::invalid_argument& e) {
        r_.fail(g.child("crs"), std::string(e.what()) + ", got \"" + (text.size() > 60 ? text.substr(0, 60) + "..." : text) + "\"");
      }
    }
    if (g.has("time_origin")) geo.time_origin = time_origin(g["time_origin"]);
  }

  // A date and time "YYYY-MM-DDThh:mm:ss" (a trailing Z, or a space for the T, accepted), in UDUNITS form.
  std::string time_origin(const Node& n) const {
    std::string t = r_.string(n);
    if (t.size() == 20 && t.back() == 'Z') t.pop_back();
    const std::string form = "dddd-dd-ddTdd:dd:dd";
    bool ok = t.size() == form.size();
    for (size_t i = 0; ok && i < t.size(); ++i)
      ok = form[i] == 'd' ? std::isdigit(static_cast<unsigned char>(t[i])) != 0 : form[i] == 'T' ? t[i] == 'T' || t[i] == ' ' : t[i] == form[i];
    if (ok) {
      const int month = std::stoi(t.substr(5, 2)), day = std::stoi(t.substr(8, 2)), hour = std::stoi(t.substr(11, 2));
      const int minute = std::stoi(t.substr(14, 2)), second = std::stoi(t.substr(17, 2));
      ok = month >= 1 && month <= 12 && day >= 1 && day <= 31 && hour < 24 && minute < 60 && second < 60;
    }
    if (!ok) r_.expected(n, "a date and time \"YYYY-MM-DDThh:mm:ssZ\" (UTC)");
    t[10] = ' ';
    return t;
  }

  // "hazard": {"enabled": bool, "arrival_threshold": m > 0 (default: per column, hazard/hazard_map.h), "interval":
  // s in [0, time.end] (0: every step), "still_level": m (default: measured per column at t = 0)}.
  void hazard(const Node& root) {
    HazardSpec& h = s_.hazard;
    if (!root.has("hazard")) return;
    Node n = root["hazard"];
    r_.object(n, {"enabled", "arrival_threshold", "interval", "still_level"});
    h.enabled = r_.boolean(n, "enabled", true);
    if (n.has("arrival_threshold")) h.arrival_threshold = r_.number(n["arrival_threshold"], gt(0));
    h.interval = r_.number(n, "interval", {0, s_.time.end}, 0.0);
    if (n.has("still_level"))
      h.still_level = r_.number(n["still_level"], {0, s_.domain.size.back()}, " (inside the domain's height)");
  }

  SceneReader r_;
  int dim_;
  Scene s_;
  std::string multi_rate_path_;                              // time.multi_rate, when set
  Strings faces_closed_;                                     // by the boundaries read so far
  std::vector<std::pair<std::string, std::string>> faces_needed_;  // face, path of the key that names it
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
  std::vector<std::string> parts;
  std::stringstream key(text.substr(0, eq));
  for (std::string part; std::getline(key, part, '.');) parts.push_back(part);
  if (parts.empty() || text[eq - 1] == '.' || contains(parts, "")) fail("empty component in key path");
  // A parameter that the scene does not define would be used by no expression: a typo, refused like an unknown key.
  if (parts[0] == "parameters" && parts.size() >= 2 && j.is_object() &&
      !(j.contains("parameters") && j["parameters"].is_object() && j["parameters"].contains(parts[1]))) {
    Strings known;
    if (j.contains("parameters") && j["parameters"].is_object())
      for (const auto& item : j["parameters"].items()) known.push_back(item.key());
    fail("the scene has no parameter '" + parts[1] + "'" +
         (known.empty() ? " (it defines none)" : " (its parameters: " + join(known, false) + ")"));
  }
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
  Scene scene = Loader(path, resolved).load(resolved);
  check_scene_name(scene.name, path);
  scene.parameters = std::move(parameters);
  scene.path = path;
  scene.json = std::move(j);
  scene.resolved = std::move(resolved);
  scene.overrides = overrides;
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
