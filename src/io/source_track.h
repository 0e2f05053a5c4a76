// source_track.h - a recorded calving source, replayed: the displacement field of a 2D run's ice over time, imposed
// on the particles of a rigid material (rigid key `track`, docs/scenes.md; sim/rigid_bodies.h), in 2D or extruded
// across the front in 3D. A 3D run can then be driven by the failure that a 2D run computed, however the ice breaks,
// and a 2D and a 3D run share one source (scenes/eqip_sermia_replay_2d.json, scenes/eqip_sermia_replay_3d.json).
//
// The field is given on a lattice in the plane of the 2D run (x along the flow, z up): node (i, j) at
// (x0 + i h, z0 + j h), i < nx, j < nz, in the track's own coordinates, which the scene shifts by an origin. For each
// node: the fraction of its cell (h x h about it) that the ice filled at t = 0, and at each recorded time t_k the
// displacement u_k = (u_x, u_z) of the ice that started there (tools/source_track.py averages the displacements of
// the 2D run's particles in the cell, and extends them to empty cells from the nearest filled one). A particle that
// starts at X follows
//   x(t) = X + u(X, t),
// u bilinear in X between nodes (clamped at the lattice's edges), linear in t between records, held after the last.
// The body's particles are those of its shape where the nearest node's fill is at least 1/2.
//
// File format (text; '#' comment lines and blank lines are skipped):
//   cdmpm_source_track 1
//   lattice NX NZ X0 Z0 H
//   fill F_0 ... F_{NX NZ - 1}                      (node n = i + NX j, values in [0, 1])
//   times T
//   then T lines:  t  ux_0 uz_0  ux_1 uz_1 ...      (t from 0, increasing; the same node order)
// The reader is strict (io/line_reader.h): a malformed file is refused naming the file and line, and the lattice and
// record counts are bounded before anything is stored.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace cdmpm {

inline constexpr std::size_t kMaxTrackNodes = 10'000'000;    // NX NZ
inline constexpr std::size_t kMaxTrackValues = 50'000'000;   // T NX NZ (each two displacement components)

struct SourceTrack {
  std::string path;
  int nx = 0, nz = 0;
  double x0 = 0, z0 = 0, h = 0;        // lattice, track coordinates [m]
  std::vector<double> fill;            // per node, the ice's share of its cell at t = 0
  std::vector<double> times;           // [s]
  std::vector<std::vector<double>> u;  // per time, (u_x, u_z) per node [m]
  std::array<double, 2> origin{0, 0};  // the scene position (along the flow, up) of the track's (0, 0)

  // Whether the ice filled the point (x, z) (scene coordinates) at t = 0: the nearest node's fill >= 1/2.
  bool occupied(double x, double z) const;
  // The displacement at time t of the ice that started at (x, z) (scene coordinates).
  std::array<double, 2> displacement(double x, double z, double t) const;
  // The largest displacement magnitude in the file [m] (how far the source reaches from where it starts).
  double reach() const;
};

// Reads and checks a source-track file (format above); throws SceneError naming the file and line.
SourceTrack read_source_track(const std::string& path);

}  // namespace cdmpm
