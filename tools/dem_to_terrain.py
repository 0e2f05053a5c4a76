#!/usr/bin/python3
"""dem_to_terrain.py - turns a DEM (GeoTIFF, netCDF, any raster GDAL reads) into a terrain file for the
"bathymetry" boundary's "file" key (docs/scenes.md#terrain-from-files, src/terrain/terrain_file.h):

  grid      an ESRI ASCII grid (.asc) with square cells, north-up, optionally cropped and resampled, with the DEM's
            CRS in a .prj beside it
  transect  a CSV profile (distance, elevation) sampled bilinearly along a straight line

    /usr/bin/python3 tools/dem_to_terrain.py grid DEM OUT.asc [--bounds XMIN YMIN XMAX YMAX] [--cellsize S]
    /usr/bin/python3 tools/dem_to_terrain.py transect DEM OUT.csv --start X Y --end X Y --spacing S

Coordinates are those of the DEM, which must be in a projected (metric) coordinate system; --variable picks
the variable of a netCDF file. Needs GDAL's Python bindings (Debian: python3-gdal); the simulator does not.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.io import write_asc  # noqa: E402


def import_gdal():
    try:
        from osgeo import gdal
    except ImportError:
        sys.exit("dem_to_terrain.py: GDAL's Python bindings are missing: install the Debian package python3-gdal "
                 "(apt-get install python3-gdal) and run this with /usr/bin/python3")
    gdal.UseExceptions()
    return gdal


def open_dem(gdal, path, variable):
    name = f'NETCDF:"{path}":{variable}' if variable else path
    try:
        ds = gdal.Open(name)
    except RuntimeError as e:
        sys.exit(f"dem_to_terrain.py: {path}: cannot read the DEM: {e}")
    gt = ds.GetGeoTransform()
    if gt[2] != 0 or gt[4] != 0:
        sys.exit(f"dem_to_terrain.py: {path}: the DEM is rotated; warp it north-up first (gdalwarp)")
    srs = ds.GetSpatialRef()
    if srs is not None and srs.IsGeographic():
        sys.exit(f"dem_to_terrain.py: {path}: coordinates in degrees; reproject to metres first "
                 "(gdalwarp -t_srs EPSG:<a UTM zone>)")
    return ds


def heights_and_nodata(ds, band):
    """The band as a float array (rows as stored) and a mask of its missing values."""
    import numpy as np
    b = ds.GetRasterBand(band)
    a = b.ReadAsArray().astype(float)
    nodata = b.GetNoDataValue()
    missing = ~np.isfinite(a)
    if nodata is not None:
        missing |= a == nodata
    return a, missing


def write_grid(gdal, ds, out, band, bounds, cellsize):
    gt = ds.GetGeoTransform()
    size = cellsize or max(abs(gt[1]), abs(gt[5]))
    opts = dict(xRes=size, yRes=size, resampleAlg="bilinear", format="MEM", dstNodata=-9999)
    if bounds:
        opts["outputBounds"] = bounds
    warped = gdal.Warp("", gdal.Translate("", ds, format="MEM", bandList=[band]), **opts)
    a, missing = heights_and_nodata(warped, 1)
    wgt = warped.GetGeoTransform()
    nrows, ncols = a.shape
    srs, prj = ds.GetSpatialRef(), None
    if srs is not None:  # the DEM's CRS beside the grid (ESRI WKT, as GDAL and QGIS read a .prj)
        esri = srs.Clone()
        esri.MorphToESRI()
        prj = esri.ExportToWkt()
    a[missing] = float("nan")  # written as NODATA; rows north-up, the first the northernmost
    write_asc(out, a, wgt[0], wgt[3] + nrows * wgt[5], size, fmt=".3f", prj=prj)
    print(f"{out}: {ncols} x {nrows} cells of {size} m, {int(missing.sum())} NODATA")


def sample(a, missing, gt, x, y):
    """Bilinear value at (x, y) from the cell centres, or None outside the DEM or next to a missing value."""
    u = (x - gt[0]) / gt[1] - 0.5
    v = (y - gt[3]) / gt[5] - 0.5
    nrows, ncols = a.shape
    if not (0 <= u <= ncols - 1 and 0 <= v <= nrows - 1):
        return None
    i, j = min(int(u), ncols - 2), min(int(v), nrows - 2)
    fu, fv = u - i, v - j
    if missing[j:j + 2, i:i + 2].any():
        return None
    top = (1 - fu) * a[j, i] + fu * a[j, i + 1]
    bottom = (1 - fu) * a[j + 1, i] + fu * a[j + 1, i + 1]
    return (1 - fv) * top + fv * bottom


def write_transect(ds, dem, out, band, start, end, spacing):
    a, missing = heights_and_nodata(ds, band)
    gt = ds.GetGeoTransform()
    length = math.dist(start, end)
    n = max(1, math.ceil(length / spacing - 1e-9))
    rows = []
    for k in range(n + 1):
        s = min(k * spacing, length)
        t = s / length if length > 0 else 0
        z = sample(a, missing, gt, start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]))
        if z is None:
            sys.exit(f"dem_to_terrain.py: {dem}: no elevation at distance {s:g} m of the transect "
                     "(outside the DEM or next to a NODATA cell)")
        rows.append((s, z))
    with open(out, "w") as f:
        f.write(f"# transect of {dem} (band {band}) from {start} to {end}, every {spacing} m: made by "
                "tools/dem_to_terrain.py\ndistance_m,elevation_m\n")
        f.writelines(f"{s:.3f},{z:.3f}\n" for s, z in rows)
    print(f"{out}: {len(rows)} points over {length:g} m")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="mode", required=True)
    g = sub.add_parser("grid", help="ESRI ASCII grid (.asc)")
    g.add_argument("--bounds", type=float, nargs=4, metavar=("XMIN", "YMIN", "XMAX", "YMAX"))
    g.add_argument("--cellsize", type=float, help="cell size [m] (default: the DEM's larger pixel side)")
    t = sub.add_parser("transect", help="CSV profile along a line")
    t.add_argument("--start", type=float, nargs=2, required=True, metavar=("X", "Y"))
    t.add_argument("--end", type=float, nargs=2, required=True, metavar=("X", "Y"))
    t.add_argument("--spacing", type=float, required=True, help="distance between points [m]")
    for s in (g, t):
        s.add_argument("dem", help="DEM file (GeoTIFF, netCDF, ...)")
        s.add_argument("out", help="output file")
        s.add_argument("--band", type=int, default=1)
        s.add_argument("--variable", help="netCDF variable holding the elevation")
    args = p.parse_args()
    if (args.mode == "grid" and args.cellsize is not None and args.cellsize <= 0) or \
            (args.mode == "transect" and args.spacing <= 0):
        p.error("cellsize and spacing must be > 0")
    gdal = import_gdal()
    ds = open_dem(gdal, args.dem, args.variable)
    if args.mode == "grid":
        write_grid(gdal, ds, args.out, args.band, args.bounds, args.cellsize)
    else:
        write_transect(ds, args.dem, args.out, args.band, args.start, args.end, args.spacing)


if __name__ == "__main__":
    main()
