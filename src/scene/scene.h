// scene.h - the validated description of a simulation, as read from a JSON scene file.
//
// Everything here is in SI units. The loader (scene_loader.h) fills and validates these structs; the
// engine never sees raw JSON. Vectors have exactly `dim` entries once loaded. See docs/scenes.md for the
// meaning of each key and its default.
#pragma once

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

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
};

struct MaterialSpec {
  std::string name;
  std::string type;  // "water", "ice" or "rigid" (a rigid body's material: density and the water keys but viscosity)
  double density = 0;  // reference density rho0 [kg/m^3]
  // water: Tait equation of state p = K/gamma ((rho/rho0)^gamma - 1), optional dynamic viscosity
  double bulk_modulus = 0;  // K [Pa]
  double gamma = 7;         // Tait exponent
  double viscosity = 0;     // dynamic viscosity mu [Pa s]
  // ice: split Neo-Hookean elasticity + cohesive Cam-Clay plasticity (docs/ice.md)
  double youngs_modulus = 0;   // E [Pa]
  double poissons_ratio = 0.3; // nu
  double M = 0;                // critical-state slope (from "M" or "friction_angle")
  double beta = 0;             // cohesion: hydrostatic tensile strength / p0
  double xi = 0;               // softening/hardening rate of p0(alpha)
  double p0 = 0;               // initial pre-consolidation pressure [Pa] (from "p0", "alpha0" or "tensile_strength")
  bool hardening = true;       // evolve p0 with the hardening variable alpha
  bool plastic = true;         // false: purely elastic ice
};

struct ShapeSpec {
  std::string type;  // "box", "ball", "polygon" (2D only)
  std::vector<double> min, max;                  // box
  std::vector<double> center;                    // ball
  double radius = 0;                             // ball
  std::vector<std::array<double, 2>> vertices;   // polygon, counter-clockwise or clockwise
};

struct BodySpec {
  std::string material;            // name of a material in `materials`
  int material_index = -1;         // resolved index into Scene::materials
  ShapeSpec shape;
  std::vector<ShapeSpec> holes;    // regions left empty inside the shape (crevasses, notches)
  int particles_per_cell = 0;      // must be n^dim (n particles per axis per cell)
  std::vector<double> velocity;    // initial velocity, default zero
  // initial velocity gradient G (row-major dim x dim, default zero): v(x) = velocity + G (x - c), c the centre
  // of the shape's bounding box; also the particles' initial APIC matrix C = G (a spinning or stretching body)
  std::vector<double> velocity_gradient;
  bool hydrostatic = true;         // start in equilibrium under gravity (water: hydrostatic; ice: lithostatic)
  std::optional<double> surface_level;  // free-surface height for the pre-compression; default shape top
  // Rigid bodies only (material type "rigid", key "rigid" of the body; sim/rigid_bodies.h):
  double tilt = 0;                 // initial rotation of the shape [degrees], turning +x towards up (counter-
                                   // clockwise in 2D; in the x-z plane in 3D), about the hinge if any, else the centre
  std::vector<double> hinge;       // fixed pivot point (dim entries); empty = free body
  double hold_until = 0;           // the body is held at rest until this time [s], then released
};

struct BoundarySpec {
  std::string type;  // "walls", "half_plane", "box", "bathymetry"
  BoundaryCondition condition = BoundaryCondition::Separate;
  double friction = 0;  // Coulomb friction coefficient (separate condition only)
  // walls: which faces; each of "x-","x+","y-","y+","z-","z+"; default all faces
  std::vector<std::string> faces;
  // half_plane: solid where (x - point) . normal < 0; normal points into the fluid
  std::vector<double> point, normal;
  // box: solid inside [min, max] at t = 0, moving with `velocity` (rigid translation; default at rest),
  // reached by a linear ramp from rest over `ramp_time` [s] (0 = from the start)
  std::vector<double> min, max, velocity;
  double ramp_time = 0;
  // bathymetry 2D: polyline of (x, height) points with increasing x; solid below it
  std::vector<std::array<double, 2>> points;
  // bathymetry 3D: height field heights[j][i] at (origin[0] + i*spacing[0], origin[1] + j*spacing[1])
  std::vector<double> origin, spacing;
  std::vector<std::vector<double>> heights;
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

struct ProbeSpec {
  std::string name;
  // "wave_gauge", "front", "pressure", "kinetic_energy", "gravitational_energy", "elastic_energy",
  // "total_energy", "mass", "rigid_position", "rigid_velocity", "rigid_angle" (of the rigid body made of
  // `material`; position and velocity give dim columns <name>_x, <name>_y(, <name>_z))
  std::string type;
  std::vector<double> position;         // pressure: dim entries; wave_gauge: dim-1 horizontal entries
  std::string material;                 // optional material filter (empty = all materials)
  int material_index = -1;              // resolved, -1 = all
  int axis = 0;                         // front: axis along which the extent is measured
  int direction = 1;                    // front: +1 = furthest along +axis, -1 = along -axis
  std::optional<double> still_level;    // wave_gauge: still-water level; default the level at t = 0
};

struct OutputSpec {
  bool frames = true;          // write particles_NNNN.vtu and particles.pvd
  int checkpoint_every = 0;    // checkpoint every N frames (0 = only at the end of the run)
  double probe_interval = 0;   // probes.csv sampling interval [s]; 0 = every frame interval / 10
  // icebergs.csv (written when the scene has ice): connected bodies of intact ice (probe/icebergs.h)
  int flow_axis = 0;              // axis along which an iceberg's length is measured
  double damage_threshold = 0.5;  // a particle / cell with damage at or above this is broken
  int min_iceberg_cells = 4;      // bodies with fewer particles than this many cells' worth are debris
  double stop_after_first = -1;   // end the run this long [s] after the first iceberg separates; < 0 = never
};

struct Scene {
  std::string path;             // file it was read from
  std::string name;             // scene name (default: file stem)
  int dim = 2;
  DomainSpec domain;
  TimeSpec time;
  std::vector<double> gravity;  // default (0, -9.81) or (0, 0, -9.81)
  std::vector<MaterialSpec> materials;
  std::vector<BodySpec> bodies;
  std::vector<BoundarySpec> boundaries;
  std::vector<SinkSpec> sinks;
  std::vector<ProbeSpec> probes;
  OutputSpec output;
  nlohmann::json json;          // the scene as read, with --set overrides applied
  std::map<std::string, double> parameters;  // the values of its "parameters" (after --set), for summary.json

  int material_index(const std::string& material_name) const {
    for (size_t i = 0; i < materials.size(); ++i)
      if (materials[i].name == material_name) return static_cast<int>(i);
    return -1;
  }
};

}  // namespace cdmpm
