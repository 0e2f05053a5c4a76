#!/usr/bin/python3
"""test_netcdf_outputs.py - the netCDF (CF 1.8) and georeferenced outputs of a run, read back with python3-netcdf4,
GDAL and xarray and checked against the CSV/ASCII products and theory:

    /usr/bin/python3 tests/tools/test_netcdf_outputs.py --cdmpm PATH [--work DIR] [--keep] [-k NAME]

Each test prints PASS or FAIL with the reason; the last line is "N passed, M failed" (exit status 1 if any failed).
  - 2D (scenes/handoff_2d.json, coarse): stations.nc holds probes.csv's values and each station's coordinates in the
    domain and on the map (along the transect's azimuth), bed and still level; snapshots.nc at the section's point
    holds the section's eta, d and q of probes.csv, and at t = 0 the solitary wave the scene started (eta =
    H sech^2(k (x - x0)), hu = c eta); hazard.csv and waves.csv carry easting and northing; summary.json the CRS;
  - 3D (a still lake beside a shelf, EPSG:3413): hazard.nc holds the rasters' values on the rasters' cell centres;
    GDAL reads the rasters (with their .prj) and hazard.nc with the CRS and corner; the snapshots of the still lake
    are flat and at rest; xarray opens every file; terrain.vtp is the shelf and the floor under every column;
  - tools/plot_probes.py draws a section probe as one panel per quantity with its stations as lines;
  - every file satisfies the CF rules of tests/tools/cf_rules.py, and those rules catch files that break them;
  - snapshots change no simulation bit (probes.csv the same bytes with and without them) and have the same bytes
    on 1 and 2 threads and across a checkpoint and resume;
  - bad keys (snapshots, georeference.crs, georeference.time_origin) stop the program with exit code 2 and a
    message naming the key, writing nothing.
"""
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np
from netCDF4 import Dataset

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.io import read_asc, read_csv  # noqa: E402
import cf_rules  # noqa: E402
import harness  # noqa: E402
from harness import check, test  # noqa: E402

HANDOFF = os.path.join(ROOT, "scenes", "handoff_2d.json")
CELLS = 4  # cells per depth of the coarse 2D run
COARSE = ["--set", f"parameters.cells_per_h={CELLS}", "--set", "time.end=3", "--set", "output.snapshots.times=[0,1,2,3]"]
H, DEPTH, X0, G = 0.1, 1.0, 10.0, 9.81  # the scene's wave height, depth, crest position, gravity

ARGS = None


def cdmpm(*args, expect=0):
    r = subprocess.run([ARGS.cdmpm, *args], capture_output=True, text=True)
    check(r.returncode == expect, f"cdmpm {' '.join(args)}: exit {r.returncode}, expected {expect}: {r.stderr[-2000:]}")
    return r


RUNS = {}


def run_2d():
    """The coarse 2D run (once)."""
    if "2d" not in RUNS:
        out = os.path.join(ARGS.work, "handoff")
        cdmpm("run", HANDOFF, "--out", out, "--quiet", *COARSE)
        RUNS["2d"] = out
    return RUNS["2d"]


LAKE = {
    "name": "lake", "dim": 3,
    "domain": {"size": [1.0, 0.5, 0.3], "dx": 0.05},
    "time": {"end": 0.4, "frame_interval": 0.2},
    "materials": {"water": {"type": "water", "density": 1000, "bulk_modulus": 2e5}},
    "bodies": [{"material": "water", "particles_per_cell": 8,
                "shape": {"type": "box", "min": [0, 0, 0], "max": [1.0, 0.5, 0.15]}}],
    "boundaries": [{"type": "walls", "condition": "slip"},
                   {"type": "box", "condition": "slip", "min": [0.6, 0, 0], "max": [1.0, 0.5, 0.2]}],
    "georeference": {"easting": -200000.5, "northing": -2100000.25, "crs": "EPSG:3413"},
    "output": {"frames": False,
               "snapshots": {"times": [0, 0.2, 0.4], "start": [0.025, 0.025], "spacing": 0.05, "count": [12, 10]}}
}


def run_3d():
    if "3d" not in RUNS:
        scene = os.path.join(ARGS.work, "lake.json")
        with open(scene, "w") as f:
            json.dump(LAKE, f)
        out = os.path.join(ARGS.work, "lake")
        cdmpm("run", scene, "--out", out, "--quiet")
        RUNS["3d"] = out
    return RUNS["3d"]


