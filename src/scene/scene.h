// scene.h - the validated description of a simulation, as read from a JSON scene file.
//
// Everything here is in SI units. The loader (scene_loader.h) fills and validates these structs; the
// engine never sees raw JSON, except the objects of boundaries and probes, which it builds through their
// registries from the objects the loader checked. Vectors have exactly `dim` entries once loaded. See docs/scenes.md for the
// meaning of each key and its default.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geo/crs.h"
#include "io/source_track.h"
#include "material/material.h"
#include "shape/crevasse_field.h"
#include "shape/shape.h"
#include "sim/solitary_wave.h"

namespace cdmpm {

enum class BoundaryCondition { Sticky, Slip, Separate };

struct DomainSpec {
  std::vector<double> size;  // domain is [0, size[a]] along each axis a
  double dx = 0;             // grid spacing
};

struct TimeSpec {
  double end = 0;             // simulated end time [s]
  double frame_interval = 0;  // output frame interval [s]
  double cfl = 0.4;           // dt <= cfl * dx / max particle speed
  double wave_cfl = 0.4;      // dt <= wave_cfl * dx / largest wave speed of any material
  double max_dt = 0;          // optional upper bound on dt [s]; 0 = none
  double settle = 0;          // settling before t = 0 [s]: solids elastic, velocities damped (sim/simulation.h)
  double settle_damping = 0;  // damping rate of the settling [1/s]; default 10 / settle
  bool multi_rate = false;    // the solids' own field (ice with "contact") sub-steps at its own stable time step
                              // within each step of the others (sim/field_contact.h, subcycle)
};

struct BodySpec {
  std::string material;            // name of a material in `materials`
  int material_index = -1;         // resolved index into Scene::materials
  Shape shape;                     // shape/shape.h
  std::vector<Shape> holes;        // regions left empty inside the shape (crevasses, notches)
  int particles_per_cell = 0;      // must be n^dim (n particles per axis per cell)
  std::vector<double> velocity;    // initial velocity, default zero
  // initial velocity gradient G (row-major dim x dim, default zero): v(x) = velocity + G (x - c), c the centre
  // of the shape's bounding box; also the particles' initial APIC matrix C = G (a spinning or stretching body)
  std::vector<double> velocity_gradient;
  bool hydrostatic = true;         // start in equilibrium under gravity (water: hydrostatic; ice: lithostatic)
  double lateral_stress_ratio = 0; // solids: horizontal / vertical stress of the lithostatic state (0: laterally
                                   // free slab, 1: cryostatic, no deviatoric stress; sim/seeding.h)
  std::optional<double> surface_level;  // free-surface height for the pre-compression; default shape top
  // Rigid bodies only (material type "rigid", key "rigid" of the body; sim/rigid_bodies.h):
  double tilt = 0;                 // initial rotation of the shape [degrees], turning +x towards up (counter-
                                   // clockwise in 2D; in the x-z plane in 3D), about the hinge if any, else the centre
  std::vector<double> hinge;       // fixed pivot point (dim entries); empty = free body
  double hold_until = 0;           // the body is held at rest until this time [s], then released
  std::vector<std::array<double, 2>> motion;  // hinged only: a prescribed tilt, (time [s], degrees) pairs, piecewise
                                              // linear, held at the last angle after the last time; empty = free
  std::shared_ptr<const SourceTrack> track;  // a recorded source that the particles follow instead (rigid key `track`)
  // Fluid bodies only: start a solitary wave (sim/solitary_wave.h; key "solitary_wave" of the body).
  std::optional<SolitaryWave> solitary;
  // Ice bodies only: surface crevasses cut from the top, from seeded simplex noise (shape/crevasse_field.h;
  // key "crevasses" of the body).
  std::optional<CrevasseField> crevasses;

