#!/usr/bin/python3
"""compare_runs.py - are two cdmpm output folders the same, bit for bit? (docs/testing.md)

    /usr/bin/python3 tools/compare_runs.py REF_DIR NEW_DIR [--quiet]

REF_DIR and NEW_DIR are either two run folders (--out of `cdmpm run`) or two folders of run folders (e.g. the
OUTDIR/ref and OUTDIR/new of tools/check_bitwise.sh): then every run folder present in both is compared, and one
present in only one of them is a difference. Per run folder it checks:

  - probes.csv, icebergs.csv and waves.csv: byte for byte (the first differing line is printed); the hazard
    products and crevasses.csv likewise when both runs wrote them;
  - stations.nc, snapshots.nc, hazard.nc, when both runs wrote them: every variable's values bit for bit and its
    attributes, the global attributes but "source" (the program's version) (python3-netcdf4);
  - particles.pvd: the same frame list (file names and the bits of every time);
  - every frame particles_NNNN.vtu, read through tools/cdmpm_tools/frames.py (so any encoding it reads): the particle count,
    the points, and every point-data array present in BOTH frames: the same type, shape and bits (two NaNs are
    equal whatever their payload; +0.0 and -0.0 are not). Arrays present in only one frame are listed (a new
    build may add fields, e.g. a particle id) but are not a difference;
  - summary.json: every key present in both except the timing, memory, thread and version ones (steps, sim_time,
    particles, energies, mass_change, first_iceberg, status, ...) must be equal.

checkpoint.bin is not compared (its layout may change in a refactor; the frames carry the state).
Prints a verdict per run folder; the last line is `ALL IDENTICAL` or `DIFFERENCES FOUND`. Exit status 0 if
everything compared is identical, 1 if not, 2 on bad usage.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.frames import read_pvd, read_vtu  # noqa: E402
from cdmpm_tools.io import read_summary  # noqa: E402

TEXT_FILES = ("probes.csv", "icebergs.csv", "waves.csv")
# The hazard products (docs/scenes.md#hazard), the realised crevasses (docs/scenes.md#crevasses) and the crack-start
# record (docs/ice.md): compared byte for byte when both runs wrote them; a file only one run wrote (a build from before them) is listed, not counted
# as a difference.
HAZARD_FILES = ("hazard.csv", "runup.csv", "max_elevation.asc", "max_elevation_time.asc", "arrival_time.asc",
                "inundation_depth.asc", "crevasses.csv", "crack_starts.csv")
# summary.json keys that depend on the host, the build or the thread count, not on the results.
# The netCDF outputs (docs/running.md#netcdf-outputs): every variable's values bit for bit and every attribute, but
# the global "source", which names the program's version; compared when both runs wrote them (needs python3-netcdf4).
NETCDF_FILES = ("stations.nc", "snapshots.nc", "hazard.nc")
SUMMARY_SKIP = {"wall_time", "setup_wall_time", "particle_steps_per_second", "stepping_particle_steps_per_second",
                "peak_memory_bytes", "bytes_per_particle", "threads", "version", "scene_file", "phase_seconds",
                "command_line", "git_commit"}
MAX_LINE = 160


def is_run_dir(d):
    return any(os.path.exists(os.path.join(d, f)) for f in ("summary.json", "particles.pvd", "probes.csv"))


def short(s):
    s = s.rstrip("\n")
    return s if len(s) <= MAX_LINE else s[:MAX_LINE] + "..."


def compare_text(name, a, b, report):
    """Byte-for-byte comparison of one text file; returns False on a difference."""
    pa, pb = os.path.join(a, name), os.path.join(b, name)
    ea, eb = os.path.exists(pa), os.path.exists(pb)
    if not ea and not eb:
        return True
    if ea != eb:
        report(f"  {name}: only in {'REF' if ea else 'NEW'}")
        return False
    da, db = open(pa, "rb").read(), open(pb, "rb").read()
    if da == db:
        report(f"  {name}: identical ({da.count(10)} lines)", detail=True)
        return True
    la, lb = da.split(b"\n"), db.split(b"\n")
    for i, (x, y) in enumerate(zip(la, lb)):
        if x != y:
            report(f"  {name}: DIFFERS at line {i + 1}:")
            report(f"    REF: {short(x.decode(errors='replace'))}")
            report(f"    NEW: {short(y.decode(errors='replace'))}")
            return False
    report(f"  {name}: DIFFERS: REF has {len(la)} lines, NEW {len(lb)} (one is a prefix of the other)")
    return False


def compare_netcdf(name, a, b, report):
    """Values (bit for bit, NaN included) and attributes of every variable of one netCDF file; False on a difference."""
    try:
        from netCDF4 import Dataset
    except ImportError:
        report(f"  {name}: not compared (python3-netcdf4 missing)")
        return True
    with Dataset(os.path.join(a, name)) as x, Dataset(os.path.join(b, name)) as y:
        if set(x.variables) != set(y.variables):
            report(f"  {name}: DIFFERS: variables {sorted(x.variables)} against {sorted(y.variables)}")
            return False
        ga = {k: str(x.getncattr(k)) for k in x.ncattrs() if k != "source"}
        gb = {k: str(y.getncattr(k)) for k in y.ncattrs() if k != "source"}
        if ga != gb:
            report(f"  {name}: DIFFERS in its global attributes")
            return False
        for v in x.variables:
            va, vb = x.variables[v], y.variables[v]
            va.set_auto_maskandscale(False)
            vb.set_auto_maskandscale(False)
            if np.asarray(va[:]).tobytes() != np.asarray(vb[:]).tobytes() or \
                    {k: str(va.getncattr(k)) for k in va.ncattrs()} != {k: str(vb.getncattr(k)) for k in vb.ncattrs()}:
                report(f"  {name}: DIFFERS in variable {v}")
                return False
    report(f"  {name}: identical", detail=True)
    return True


def float_bits(x):
    return np.float64(x).tobytes()


def equal_bits(x, y):
    """Element mask of bit-identical values of two arrays of the same dtype and shape; NaN == NaN."""
    if x.dtype.kind == "f":
        u = np.dtype(f"u{x.dtype.itemsize}")
        eq = np.ascontiguousarray(x).view(u) == np.ascontiguousarray(y).view(u)
        return eq | (np.isnan(x) & np.isnan(y))
    return x == y


def describe_diff(x, y, eq):
    """Where and how much two arrays of the same shape differ (eq: element mask, False where they differ)."""
    bad = np.argwhere(~eq)
    n = len(bad)
    first = tuple(int(i) for i in bad[0])
    where = first[0] if len(first) == 1 else first
    s = f"{n} of {eq.size} values differ; first at {where}: REF {x[first]!r} NEW {y[first]!r}"
    if x.dtype.kind in "fi":
        with np.errstate(all="ignore"):
            xf, yf = x.astype(np.float64), y.astype(np.float64)
            d = np.abs(xf - yf)[~eq]
            fin = np.isfinite(d)
            if fin.any():
                scale = np.maximum(np.abs(xf), np.abs(yf))[~eq][fin]
                rel = np.where(scale > 0, d[fin] / np.where(scale > 0, scale, 1), 0)
                s += f"; max |diff| {d[fin].max():.3g}, max rel {rel.max():.3g}"
            if (~fin).any():
                s += f"; {int((~fin).sum())} differ in NaN/inf"
    return s


def compare_array(label, x, y):
    """None if bit-identical, else a description of the difference."""
    if x.dtype != y.dtype:
        return f"type {x.dtype} vs {y.dtype}"
    if x.shape != y.shape:
        return f"shape {x.shape} vs {y.shape}"
    eq = equal_bits(x, y)
    if eq.all():
        return None
    return describe_diff(x, y, eq)


def compare_frames(a, b, report, stats):
    pa, pb = os.path.join(a, "particles.pvd"), os.path.join(b, "particles.pvd")
    ea, eb = os.path.exists(pa), os.path.exists(pb)
    if not ea and not eb:
        report("  frames: none in either (output.frames=false?)")
        return True
    if ea != eb:
        report(f"  particles.pvd: only in {'REF' if ea else 'NEW'}")
        return False
    fa, fb = read_pvd(a), read_pvd(b)
    ok = True
    if len(fa) != len(fb) or any(x[1] != y[1] or float_bits(x[0]) != float_bits(y[0]) for x, y in zip(fa, fb)):
        ok = False
        for i, (x, y) in enumerate(zip(fa, fb)):
            if x[1] != y[1] or float_bits(x[0]) != float_bits(y[0]):
                report(f"  particles.pvd: DIFFERS at entry {i}: REF t={x[0]!r} {x[1]}, NEW t={y[0]!r} {y[1]}")
                break
        else:
            report(f"  particles.pvd: DIFFERS: REF lists {len(fa)} frames, NEW {len(fb)}")
    # Compare the frames listed in both (by file name), so that a shorter run still shows where it diverges.
    files_b = {f for _, f in fb}
    common = [f for _, f in fa if f in files_b]
    only = {}
    first_bad = None
    for f in common:
        xa, xb = os.path.join(a, f), os.path.join(b, f)
        if not os.path.exists(xa) or not os.path.exists(xb):
            report(f"  {f}: listed but missing in {'REF' if not os.path.exists(xa) else 'NEW'}")
            ok = False
            continue
        pts_a, fld_a = read_vtu(xa)
        pts_b, fld_b = read_vtu(xb)
        stats["frames"] += 1
        stats["particles"] = len(pts_a)
        problems = []
        if len(pts_a) != len(pts_b):
            problems.append(f"particle count {len(pts_a)} vs {len(pts_b)}")
        else:
            d = compare_array("Points", np.asarray(pts_a), np.asarray(pts_b))
            if d:
                problems.append(f"Points: {d}")
            for name in fld_a:
                if name in fld_b:
                    d = compare_array(name, np.asarray(fld_a[name]), np.asarray(fld_b[name]))
                    if d:
                        problems.append(f"{name}: {d}")
        for name in set(fld_a) ^ set(fld_b):
            only.setdefault(name, "REF" if name in fld_a else "NEW")
        stats["fields"] = sorted(set(fld_a) & set(fld_b))
        if problems:
            ok = False
            if first_bad is None:
                first_bad = f
                report(f"  {f}: DIFFERS ({len(pts_a)} particles):")
                for p in problems:
                    report(f"    {p}")
            stats["frames_differing"] += 1
        else:
            report(f"  {f}: identical ({len(pts_a)} particles, {len(stats['fields'])} fields)", detail=True)
    if only:
        report("  fields in only one run (not compared): " +
               ", ".join(f"{k} ({v} only)" for k, v in sorted(only.items())))
    if stats["frames_differing"]:
        report(f"  frames: {stats['frames_differing']} of {stats['frames']} differ (first: {first_bad})")
    elif ok:
        report(f"  frames: {stats['frames']} identical, {stats['particles']} particles, "
               f"fields {', '.join(stats['fields']) or '-'} + points")
    return ok


def compare_summary(a, b, report, stats):
    pa, pb = os.path.join(a, "summary.json"), os.path.join(b, "summary.json")
    if not os.path.exists(pa) or not os.path.exists(pb):
        if os.path.exists(pa) != os.path.exists(pb):
            report(f"  summary.json: only in {'REF' if os.path.exists(pa) else 'NEW'}")
            return False
        return True
    sa, sb = read_summary(a), read_summary(b)
    stats["steps"] = sa.get("steps")
    stats["sim_time"] = sa.get("sim_time")
    bad = []

    def walk(x, y, path):
        if isinstance(x, dict) and isinstance(y, dict):
            for k in x:
                if k in y and not (path == "" and k in SUMMARY_SKIP):
                    walk(x[k], y[k], f"{path}.{k}" if path else k)
        elif isinstance(x, float) and isinstance(y, float):
            if float_bits(x) != float_bits(y) and not (math.isnan(x) and math.isnan(y)):
                bad.append(f"{path}: {x!r} vs {y!r}")
        elif x != y:
            bad.append(f"{path}: {x!r} vs {y!r}")

    walk(sa, sb, "")
    if bad:
        report(f"  summary.json: DIFFERS in {len(bad)} value(s): " + "; ".join(bad[:6]) + (" ..." if len(bad) > 6 else ""))
        return False
    report(f"  summary.json: identical results (steps {sa.get('steps')}, sim_time {sa.get('sim_time')})", detail=True)
    return True


def compare_run(a, b, name, verbose):
    lines = []

    def report(s, detail=False):
        if verbose or not detail:
            lines.append(s)

    stats = {"frames": 0, "frames_differing": 0, "particles": None, "fields": [], "steps": None, "sim_time": None}
    ok = True
    for f in TEXT_FILES:
        ok &= compare_text(f, a, b, report)
    for f in HAZARD_FILES:
        if os.path.exists(os.path.join(a, f)) and os.path.exists(os.path.join(b, f)):
            ok &= compare_text(f, a, b, report)
        elif os.path.exists(os.path.join(a, f)) or os.path.exists(os.path.join(b, f)):
            report(f"  {f}: only in {'REF' if os.path.exists(os.path.join(a, f)) else 'NEW'} (not compared)")
    for f in NETCDF_FILES:
        if os.path.exists(os.path.join(a, f)) and os.path.exists(os.path.join(b, f)):
            ok &= compare_netcdf(f, a, b, report)
        elif os.path.exists(os.path.join(a, f)) or os.path.exists(os.path.join(b, f)):
            report(f"  {f}: only in {'REF' if os.path.exists(os.path.join(a, f)) else 'NEW'} (not compared)")
    ok &= compare_frames(a, b, report, stats)
    ok &= compare_summary(a, b, report, stats)
    verdict = "IDENTICAL" if ok else "DIFFERENT"
    print(f"{name}: {verdict} (steps {stats['steps']}, frames compared {stats['frames']}, "
          f"particles {stats['particles']})")
    for s in lines:
        print(s)
    return ok, stats


def main():
    ap = argparse.ArgumentParser(description="Compare two cdmpm output folders bit for bit.")
    ap.add_argument("ref", help="reference run folder, or folder of run folders")
    ap.add_argument("new", help="new run folder, or folder of run folders")
    ap.add_argument("-v", "--verbose", action="store_true", help="also list every identical file and frame")
    ap.add_argument("--json", metavar="FILE", help="write per-run verdicts and counts to FILE")
    ap.add_argument("--skip-summary", metavar="KEY[,KEY]", default="",
                    help="also ignore these top-level summary.json keys, e.g. energy,energy_initial,mass_change across thread "
                         "counts (their OpenMP reduction sums in another order)")
    args = ap.parse_args()
    SUMMARY_SKIP.update(k for k in args.skip_summary.split(",") if k)
    for d in (args.ref, args.new):
        if not os.path.isdir(d):
            print(f"compare_runs: {d} is not a folder", file=sys.stderr)
            return 2

    if is_run_dir(args.ref) or is_run_dir(args.new):
        pairs = [(os.path.basename(os.path.normpath(args.new)) or args.new, args.ref, args.new)]
        missing = []
    else:
        ra = {d for d in os.listdir(args.ref) if is_run_dir(os.path.join(args.ref, d))}
        rb = {d for d in os.listdir(args.new) if is_run_dir(os.path.join(args.new, d))}
        pairs = [(d, os.path.join(args.ref, d), os.path.join(args.new, d)) for d in sorted(ra & rb)]
        missing = [(d, "REF" if d in ra else "NEW") for d in sorted(ra ^ rb)]
        if not pairs and not missing:
            print(f"compare_runs: no run folders in {args.ref} or {args.new}", file=sys.stderr)
            return 2

    all_ok = True
    results = {}
    for name, a, b in pairs:
        ok, stats = compare_run(a, b, name, args.verbose)
        all_ok &= ok
        results[name] = {"identical": ok, **stats}
    for d, side in missing:
        print(f"{d}: DIFFERENT (run folder only in {side})")
        all_ok = False
        results[d] = {"identical": False, "only_in": side}
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    print("ALL IDENTICAL" if all_ok else "DIFFERENCES FOUND")
    return 0 if all_ok else 1


if __name__ == "__main__":
    sys.exit(main())
