#!/usr/bin/python3
"""synthetic_dems.py - writes the synthetic DEM pair of docs/dem_tutorial.md: a glacier ending in a fjord, in
EPSG:3413 (NSIDC polar stereographic north, metres), 1600 m x 800 m at 20 m cells, lower-left corner at easting
-200000, northing -2200000:

    /usr/bin/python3 tools/synthetic_dems.py FOLDER

  bed.asc, bed.prj          a U-shaped valley along +x (east): bed = base(x) + 120 ((y - 400) / 400)^2 m, base -80 m
                            in the fjord (x >= 600 m) rising to -20 m at x = 0 under the glacier
  surface.asc, surface.prj  the glacier's surface for x < 600 m, 60 m at the front rising 0.1 m per m inland; elsewhere
                            the sea level 0 over water and the bed on land (as a DEM shows them)
  front.geojson             the calving front, the line x = 600 m across the valley (with its CRS named)
(x, y: metres east and north of the corner). Needs numpy and GDAL's Python bindings (python3-numpy, python3-gdal).
"""
import json
import os
import sys

import numpy as np
from osgeo import osr

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.io import write_asc  # noqa: E402

E0, N0, CELL, NX, NY, FRONT = -200000.0, -2200000.0, 20.0, 80, 40, 600.0


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    x = (np.arange(NX) + 0.5) * CELL
    y = (np.arange(NY) + 0.5) * CELL
    X, Y = np.meshgrid(x, y[::-1])  # rows north first
    base = np.where(X >= FRONT, -80.0, -80.0 + 60.0 * (FRONT - X) / FRONT)
    bed = base + 120.0 * ((Y - 400.0) / 400.0) ** 2
    surface = np.where(X < FRONT, 60.0 + 0.1 * (FRONT - X), np.maximum(bed, 0.0))
    surface = np.maximum(surface, bed)
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(3413)
    srs.MorphToESRI()
    for name, a in (("bed", bed), ("surface", surface)):
        write_asc(os.path.join(out, name + ".asc"), a, E0, N0, CELL, fmt=".3f", prj=srs.ExportToWkt())
    front = {"type": "FeatureCollection",
             "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::3413"}},
             "features": [{"type": "Feature", "properties": {"name": "calving front"},
                           "geometry": {"type": "LineString", "coordinates": [[E0 + FRONT, N0], [E0 + FRONT, N0 + NY * CELL]]}}]}
    with open(os.path.join(out, "front.geojson"), "w") as f:
        json.dump(front, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
