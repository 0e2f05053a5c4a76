// terrain_surface.cpp - the bed as a VTK XML PolyData surface (terrain_surface.h).
#include "io/terrain_surface.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace cdmpm {

void write_terrain_surface(const std::string& path, const std::vector<std::array<double, 3>>& points, int nx, int ny,
                           const std::vector<double>& bed) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream os(tmp);
    os.precision(12);
    const bool quads = ny > 1;
    const long cells = quads ? long(nx - 1) * (ny - 1) : 1;
    os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n<PolyData>\n"
       << "<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << (quads ? 0 : 1)
       << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << (quads ? cells : 0) << "\">\n"
       << "<PointData Scalars=\"bed\"><DataArray type=\"Float64\" Name=\"bed\" format=\"ascii\">\n";
    for (double b : bed) os << b << '\n';
    os << "</DataArray></PointData>\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : points) os << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    os << "</DataArray></Points>\n" << (quads ? "<Polys>" : "<Lines>")
       << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    if (quads) {
      for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
          const long a = long(j) * nx + i;
          os << a << ' ' << a + 1 << ' ' << a + 1 + nx << ' ' << a + nx << '\n';
        }
    } else {
      for (int i = 0; i < nx; ++i) os << i << '\n';
    }
    os << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (long c = 1; c <= cells; ++c) os << (quads ? 4 * c : nx) << '\n';
    os << "</DataArray>" << (quads ? "</Polys>" : "</Lines>") << "\n</Piece>\n</PolyData>\n</VTKFile>\n";
    if (!os) throw std::runtime_error(tmp + ": cannot write");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace cdmpm
