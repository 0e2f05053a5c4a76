#!/usr/bin/python3
"""test_dem_to_scene.py - scenes from DEMs (tools/dem_to_scene.py, the heightfield shape, docs/dem_tutorial.md), on
the shipped synthetic pair (scenes/data/synthetic_glacier, tools/synthetic_dems.py):

    /usr/bin/python3 tests/tools/test_dem_to_scene.py --cdmpm PATH [--work DIR] [--keep] [-k NAME]

  - the tutorial's 3D and 2D scenes pass `cdmpm check`; a few steps of the 3D scene seed the glacier's volume between
    its bed and surface (the ice particles' count times their volume, within the surface's resolution), and write
    rasters that GDAL places at the region's corner in EPSG:3413 and a snapshot that xarray opens;
  - bad DEM inputs are refused with one line naming the input, exit status 2, nothing written: DEMs in different
    CRS, DEMs that do not overlap, NODATA inside the region, a front line outside the ice;
  - the heightfield shape's loader checks: a top nowhere above the bottom, a missing file, an unknown key, a footprint
    of two vertices (exit 2, the key named); a footprint that splits the glacier seeds each part of its ice.
Each test prints PASS or FAIL with the reason; the last line is "N passed, M failed".
"""
import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "tools"))
import harness  # noqa: E402
from harness import check, test  # noqa: E402
from cdmpm_tools.frames import read_field_data, read_vtu  # noqa: E402
from cdmpm_tools.io import read_asc  # noqa: E402

DATA = os.path.join(ROOT, "scenes", "data", "synthetic_glacier")
TOOL = os.path.join(ROOT, "tools", "dem_to_scene.py")
DX = 40.0
REGION = [-199960, -2199960, -198440, -2199240]
ARGS = None


def tool(out, bed=None, surface=None, front=None, extra=(), expect=0):
    cmd = ["/usr/bin/python3", TOOL, "--bed", bed or os.path.join(DATA, "bed.asc"),
           "--surface", surface or os.path.join(DATA, "surface.asc"), "--front", front or os.path.join(DATA, "front.geojson"),
           "--level", "0", "--region", *map(str, REGION), "--dx", str(DX), "--out", out, *extra]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == expect, f"dem_to_scene.py exit {r.returncode}, expected {expect}: {r.stderr.strip()}")
    return r


def cdmpm(*args, expect=0):
    r = subprocess.run([ARGS.cdmpm, *args], capture_output=True, text=True)
    check(r.returncode == expect, f"cdmpm {' '.join(args)}: exit {r.returncode}, expected {expect}: {r.stderr[-1500:]}")
    return r


def made():
    out = os.path.join(ARGS.work, "scene")
    if not os.path.isfile(os.path.join(out, "glacier_3d.json")):
        tool(out, extra=["--transect", "-199960", "-2199600", "-198440", "-2199600"])
    return out


@test
def tutorial_scene_seeds_the_glacier_and_its_rasters_are_georeferenced():
    from osgeo import gdal, osr
    import xarray
    gdal.UseExceptions()
    out = made()
    for s in ("glacier_3d.json", "glacier_2d.json"):
        cdmpm("check", os.path.join(out, s))
    run = os.path.join(ARGS.work, "run3d")
    snap = '{"times": [0], "start": [20, 20], "spacing": 40, "count": [38, 18]}'
    cdmpm("run", os.path.join(out, "glacier_3d.json"), "--out", run, "--quiet", "--steps", "3",
          "--set", f"output.snapshots={snap}")
    # The glacier's volume: the thickness top - bottom of the tool's grids, bilinear between their cell centres as the
    # heightfield shape reads them, integrated over the domain on 5 m samples; against the seeded ice particles (8 per
    # cell, each (dx/2)^3). The lattice rounds each column's top and bottom to its particles (half a spacing either
    # way, averaging out over the columns): within a quarter of a particle layer over the glacier's area.
    bed, top = read_asc(os.path.join(out, "bed.asc"))[0][::-1], read_asc(os.path.join(out, "ice_top.asc"))[0][::-1]
    th = top - bed  # rows south first; cell centres at ((i - 0.5) dx, (j - 0.5) dx) in the domain
    size = (REGION[2] - REGION[0], REGION[3] - REGION[1])
    X, Y = np.meshgrid(np.arange(2.5, size[0], 5.0), np.arange(2.5, size[1], 5.0))
    u, w = np.clip(X / DX + 0.5, 0, th.shape[1] - 1), np.clip(Y / DX + 0.5, 0, th.shape[0] - 1)
    i, j = np.minimum(u.astype(int), th.shape[1] - 2), np.minimum(w.astype(int), th.shape[0] - 2)
    fu, fw = u - i, w - j
    t = (1 - fw) * ((1 - fu) * th[j, i] + fu * th[j, i + 1]) + fw * ((1 - fu) * th[j + 1, i] + fu * th[j + 1, i + 1])
    expected, area = float(np.maximum(t, 0).sum()) * 25.0, float((t > 0).sum()) * 25.0
    frame = os.path.join(run, "particles_0000.vtu")
    material = np.asarray(read_vtu(frame)[1]["material"])
    ice = list(read_field_data(frame)["material_names"]).index("ice")
    seeded = float((material == ice).sum()) * (DX / 2) ** 3
    check(abs(seeded - expected) <= area * (DX / 2) / 4,
          f"ice volume seeded {seeded:.5g} m3, between the grids {expected:.5g} m3 (tolerance {area * DX / 8:.3g} m3)")
    epsg3413 = osr.SpatialReference()
    epsg3413.ImportFromEPSG(3413)
    r = gdal.Open(os.path.join(run, "max_elevation.asc"))
    check(osr.SpatialReference(wkt=r.GetProjection()).IsSame(epsg3413), "GDAL's CRS of max_elevation.asc")
    gt = r.GetGeoTransform()
    check(np.allclose(gt, (REGION[0], DX, 0, REGION[3], 0, -DX), atol=1e-6), f"GDAL's corner of max_elevation.asc {gt}")
    check((r.RasterXSize, r.RasterYSize) == (38, 18), f"raster size {r.RasterXSize} x {r.RasterYSize}")
    with xarray.open_dataset(os.path.join(run, "snapshots.nc")) as s:
        check(s.eta.shape == (1, 18, 38), f"snapshot shape {s.eta.shape}")
        check(float(s.x[0]) == REGION[0] + 20, f"snapshot x starts at {float(s.x[0])}")