def close(a, b, rtol=1e-9):
    """Equal as written to 10 significant digits (probes.csv), NaN equal to NaN."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.allclose(a, b, rtol=rtol, atol=1e-300, equal_nan=True)


def values(var):
    return np.ma.filled(var[:].astype(float), np.nan)


@test
def stations_hold_probes_csv_and_station_coordinates():
    out = run_2d()
    probes = read_csv(os.path.join(out, "probes.csv"))
    with Dataset(os.path.join(out, "stations.nc")) as ds:
        check(ds.featureType == "timeSeries", "featureType")
        names = ["".join(c.decode() for c in row if c) for row in np.ma.filled(ds["station_name"][:], b"")]
        check(names == ["g20", "g30", "g40", "s20"], f"stations {names}")
        check(close(values(ds["time"]), probes["time"]), "time differs from probes.csv")
        for k, name in enumerate(names):
            column = name + ("_eta" if name == "s20" else "")
            check(close(values(ds["eta"])[k], probes[column]), f"eta of {name} differs from probes.csv")
        for q, column in (("d", "s20_d"), ("u", "s20_u"), ("q", "s20_q")):
            check(close(values(ds[q])[3], probes[column]), f"{q} of s20 differs from probes.csv")
            check(np.isnan(values(ds[q])[0]).all(), f"{q} of the wave gauge g20 is not the fill value")
        x = np.array([20.0, 30.0, 40.0, 20.0])
        check(close(values(ds["x"]), x), "station x")
        # Azimuth 270: +x points west, easting = E0 - x, northing = N0 (to rounding of cos 270 deg).
        check(np.allclose(values(ds["easting"]), 500000 - x, rtol=0, atol=1e-9), f"easting {values(ds['easting'])}")
        check(np.allclose(values(ds["northing"]), 7700000, rtol=0, atol=1e-9), "northing")
        check(np.allclose(values(ds["bed"]), 0, atol=1e-9 * 1.5), "bed of a flat floor is not 0")
        check(close(values(ds["still_level"]), [DEPTH] * 4), "still level")
        check(ds["time"].units == "seconds since 2014-07-04 12:00:00", f"time units {ds['time'].units}")
        check(ds["crs"].grid_mapping_name == "transverse_mercator", "grid mapping of EPSG:32624")
        check(abs(ds["crs"].longitude_of_central_meridian - (-39)) < 1e-12, "UTM 24N central meridian -39")


@test
def snapshots_hold_the_section_and_the_initial_solitary_wave():
    out = run_2d()
    probes = read_csv(os.path.join(out, "probes.csv"))
    t = np.asarray(probes["time"])
    with Dataset(os.path.join(out, "snapshots.nc")) as ds:
        x = values(ds["x"])
        dx = DEPTH / CELLS
        check(close(x, np.arange(60 * CELLS + 1) * dx), "snapshot grid")
        i = int(round(20 / dx))
        for k, ts in enumerate(values(ds["time"])):
            row = int(np.argmin(abs(t - ts)))
            check(abs(t[row] - ts) < 1e-9, f"no probe sample at snapshot time {ts}")
            for q, column in (("eta", "s20_eta"), ("d", "s20_d"), ("hu", "s20_q")):
                check(close(values(ds[q])[k, i], probes[column][row]),
                      f"{q} at x = 20, t = {ts}: {values(ds[q])[k, i]} vs section {probes[column][row]}")
        # t = 0: the Boussinesq solitary wave the scene seeds, eta = H sech^2(k (x - x0)), hu = c eta (u = c eta /
        # (h + eta) over the depth h + eta), within the surface's resolution: a column's top is its highest
        # particle plus half the spacing, within half a spacing (dx/4) of the surface; hu within c dx/4.
        k, c = math.sqrt(3 * H / (4 * DEPTH ** 3)), math.sqrt(G * (DEPTH + H))
        eta0 = H / np.cosh(k * (x - X0)) ** 2
        err = np.nanmax(abs(values(ds["eta"])[0] - eta0))
        check(err <= dx / 4, f"initial eta differs from the solitary wave by {err:.4g} > dx/4 = {dx / 4:.4g}")
        err = np.nanmax(abs(values(ds["hu"])[0] - c * eta0))
        check(err <= c * dx / 4, f"initial hu differs from c eta by {err:.4g} > c dx/4 = {c * dx / 4:.4g}")
        check(np.allclose(values(ds["easting"]), 500000 - x, rtol=0, atol=1e-9), "snapshot easting")


@test
def hazard_profile_gauges_and_summary_carry_the_map():
    out = run_2d()
    hz = read_csv(os.path.join(out, "hazard.csv"))
    check(np.allclose(hz["easting"], 500000 - np.asarray(hz["x"]), rtol=0, atol=1e-6), "hazard.csv easting")
    check(np.allclose(hz["northing"], 7700000, rtol=0, atol=1e-6), "hazard.csv northing")
    waves = read_csv(os.path.join(out, "waves.csv"))
    check(np.allclose(waves["easting"], 500000 - np.asarray(waves["x"]), rtol=0, atol=1e-6), "waves.csv easting")
    with open(os.path.join(out, "summary.json")) as f:
        crs = json.load(f)["georeference"]["crs"]
    check(crs["epsg"] == 32624 and crs["name"] == "WGS 84 / UTM zone 24N", f"summary crs {crs['name']}")


@test
def hazard_grid_matches_the_rasters_and_gdal_reads_the_crs():
    from osgeo import gdal, osr
    gdal.UseExceptions()
    out = run_3d()
    dx, e0, n0 = 0.05, LAKE["georeference"]["easting"], LAKE["georeference"]["northing"]
    epsg3413 = osr.SpatialReference()
    epsg3413.ImportFromEPSG(3413)
    with Dataset(os.path.join(out, "hazard.nc")) as ds:
        check(close(values(ds["x"]), e0 + dx * (np.arange(20) + 0.5)), "hazard.nc x: cell centres on the map")
        check(close(values(ds["y"]), n0 + dx * (np.arange(10) + 0.5)), "hazard.nc y")
        check(ds["crs"].grid_mapping_name == "polar_stereographic", "grid mapping of EPSG:3413")
        check(ds["crs"].straight_vertical_longitude_from_pole == -45, "EPSG:3413 central longitude -45")
        check(ds["crs"].standard_parallel == 70, "EPSG:3413 standard parallel 70")
        for name in ("max_elevation", "max_elevation_time", "arrival_time", "inundation_depth"):
            asc = os.path.join(out, name + ".asc")
            check(os.path.isfile(os.path.join(out, name + ".prj")), f"{name}.prj missing")
            raster = read_asc(asc)[0][::-1]  # NaN where NODATA; the first row the northernmost
            check(close(values(ds[name]), raster), f"{name}: hazard.nc differs from the raster")
            r = gdal.Open(asc)
            check(osr.SpatialReference(wkt=r.GetProjection()).IsSame(epsg3413),
                  f"GDAL reads {name}.asc's CRS as {r.GetProjection()[:80]}")
            gt = r.GetGeoTransform()
            check(np.allclose(gt, (e0, dx, 0, n0 + 10 * dx, 0, -dx), rtol=0, atol=1e-9), f"GDAL's corner of {name}.asc {gt}")
        n = gdal.Open(f'NETCDF:"{os.path.join(out, "hazard.nc")}":max_elevation')
        check(osr.SpatialReference(wkt=n.GetProjection()).IsSame(epsg3413), "GDAL reads hazard.nc's CRS")
        gt = n.GetGeoTransform()
        check(np.allclose([gt[0], gt[1], abs(gt[5])], [e0, dx, dx], rtol=0, atol=1e-6), f"GDAL's corner of hazard.nc {gt}")
        check(abs(min(gt[3], gt[3] + 10 * gt[5]) - n0) < 1e-6, f"GDAL's south edge of hazard.nc {gt}")


@test
def still_lake_snapshots_are_flat_at_rest_and_xarray_opens_every_file():
    import xarray
    out = run_3d()
    with Dataset(os.path.join(out, "snapshots.nc")) as ds:
        eta, hu, hv = values(ds["eta"]), values(ds["hu"]), values(ds["hv"])
        lake = values(ds["x"]) < LAKE["georeference"]["easting"] + 0.6
        spacing = 0.05 / 2
        # The lake (hydrostatic at the start) stays within a quarter of the particle spacing of its still level;
        # the shelf's columns hold no water (eta the fill value, d = hu = hv = 0).
        check(np.nanmax(abs(eta[:, :, lake])) <= spacing / 4, f"lake eta {np.nanmax(abs(eta[:, :, lake])):.3g}")
        check(np.isnan(eta[:, :, ~lake]).all() and (values(ds["d"])[:, :, ~lake] == 0).all(), "the shelf is dry")
        # At rest: |hu| below the hydrostatic adjustment's speed scale, sqrt(g h) times the level's resolution.
        limit = math.sqrt(9.81 * 0.15) * spacing / 4
        check(max(np.nanmax(abs(hu)), np.nanmax(abs(hv))) <= limit, f"lake discharge {np.nanmax(abs(hu)):.3g} > {limit:.3g}")
    for run, name in ((run_3d(), "snapshots.nc"), (run_3d(), "hazard.nc"), (run_2d(), "snapshots.nc"),
                      (run_2d(), "stations.nc")):
        with xarray.open_dataset(os.path.join(run, name)) as x:
            check(len(x.data_vars) > 0, f"xarray reads no variable of {name}")
            if "time" in x.coords and name != "hazard.nc":
                check(str(x.time.values[0]).startswith("2014-07-04T12:00:00" if run == run_2d() else "1970-01-01"),
                      f"xarray's first time of {name}: {x.time.values[0]}")


@test
def terrain_surface_is_the_bed_under_every_column():
    import xml.etree.ElementTree as ET
    out = run_3d()
    piece = ET.parse(os.path.join(out, "terrain.vtp")).getroot().find("PolyData/Piece")
    nx, ny, dx = 20, 10, 0.05
    check(int(piece.get("NumberOfPoints")) == nx * ny and int(piece.get("NumberOfPolys")) == (nx - 1) * (ny - 1),
          f"terrain.vtp: {piece.get('NumberOfPoints')} points, {piece.get('NumberOfPolys')} quads")
    arrays = {a.get("Name"): np.array(a.text.split(), dtype=float) for a in piece.iter("DataArray") if a.get("Name")}
    points = np.array(piece.find("Points/DataArray").text.split(), dtype=float).reshape(-1, 3)
    conn, offsets = arrays["connectivity"].astype(int), arrays["offsets"].astype(int)
    check(offsets[-1] == len(conn) == 4 * (nx - 1) * (ny - 1) and conn.max() == nx * ny - 1, "quads' connectivity")
    # The column centres in the frames' coordinates, at the bed: the shelf (0.2 m high from x = 0.6 m) and the floor,
    # to bed_height's accuracy (1e-9 of the domain's height); the same bed as hazard.nc's.
    xc = dx * (np.arange(nx) + 0.5)
    check(np.allclose(points[:nx, 0], xc) and np.allclose(points[::nx, 1], dx * (np.arange(ny) + 0.5)), "point x, y")
    expected = np.tile(np.where(xc > 0.6, 0.2, 0.0), ny)
    check(np.allclose(points[:, 2], expected, rtol=0, atol=1e-9 * 0.3), f"terrain heights {points[:nx, 2]}")
    check(np.array_equal(points[:, 2], arrays["bed"]), "point data bed differs from the heights")
    with Dataset(os.path.join(out, "hazard.nc")) as ds:
        check(close(values(ds["bed"]).ravel(), arrays["bed"], rtol=1e-11), "terrain.vtp's bed differs from hazard.nc's")


@test
def every_file_satisfies_the_cf_rules_and_the_rules_catch_violations():
    files = [os.path.join(run_2d(), n) for n in ("stations.nc", "snapshots.nc")] + \
            [os.path.join(run_3d(), n) for n in ("hazard.nc", "snapshots.nc")]
    for f in files:
        found = cf_rules.violations(f)
        check(not found, "\n".join(found))
    # The rules are not vacuous: each breach below is caught.
    breaches = [("eta", "delncattr", "units", "3.1"), ("eta", "setncattr", ("standard_name", "sea_level"), "3.3"),
                ("station_name", "delncattr", "cf_role", "9.5"), ("eta", "setncattr", ("coordinates", "lat lon"), "5"),
                ("time", "setncattr", ("units", "s"), "4.4"), ("crs", "delncattr", "crs_wkt", "5.6")]
    for var, op, arg, rule in breaches:
        broken = os.path.join(ARGS.work, "broken.nc")
        shutil.copy(files[0], broken)
        with Dataset(broken, "a") as ds:
            getattr(ds[var], op)(*(arg if isinstance(arg, tuple) else (arg,)))
        found = cf_rules.violations(broken)
        check(any(f": {rule}: " in v for v in found), f"{var} {op} {arg}: rule {rule} not caught ({found})")


@test
def snapshots_change_no_bit_and_are_reproducible():
    base = os.path.join(ARGS.work, "bits")
    plain_sets = ["--quiet", "--set", f"parameters.cells_per_h={CELLS}", "--set", "time.end=3", "--set",
                  "time.frame_interval=1", "--set", "output.checkpoint_every=1"]
    common = plain_sets + ["--set", "output.snapshots.times=[0,1,2,3]"]
    scene = json.load(open(HANDOFF))
    del scene["output"]["snapshots"]
    plain = os.path.join(ARGS.work, "plain.json")
    json.dump(scene, open(plain, "w"))
    # With frames, whose particle arrays are the state bit for bit (probes.csv has 10 significant digits).
    frames = ["--set", "output.frames=true"]
    cdmpm("run", plain, "--out", base + "_plain", "--threads", "2", *plain_sets, *frames)
    cdmpm("run", HANDOFF, "--out", base + "_frames", "--threads", "2", *common, *frames)
    cdmpm("run", HANDOFF, "--out", base + "_2", "--threads", "2", *common)
    cdmpm("run", HANDOFF, "--out", base + "_1", "--threads", "1", *common)
    cdmpm("run", HANDOFF, "--out", base + "_half", "--threads", "2", *common, "--set", "time.end=1.5")
    cdmpm("run", "--resume", base + "_half", "--threads", "2", "--quiet", "--set", "time.end=3")
    read = lambda d, f: open(os.path.join(d, f), "rb").read()  # noqa: E731
    for f in ("probes.csv", "particles_0001.vtu", "particles_0003.vtu"):
        check(read(base + "_plain", f) == read(base + "_frames", f), f"snapshots changed {f}")
    for f in ("snapshots.nc", "stations.nc", "probes.csv"):
        check(read(base + "_2", f) == read(base + "_1", f), f"{f} differs between 1 and 2 threads")
        check(read(base + "_2", f) == read(base + "_half", f), f"{f} differs after a resume")


@test
def plot_probes_draws_a_section_as_one_panel_per_quantity():
    import plot_probes
    out = run_2d()
    names = set(read_csv(os.path.join(out, "probes.csv")))
    panels = plot_probes.section_panels(out, names)
    check([p[0].split(":")[0] for p in panels] == ["s20"] * 4, f"2D section panels {panels}")
    check([p[1][0][0] for p in panels] == ["s20_eta", "s20_d", "s20_u", "s20_q"], f"2D section columns {panels}")
    check(all("[m" in p[0] for p in panels), f"units missing in {panels}")
    # A 3D section of 3 stations: 6 panels (eta, d, u, v, qx, qy), 3 lines each.
    fake = os.path.join(ARGS.work, "fake3d")
    os.makedirs(fake, exist_ok=True)
    with open(os.path.join(fake, "scene.resolved.json"), "w") as f:
        json.dump({"dim": 3, "probes": {"list": [{"name": "s", "type": "section", "start": [0, 0], "end": [2, 0],
                                                  "points": 3}]}}, f)
    cols = {f"s_{k}_{q}" for k in range(3) for q in ("eta", "d", "u", "v", "qx", "qy")}
    panels = plot_probes.section_panels(fake, cols)
    check(len(panels) == 6 and all(len(p[1]) == 3 for p in panels), f"3D section panels {panels}")
    check(panels[0][1][2][1] == "station 2 (2, 0) m", f"station label {panels[0][1][2][1]}")
    r = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools", "plot_probes.py"), out], capture_output=True,
                       text=True)
    check(r.returncode == 0 and os.path.isfile(os.path.join(out, "plots", "probes.png")), f"plot_probes: {r.stderr}")


@test
def bad_keys_are_input_errors_naming_the_key():
    cases = [
        ("output.snapshots.times=[0.5,0.25]", "output.snapshots.times[1]"),
        ("output.snapshots.times=[0.013]", "output.snapshots.times[0]"),
        ("output.snapshots.spacing=0", "output.snapshots.spacing"),
        ("output.snapshots.count=[10000]", "output.snapshots.start"),
        ("output.snapshots.count=[2.5]", "output.snapshots.count"),
        ("output.snapshots.grid=1", "output.snapshots.grid"),
        ('georeference.crs="EPSG:999999"', "georeference.crs"),
        ('georeference.crs="EPSG:4326"', "georeference.crs"),
        ('georeference.crs="PROJCS[nonsense"', "georeference.crs"),
        ('georeference.time_origin="2014-13-04T12:00:00Z"', "georeference.time_origin"),
    ]
    for setting, key in cases:
        out = os.path.join(ARGS.work, "bad")
        r = cdmpm("run", HANDOFF, "--out", out, "--quiet", "--set", setting, expect=2)
        check(key in r.stderr, f"{setting}: message does not name {key}: {r.stderr.strip()}")
        check(not os.path.exists(out), f"{setting}: {out} written")


def use_args(args):
    global ARGS
    ARGS = args


if __name__ == "__main__":
    harness.main(__doc__, "cdmpm_netcdf_", use_args)
