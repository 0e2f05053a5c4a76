#!/usr/bin/python3
"""plot_hazard.py - plots of a run's hazard products (docs/scenes.md#hazard) into a folder you name.

    /usr/bin/python3 tools/plot_hazard.py RUN_DIR [--out FOLDER]

2D (hazard.csv, runup.csv): hazard.png, the bed and still level, the maximum free-surface elevation and the
inundation depth along the domain, the arrival time and the time of the maximum, and each shore's run-up and
inundation extent. 3D (the .asc rasters): hazard_maps.png, maps of the maximum elevation, its time, the arrival
time and the inundation depth in map coordinates (the rasters' georeferenced corner). Writes only into FOLDER
(default RUN_DIR/plots; a folder holding committed files is refused unless --force); a folder without hazard
output is a one-line error (exit code 2).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import add_output_arguments, fail as fail_as, output_folder  # noqa: E402
from cdmpm_tools.io import read_asc, read_csv, read_summary  # noqa: E402
from cdmpm_tools.plotting import pyplot, save_figure  # noqa: E402

TOOL = "plot_hazard"


def fail(msg):
    fail_as(TOOL, msg)


plt = pyplot(TOOL)


def plot_2d(run, out):
    h = read_csv(os.path.join(run, "hazard.csv"))
    shores = read_csv(os.path.join(run, "runup.csv")) if os.path.exists(os.path.join(run, "runup.csv")) else {}
    fig, (a, b) = plt.subplots(2, 1, figsize=(11, 7), sharex=True)
    x = h["x"]
    a.plot(x, h["bed"], color="saddlebrown", label="bed [m]")
    a.plot(x, h["still_level"], color="grey", ls="--", label="still level [m]")
    a.plot(x, h["still_level"] + h["max_elevation"], color="tab:blue", label="still level + max elevation [m]")
    a.plot(x, h["bed"] + h["max_depth"], color="tab:red", label="bed + max inundation depth [m]")
    for k in range(len(shores.get("runup", []))):
        if not np.isnan(shores["runup"][k]):
            a.plot(shores["runup_x"][k], shores["still_level"][k] + shores["runup"][k], "k^",
                   label=f"run-up {shores['runup'][k]:.4g} m at x = {shores['runup_x'][k]:.4g} m")
            a.axvline(shores["extent_x"][k], color="k", lw=0.8, ls=":")
    a.set_ylabel("elevation [m]")
    a.legend(fontsize=8, loc="best")
    a.set_title(f"{os.path.basename(os.path.normpath(run))}: maximum elevation and inundation")
    b.plot(x, h["arrival_time"], ".", color="tab:green", label="arrival time [s]")
    b.plot(x, h["time_of_max"], ".", color="tab:purple", ms=3, label="time of the maximum [s]")
    b.set_xlabel("x [m]")
    b.set_ylabel("time [s]")
    b.legend(fontsize=8)
    return [save_figure(fig, os.path.join(out, "hazard.png"), dpi=120)]


def plot_3d(run, out):
    names = [("max_elevation.asc", "maximum elevation [m]"), ("max_elevation_time.asc", "time of the maximum [s]"),
             ("arrival_time.asc", "arrival time [s]"), ("inundation_depth.asc", "maximum inundation depth [m]")]
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    for ax, (name, label) in zip(axes.flat, names):
        data, _, _, extent = read_asc(os.path.join(run, name))
        im = ax.imshow(data, extent=extent, origin="upper", aspect="equal")
        fig.colorbar(im, ax=ax, label=label)
        ax.set_xlabel("easting [m]")
        ax.set_ylabel("northing [m]")
        ax.set_title(name)
    return [save_figure(fig, os.path.join(out, "hazard_maps.png"), dpi=120)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="a run's output folder")
    add_output_arguments(ap, "folder for the PNG files (default RUN/plots; created if missing)")
    args = ap.parse_args()
    has_2d = os.path.isfile(os.path.join(args.run, "hazard.csv"))
    has_3d = os.path.isfile(os.path.join(args.run, "max_elevation.asc"))
    if not (has_2d or has_3d):
        fail(f"{args.run}: no hazard output (hazard.csv or max_elevation.asc); run a scene with water first")
    args.out = output_folder(TOOL, args.out or os.path.join(args.run, "plots"), args.force)
    try:
        written = plot_2d(args.run, args.out) if has_2d else plot_3d(args.run, args.out)
    except (OSError, ValueError, KeyError, IndexError) as e:
        fail(f"{args.run}: cannot plot the hazard output: {e}")
    summary = read_summary(args.run)
    if summary is not None:
        for s in summary.get("hazard", {}).get("shores", []):
            print(f"shore (direction {s['direction']}): run-up {s['runup']} m at x = {s['runup_x']} m, "
                  f"inundation extent x = {s['extent_x']} m")
    for p in written:
        print(p)


if __name__ == "__main__":
    main()