def copy_data(name):
    d = os.path.join(ARGS.work, name)
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(DATA, d)
    return d


@test
def bad_dem_inputs_are_refused_naming_the_input():
    from osgeo import osr
    cases = []
    d = copy_data("crs")  # the surface in UTM zone 24N
    utm = osr.SpatialReference()
    utm.ImportFromEPSG(32624)
    utm.MorphToESRI()
    open(os.path.join(d, "surface.prj"), "w").write(utm.ExportToWkt())
    cases.append(("different CRS", dict(surface=os.path.join(d, "surface.asc")), "--surface", "not in the bed DEM's CRS"))
    d = copy_data("apart")  # the surface 100 km east
    lines = open(os.path.join(d, "surface.asc")).read().split("\n")
    lines[2] = "xllcorner -100000.0"
    open(os.path.join(d, "surface.asc"), "w").write("\n".join(lines))
    cases.append(("no overlap", dict(surface=os.path.join(d, "surface.asc")), "--surface", "does not overlap"))
    d = copy_data("hole")  # one NODATA cell in the middle of the bed
    lines = open(os.path.join(d, "bed.asc")).read().split("\n")
    row = lines[6 + 20].split()
    row[40] = "-9999"
    lines[6 + 20] = " ".join(row)
    open(os.path.join(d, "bed.asc"), "w").write("\n".join(lines))
    cases.append(("NODATA inside", dict(bed=os.path.join(d, "bed.asc")), "--bed", "NODATA inside the region"))
    d = copy_data("sea")  # the front line out in the fjord, 1400 m from the corner
    front = json.load(open(os.path.join(d, "front.geojson")))
    for p in front["features"][0]["geometry"]["coordinates"]:
        p[0] = -200000 + 1400
    json.dump(front, open(os.path.join(d, "front.geojson"), "w"))
    cases.append(("front outside the ice", dict(front=os.path.join(d, "front.geojson")), "--front", "outside the ice"))
    for what, inputs, key, words in cases:
        out = os.path.join(ARGS.work, "bad_" + what.replace(" ", "_"))
        r = tool(out, expect=2, **inputs)
        msg = r.stderr.strip()
        check(msg.startswith("dem_to_scene.py: ") and key in msg and words in msg and "\n" not in msg,
              f"{what}: message {msg!r}")
        check(not os.path.exists(out), f"{what}: {out} written")


@test
def heightfield_shape_input_errors_name_the_key():
    out = made()
    scene = json.load(open(os.path.join(out, "glacier_3d.json")))
    cases = [("bodies[0].shape.top", lambda s: s["bodies"][0]["shape"].update(top="bed.asc"), "above the bottom"),
             ("bodies[0].shape.bottom", lambda s: s["bodies"][0]["shape"].update(bottom="no_such.asc"), "no such file"),
             ("bodies[0].shape.depth", lambda s: s["bodies"][0]["shape"].update(depth=1), "unknown key"),
             ("bodies[0].shape.footprint.vertices",
              lambda s: s["bodies"][0]["shape"].update(footprint={"vertices": [[0, 0], [10, 0]]}), "at least 3")]
    for key, change, words in cases:
        s = json.loads(json.dumps(scene))
        change(s)
        path = os.path.join(out, "bad.json")
        json.dump(s, open(path, "w"))
        r = cdmpm("check", path, expect=2)
        check(key in r.stderr and words in r.stderr, f"{key}: {r.stderr.strip()}")


@test
def heightfield_footprint_keeps_the_ice_inside_it():
    # A footprint splits the glacier at x = 300 m (between lattice points): the ice seeded on either side adds up to
    # the whole glacier's, each part non-empty. The water body is seeded alone to count it out.
    out = made()
    path = os.path.join(out, "glacier_3d.json")
    scene = json.load(open(path))
    check([b["material"] for b in scene["bodies"]] == ["ice", "water"], "the tutorial scene's bodies: ice, then water")
    x1, y1 = scene["domain"]["size"][:2]

    def seeded(*sets):
        r = cdmpm("check", path, *[a for s in sets for a in ("--set", s)])
        m = re.search(r"seeded: (\d+) particles", r.stdout)
        check(m is not None, f"no particle count in {r.stdout!r}")
        return int(m.group(1)) if m else 0

    def footprint(xa, xb):
        return "bodies.0.shape.footprint=" + json.dumps({"vertices": [[xa, 0], [xb, 0], [xb, y1], [xa, y1]]})

    water = seeded("bodies=" + json.dumps(scene["bodies"][1:]))
    whole, left, right = (seeded(*f) - water for f in ([], [footprint(0, 300)], [footprint(300, x1)]))
    check(left > 0 and right > 0 and left + right == whole, f"ice seeded with the footprints {left} + {right}, "
          f"without {whole}")


def use_args(args):
    global ARGS
    ARGS = args


if __name__ == "__main__":
    harness.main(__doc__, "cdmpm_dem_", use_args)
