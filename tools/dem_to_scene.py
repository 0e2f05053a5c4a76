#!/usr/bin/python3
"""dem_to_scene.py - a glacier and its fjord or lake from DEMs: a bed DEM (bathymetry and the bed under the ice), an
ice-surface DEM, the calving front (a line or the ice's outline as a polygon), a sea or lake level and a region,
made into a 3D scene (and, with --transect, the 2D scene along it) in the CRS of the DEMs (docs/dem_tutorial.md):

    /usr/bin/python3 tools/dem_to_scene.py --bed BED --surface SURFACE --front FRONT --level Z
        --region XMIN YMIN XMAX YMAX --dx DX --out FOLDER [--name NAME] [--transect X0 Y0 X1 Y1] [--min-thickness T]

Writes into FOLDER (created; files of the same names replaced):
  bed.asc, bed.prj          the bed on the scene's grid (cells of DX, one cell beyond the region on every side, so
                            that the cell centres cover it: docs/scenes.md#terrain-from-files), elevations as in BED
  ice_top.asc, ice_top.prj  the ice surface where there is ice (the front's side of it), the bed elsewhere
  NAME_3d.json              the 3D scene: the domain is the region from the floor (DX below the lowest bed) to DX
                            above the highest of surface and level; the bathymetry from bed.asc; the glacier a
                            "heightfield" body between bed.asc and ice_top.asc; the water a box up to the level
                            with the glacier as a hole; georeference at (XMIN, YMIN) with the DEMs' CRS
  bed_profile.csv, NAME_2d.json  with --transect: the bed along the line from (X0, Y0) to (X1, Y1) at DX, the glacier
                            as a polygon between bed and surface, the water up to the level; azimuth of the line
FRONT is any vector file OGR reads (GeoJSON ...) with one LineString (the calving front: the ice is on the side of
it that holds more ice) or one Polygon (the ice's outline, its seaward edge the front), in the DEMs' CRS.

Refused with one line naming the input and exit status 2, nothing written: DEMs in different CRS, in degrees, or
rotated; DEMs that do not overlap; a region outside either DEM, or not a whole number of DX; NODATA inside the
region; a front in another CRS than the DEMs', outside the region, or outside the ice (a line with ice thicker
than --min-thickness, default 1 m, above both the bed and the level at fewer than half of its points; a polygon
with no such ice inside);
a level below the lowest bed. Needs GDAL's Python bindings and numpy (Debian: python3-gdal, python3-numpy).
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.io import write_asc  # noqa: E402

TOOL = "dem_to_scene.py"


def fail(msg):
    print(f"{TOOL}: {msg}", file=sys.stderr)
    sys.exit(2)


def load_modules():
    try:
        import numpy as np
        from osgeo import gdal, ogr, osr
    except ImportError as e:
        fail(f"needs numpy and GDAL's Python bindings (Debian: python3-numpy python3-gdal, /usr/bin/python3): {e}")
    gdal.UseExceptions()
    ogr.UseExceptions()
    return np, gdal, ogr, osr


def open_dem(gdal, path, what):
    try:
        ds = gdal.Open(path)
    except RuntimeError as e:
        fail(f"--{what} {path}: cannot read the DEM: {e}")
    gt = ds.GetGeoTransform()
    if gt[2] != 0 or gt[4] != 0:
        fail(f"--{what} {path}: the DEM is rotated; warp it north-up first (gdalwarp)")
    srs = ds.GetSpatialRef()
    if srs is None:
        fail(f"--{what} {path}: no coordinate reference system (give the DEM a .prj or a CRS: gdal_edit.py -a_srs)")
    if not srs.IsProjected() or abs(srs.GetLinearUnits() - 1.0) > 1e-12:
        fail(f"--{what} {path}: expected a projected CRS in metres, got {srs.GetName()}")
    return ds, srs


def extent(ds):
    gt = ds.GetGeoTransform()
    x0, x1 = gt[0], gt[0] + gt[1] * ds.RasterXSize
    y0, y1 = gt[3] + gt[5] * ds.RasterYSize, gt[3]
    return min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)


def resample(np, gdal, ds, bounds, dx, what, path):
    """The DEM bilinearly on the cells of size dx filling bounds, rows north first. Refused if a DEM cell that the
    interpolation reads is NODATA (GDAL's warp would quietly interpolate around it)."""
    gt = ds.GetGeoTransform()
    band = ds.GetRasterBand(1)
    i0 = max(0, int(math.floor((bounds[0] - gt[0]) / gt[1])) - 1)
    i1 = min(ds.RasterXSize, int(math.ceil((bounds[2] - gt[0]) / gt[1])) + 1)
    j0 = max(0, int(math.floor((bounds[3] - gt[3]) / gt[5])) - 1)
    j1 = min(ds.RasterYSize, int(math.ceil((bounds[1] - gt[3]) / gt[5])) + 1)
    window = band.ReadAsArray(i0, j0, i1 - i0, j1 - j0).astype(float)
    nodata = band.GetNoDataValue()
    missing = ~np.isfinite(window) | ((window == nodata) if nodata is not None else False)
    if missing.any():
        j, i = np.argwhere(missing)[0]
        fail(f"--{what} {path}: NODATA inside the region (the cell at easting {gt[0] + (i0 + i + 0.5) * gt[1]:.1f}, "
             f"northing {gt[3] + (j0 + j + 0.5) * gt[5]:.1f})")
    out = gdal.Warp("", ds, format="MEM", outputBounds=bounds, xRes=dx, yRes=dx, resampleAlg="bilinear")
    return out.GetRasterBand(1).ReadAsArray().astype(float)


def read_front(ogr, osr, path, srs):
    try:
        ds = ogr.Open(path)
        layer = ds.GetLayer(0)
        feature = layer.GetNextFeature()
        geom = feature.GetGeometryRef().Clone()
    except (RuntimeError, AttributeError) as e:
        fail(f"--front {path}: expected a vector file with one line or polygon ({e})")
    fsrs = layer.GetSpatialRef()
    if fsrs is not None and not fsrs.IsSame(srs):
        fail(f"--front {path}: in {fsrs.GetName()}, not in the DEMs' CRS {srs.GetName()}")
    kind = geom.GetGeometryType() % 1000  # drop the 2.5D flag
    if kind not in (ogr.wkbLineString, ogr.wkbPolygon):
        fail(f"--front {path}: expected a LineString or a Polygon, got {geom.GetGeometryName()}")
    return geom, kind == ogr.wkbLineString


def line_points(geom, step):
    """Points along a line every `step` (its vertices included)."""
    pts = [geom.GetPoint_2D(k) for k in range(geom.GetPointCount())]
    out = []
    for (x0, y0), (x1, y1) in zip(pts[:-1], pts[1:]):
        n = max(1, int(math.ceil(math.hypot(x1 - x0, y1 - y0) / step)))
        out += [(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n) for k in range(n)]
    return out + [pts[-1]], pts


def side_of_line(np, pts, X, Y):
    """+1 / -1: the side of the polyline pts of each point (X, Y), by its nearest segment's cross product."""
    best = np.full(X.shape, np.inf)
    side = np.zeros(X.shape)
    for (x0, y0), (x1, y1) in zip(pts[:-1], pts[1:]):
        dxs, dys = x1 - x0, y1 - y0
        t = np.clip(((X - x0) * dxs + (Y - y0) * dys) / (dxs * dxs + dys * dys), 0, 1)
        d = np.hypot(X - (x0 + t * dxs), Y - (y0 + t * dys))
        cross = np.sign(dxs * (Y - y0) - dys * (X - x0))
        closer = d < best
        best = np.where(closer, d, best)
        side = np.where(closer, cross, side)
    return side


MATERIALS = {
    "ice": {"type": "ice", "density": 917, "youngs_modulus": 1.0e9, "poissons_ratio": 0.3, "M": 1.85, "beta": 0.1,
            "xi": 5, "tensile_strength": 1.0e6},
    "water": {"type": "water", "density": 1025, "bulk_modulus": 1.0e8},
}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--bed", required=True)
    p.add_argument("--surface", required=True)
    p.add_argument("--front", required=True)
    p.add_argument("--level", type=float, required=True, help="sea or lake level, in the DEMs' elevations [m]")
    p.add_argument("--region", type=float, nargs=4, required=True, metavar=("XMIN", "YMIN", "XMAX", "YMAX"))
    p.add_argument("--dx", type=float, required=True, help="grid spacing of the scene [m]")
    p.add_argument("--out", required=True)
    p.add_argument("--name", default="glacier")
    p.add_argument("--transect", type=float, nargs=4, metavar=("X0", "Y0", "X1", "Y1"))
    p.add_argument("--min-thickness", type=float, default=1.0)
    args = p.parse_args()
    np, gdal, ogr, osr = load_modules()
    xmin, ymin, xmax, ymax = args.region
    if args.transect:  # checked before anything is written
        x0, y0, x1, y1 = args.transect
        if math.hypot(x1 - x0, y1 - y0) < 4 * args.dx:
            fail(f"--transect {args.transect}: shorter than 4 cells of --dx {args.dx}")
        for x, y in ((x0, y0), (x1, y1)):
            if not (xmin <= x <= xmax and ymin <= y <= ymax):
                fail(f"--transect {args.transect}: ({x}, {y}) outside the region {args.region}")
    dx = args.dx
    if not (dx > 0 and xmax > xmin and ymax > ymin):
        fail(f"--region {args.region} --dx {dx}: expected XMIN < XMAX, YMIN < YMAX and DX > 0")
    nx, ny = (xmax - xmin) / dx, (ymax - ymin) / dx
    if abs(nx - round(nx)) > 1e-6 or abs(ny - round(ny)) > 1e-6 or round(nx) < 4 or round(ny) < 4:
        fail(f"--region {args.region}: expected a whole number (at least 4) of cells of --dx {dx} on each side")
    bed_ds, bed_srs = open_dem(gdal, args.bed, "bed")
    surf_ds, surf_srs = open_dem(gdal, args.surface, "surface")
    if not bed_srs.IsSame(surf_srs):
        fail(f"--surface {args.surface}: in {surf_srs.GetName()}, not in the bed DEM's CRS {bed_srs.GetName()}")
    eb, es = extent(bed_ds), extent(surf_ds)
    if eb[2] <= es[0] or es[2] <= eb[0] or eb[3] <= es[1] or es[3] <= eb[1]:
        fail(f"--surface {args.surface}: its extent {es} does not overlap the bed DEM's {eb}")
    grid = (xmin - dx, ymin - dx, xmax + dx, ymax + dx)  # one cell beyond the region: the centres cover it
    for what, path, e in (("bed", args.bed, eb), ("surface", args.surface, es)):
        if grid[0] < e[0] or grid[1] < e[1] or grid[2] > e[2] or grid[3] > e[3]:
            fail(f"--{what} {path}: the region with one cell of --dx around it, {grid}, is not inside its extent {e}")
    bed = resample(np, gdal, bed_ds, grid, dx, "bed", args.bed)
    surface = np.maximum(resample(np, gdal, surf_ds, grid, dx, "surface", args.surface), bed)
    ncols, nrows = bed.shape[1], bed.shape[0]
    X = grid[0] + (np.arange(ncols) + 0.5) * dx
    Y = grid[3] - (np.arange(nrows) + 0.5) * dx
    X, Y = np.meshgrid(X, Y)
    # Ice: a surface above both the bed and the level (a DEM shows the sea or lake at its level, not as ice).
    thick = surface - np.maximum(bed, args.level) > args.min_thickness

    front, is_line = read_front(ogr, osr, args.front, bed_srs)
    region = ogr.CreateGeometryFromWkt(f"POLYGON(({xmin} {ymin},{xmax} {ymin},{xmax} {ymax},{xmin} {ymax},{xmin} {ymin}))")
    if not front.Intersects(region):
        fail(f"--front {args.front}: outside the region {args.region}")
    if is_line:
        samples, pts = line_points(front, dx / 2)
        inside = [(x, y) for x, y in samples if xmin <= x <= xmax and ymin <= y <= ymax]
        at = [thick[int((grid[3] - y) / dx), int((x - grid[0]) / dx)] for x, y in inside]
        if sum(at) < 0.5 * len(at):
            fail(f"--front {args.front}: the front line lies outside the ice (ice thicker than --min-thickness "
                 f"{args.min_thickness} m at {sum(at)} of its {len(at)} points in the region)")
        side = side_of_line(np, pts, X, Y)
        volume = {s: float(((surface - bed) * (thick & (side == s))).sum()) for s in (-1, 1)}
        glacier = thick & (side == max(volume, key=volume.get))
    else:
        from matplotlib.path import Path
        ring = front.GetGeometryRef(0)
        outline = Path([ring.GetPoint_2D(k) for k in range(ring.GetPointCount())])
        inside = outline.contains_points(np.column_stack([X.ravel(), Y.ravel()])).reshape(X.shape)
        glacier = thick & inside
        if not glacier.any():
            fail(f"--front {args.front}: the polygon holds no ice thicker than --min-thickness {args.min_thickness} m")
    top = np.where(glacier, surface, bed)

    floor = float(bed.min()) - dx
    if args.level <= bed.min():
        fail(f"--level {args.level}: below the lowest bed {bed.min():.2f} m of the region")
    height = max(float(top.max()), args.level) + dx - floor
    height = dx * math.ceil(height / dx)
    crs = bed_srs.ExportToWkt()
    esri = bed_srs.Clone()
    esri.MorphToESRI()
    os.makedirs(args.out, exist_ok=True)
    write_asc(os.path.join(args.out, "bed.asc"), bed, grid[0], grid[1], dx, prj=esri.ExportToWkt())
    write_asc(os.path.join(args.out, "ice_top.asc"), top, grid[0], grid[1], dx, prj=esri.ExportToWkt())
    auth = bed_srs.GetAuthorityCode(None) if bed_srs.GetAuthorityName(None) == "EPSG" else None
    if auth is None:  # an ESRI .prj names no authority: the EPSG system it is, if GDAL finds one for certain
        matches = [m for m, confidence in bed_srs.FindMatches() if confidence == 100]
        if matches and matches[0].GetAuthorityName(None) == "EPSG":
            auth = matches[0].GetAuthorityCode(None)
    georef = {"easting": xmin, "northing": ymin, "crs": f"EPSG:{auth}" if auth else crs}
    origin = [xmin, ymin, floor]
    glacier_shape = {"type": "heightfield", "bottom": "bed.asc", "top": "ice_top.asc", "file_origin": origin}
    size = [xmax - xmin, ymax - ymin, height]
    level = args.level - floor
    scene = {
        "name": f"{args.name}_3d", "dim": 3,
        "parameters": {"dx": dx},
        "domain": {"size": size, "dx": "= dx"},
        "time": {"end": 10, "frame_interval": 1},
        "materials": MATERIALS,
        "bodies": [
            {"material": "ice", "particles_per_cell": 8, "shape": glacier_shape},
            {"material": "water", "particles_per_cell": 8,
             "shape": {"type": "box", "min": [0, 0, 0], "max": [size[0], size[1], level]}, "holes": [glacier_shape]}],
        "boundaries": [{"type": "walls", "condition": "slip"},
                       {"type": "bathymetry", "condition": "slip", "file": "bed.asc", "file_origin": origin}],
        "georeference": georef,
        "output": {"frames": True},
    }
    with open(os.path.join(args.out, f"{args.name}_3d.json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")
    written = ["bed.asc", "bed.prj", "ice_top.asc", "ice_top.prj", f"{args.name}_3d.json"]
    if args.transect:
        written += transect_scene(np, args, bed, top, grid, dx, floor, height, georef, level)
    print(f"{TOOL}: wrote {', '.join(written)} into {args.out} (floor {floor:.2f} m, level {level:.2f} m above it)")


def transect_scene(np, args, bed, top, grid, dx, floor, height, georef, level):
    """The 2D scene along the transect: bed_profile.csv, the glacier as a polygon, NAME_2d.json."""
    x0, y0, x1, y1 = args.transect
    length = math.hypot(x1 - x0, y1 - y0)
    n = int(length // dx)

    def sample(a, s):
        x, y = x0 + (x1 - x0) * s / length, y0 + (y1 - y0) * s / length
        u, v = (x - grid[0]) / dx - 0.5, (grid[3] - y) / dx - 0.5
        i, j = min(int(u), a.shape[1] - 2), min(int(v), a.shape[0] - 2)
        fu, fv = u - i, v - j
        return ((1 - fv) * ((1 - fu) * a[j, i] + fu * a[j, i + 1]) + fv * ((1 - fu) * a[j + 1, i] + fu * a[j + 1, i + 1]))

    s = np.arange(n + 1) * dx
    b = np.array([sample(bed, v) for v in s])
    t = np.array([sample(top, v) for v in s])
    with open(os.path.join(args.out, "bed_profile.csv"), "w") as f:
        f.write("distance,elevation\n")
        for v, e in zip(s, b):
            f.write(f"{v!r},{e:.6g}\n")
    ice = t - np.maximum(b, args.level) > args.min_thickness
    bodies = []
    if ice.any():  # one polygon over the ice's first contiguous stretch along the transect: surface out, bed back
        k0 = int(np.argmax(ice))
        k1 = k0 + int(np.argmin(ice[k0:])) if not ice[k0:].all() else len(ice)
        poly = [[float(s[k]), float(t[k] - floor)] for k in range(k0, k1)]
        poly += [[float(s[k]), float(b[k] - floor)] for k in range(k1 - 1, k0 - 1, -1)]
        bodies.append({"material": "ice", "particles_per_cell": 4, "shape": {"type": "polygon", "vertices": poly}})
    water = {"material": "water", "particles_per_cell": 4, "shape": {"type": "box", "min": [0, 0], "max": [float(s[-1]), level]}}
    if bodies:
        water["holes"] = [bodies[0]["shape"]]
    bodies.append(water)
    azimuth = math.degrees(math.atan2(x1 - x0, y1 - y0)) % 360
    scene = {
        "name": f"{args.name}_2d", "dim": 2,
        "parameters": {"dx": dx},
        "domain": {"size": [float(s[-1]), height], "dx": "= dx"},
        "time": {"end": 10, "frame_interval": 1},
        "materials": MATERIALS,
        "bodies": bodies,
        "boundaries": [{"type": "walls", "condition": "slip"},
                       {"type": "bathymetry", "condition": "slip", "file": "bed_profile.csv", "file_origin": [0, floor]}],
        "georeference": {"easting": x0, "northing": y0, "azimuth": azimuth, "crs": georef["crs"]},
        "output": {"frames": True},
    }
    with open(os.path.join(args.out, f"{args.name}_2d.json"), "w") as f:
        json.dump(scene, f, indent=2)
        f.write("\n")
    return ["bed_profile.csv", f"{args.name}_2d.json"]


if __name__ == "__main__":
    main()