  // A liquid body's still level [m], on which its top is seeded (sim/seeding.cpp): its solitary wave's still
  // level, its surface_level, or its shape's top along `up`, the vertical axis.
  double liquid_level(int up) const { return solitary ? solitary->still_level : surface_level.value_or(shape.upper(up)); }
};

// A boundary (boundary/boundary.h) of a registered type: its scene object as checked by the loader, from which
// the simulation builds it (each boundary type reads its own keys, boundary/*.cpp).
struct BoundarySpec {
  std::string type;       // "walls", "half_plane", "box", "bathymetry" (boundary/registry.cpp)
  nlohmann::json json;    // the boundary's object in the resolved scene
  std::string path;       // its path in the scene ("boundaries[1]"), for messages
};

// A sink (an outlet): particles of `material` (all materials if empty) whose position is inside the box
// [min, max] at the end of a step are removed from the simulation. A sink along the top of a far part of a
// basin holds the water there at the sink's lower edge, like a spillway of unlimited capacity, so that a
// body pushed into a closed 2D basin does not raise its level.
struct SinkSpec {
  std::vector<double> min, max;
  std::string material;
  int material_index = -1;  // resolved, -1 = all
};

// A probe (probe/probe.h) of a registered type: its scene object as checked by the loader, from which the run
// builds it (each probe type reads its own keys, probe/*.cpp).
struct ProbeSpec {
  std::string name;
  std::string type;       // probe/registry.cpp
  nlohmann::json json;    // the probe's object in the resolved scene
  std::string path;       // its path in the scene ("probes.list[0]")
};

// Gridded snapshots of the depth-averaged water (key "output.snapshots"; run/snapshots.h): eta, d, hu (hv) on the
// points start + i spacing (i < count, per horizontal axis) at the given times, each a probe sample time.
struct SnapshotSpec {
  std::vector<double> times;            // [s], increasing
  std::vector<double> start;            // dim - 1 coordinates [m]
  double spacing = 0;                   // [m]
  std::vector<int> count;               // dim - 1 point counts
  std::optional<double> still_level;    // [m]; default: measured per point at t = 0
};

struct OutputSpec {
  bool frames = true;          // write particles_NNNN.vtu and particles.pvd
  bool compress = true;        // zlib-compressed frame data (io/vtu_writer.h); false: raw
  bool float32_positions = false;  // frame positions in single precision (large 3D runs)
  int checkpoint_every = 0;    // checkpoint every N frames (0 = only at the end of the run)
  double probe_interval = 0;   // probes.csv sampling interval [s]; 0 = every frame interval / 10
  // icebergs.csv (written when the scene has ice): connected bodies of intact ice (probe/icebergs.h)
  int flow_axis = 0;              // axis along which an iceberg's length is measured
  double damage_threshold = 0.5;  // a particle / cell with damage at or above this is broken
  int min_iceberg_cells = 4;      // bodies with fewer particles than this many cells' worth are debris
  double stop_after_first = -1;   // end the run this long [s] after the first iceberg separates; < 0 = never
  std::optional<SnapshotSpec> snapshots;
};

// Where the domain lies on a map (key "georeference"): the easting and northing [m] of the domain's origin and,
// in 2D, the azimuth of the +x axis (the transect), degrees clockwise from north; the map's coordinate reference
// system (geo/crs.h), if given; the date and time of t = 0 (the time origin of the netCDF outputs). Recorded in
// summary.json and used as the lower-left corner of the 3D hazard rasters (hazard/hazard_report.h).
struct GeoreferenceSpec {
  bool given = false;
  double easting = 0, northing = 0;
  double azimuth = 90;  // 2D only; default +x east
  std::optional<Crs> crs;
  std::string time_origin = "1970-01-01 00:00:00";  // UDUNITS form "YYYY-MM-DD hh:mm:ss", UTC

  // The map coordinates (easting, northing) [m] of a point of `horizontal` domain coordinates (dim - 1 of them):
  // 2D along the transect's azimuth, 3D +x east and +y north.
  std::array<double, 2> map_point(const std::vector<double>& horizontal) const {
    if (horizontal.size() == 1) {
      const double az = azimuth * 3.14159265358979323846 / 180;
      return {easting + horizontal[0] * std::sin(az), northing + horizontal[0] * std::cos(az)};
    }
    return {easting + horizontal[0], northing + horizontal[1]};
  }
};

// Hazard products of scenes with a fluid (key "hazard"; hazard/hazard_map.h): sampled every step (interval 0)
// or at most once per interval; a column counts as reached when its elevation exceeds arrival_threshold (by
// default each column's own noise floor, hazard/hazard_map.h). The still level of a column wet at t = 0 is its
// water top then, or still_level if given (a scene that starts with a wave in the water).
struct HazardSpec {
  bool enabled = true;
  std::optional<double> arrival_threshold;  // [m]; default: per column, the larger of 3 x its noise and dx / 100
  double interval = 0;           // [s]; 0 = every step
  std::optional<double> still_level;  // [m]; default: each wet column's water top at t = 0
};

struct Scene {
  std::string path;             // file it was read from
  std::string name;             // scene name (default: file stem)
  int dim = 2;
  DomainSpec domain;
  TimeSpec time;
  std::vector<double> gravity;  // default (0, -9.81) or (0, 0, -9.81)
  std::vector<Material> materials;  // material/material.h
  std::vector<BodySpec> bodies;
  std::vector<BoundarySpec> boundaries;
  std::vector<SinkSpec> sinks;
  std::vector<ProbeSpec> probes;
  OutputSpec output;
  GeoreferenceSpec georeference;
  HazardSpec hazard;
  nlohmann::json json;          // the scene as read, with --set overrides applied
  nlohmann::json resolved;      // the same with its parameters and expressions evaluated (what was loaded)
  std::vector<std::string> overrides;  // the --set values applied, in order
  std::map<std::string, double> parameters;  // the values of its "parameters" (after --set), for summary.json

  int material_index(const std::string& material_name) const {
    for (size_t i = 0; i < materials.size(); ++i)
      if (materials[i].name == material_name) return static_cast<int>(i);
    return -1;
  }
};

}  // namespace cdmpm
