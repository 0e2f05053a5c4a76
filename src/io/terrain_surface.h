// terrain_surface.h - terrain.vtp: the bed of a run (bathymetry, and the bed under the ice) as a surface that
// ParaView shows under the particle frames, in the frames' coordinates: a VTK XML PolyData file (VTK file formats,
// kitware.com) of nx x ny points (x fastest), joined as quads in 3D (ny > 1) and as a polyline in 2D (ny = 1), with
// the point data "bed" [m], the bed height above the domain's floor. Written as NAME.tmp and renamed.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace cdmpm {

// Throws std::runtime_error if the file cannot be written.
void write_terrain_surface(const std::string& path, const std::vector<std::array<double, 3>>& points, int nx, int ny,
                           const std::vector<double>& bed);

}  // namespace cdmpm
