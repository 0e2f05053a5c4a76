#!/usr/bin/python3
"""float_draft.py - how a buoyant body comes to float (the float criterion: the Archimedes draft within
5 %) from a run's probes.csv: per time interval, the mean draft (the water level of a gauge far from the body
less the body's bottom, centre - H/2), its error against the Archimedes draft (rho_b / rho_w) H, the body's top
against the level, its largest vertical speed, and the level itself (a falling level is water lost).

    /usr/bin/python3 tools/float_draft.py RUN/probes.csv --height 0.4 [--ratio 0.92] [--every 1]
                                          [--centre block_y --speed speed_y --level level]

The column names are those of scenes/rigid_rise_float_2d.json (rigid_position "block", rigid_velocity "speed",
wave_gauge "level" with still_level 0, so that it reads the absolute height). Not part of the tests.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import fail  # noqa: E402
from cdmpm_tools.io import read_table  # noqa: E402

TOOL = "float_draft"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("probes")
    ap.add_argument("--height", type=float, required=True, help="the body's height H (m)")
    ap.add_argument("--ratio", type=float, default=0.92, help="density ratio rho_b / rho_w (default 0.92)")
    ap.add_argument("--every", type=float, default=1.0, help="length of the intervals (s, default 1)")
    ap.add_argument("--centre", default="block_y")
    ap.add_argument("--speed", default="speed_y")
    ap.add_argument("--level", default="level")
    args = ap.parse_args()
    cols = read_table(TOOL, args.probes, ("time", args.centre, args.speed, args.level))
    t, y, v, level = cols["time"], cols[args.centre], cols[args.speed], cols[args.level]
    if len(t) == 0:
        fail(TOOL, f"{args.probes}: no rows")
    draft = level - (y - args.height / 2)
    archimedes = args.ratio * args.height
    print(f"Archimedes draft {archimedes:.4f} m")
    print("interval (s)   draft (m)  error    top - level (m)  largest |v| (m/s)  level (m)")
    start = 0.0
    while start < t[-1]:
        s = (t > start) & (t <= start + args.every)
        if s.any():
            d = draft[s].mean()
            print(f"{start:5.1f}-{start + args.every:5.1f}   {d:.4f}   {100 * (d / archimedes - 1):+6.1f} %  "
                  f"{(y[s] + args.height / 2 - level[s]).mean():+.4f}          {np.abs(v[s]).max():.4f}            "
                  f"{level[s].mean():.4f}")
        start += args.every


if __name__ == "__main__":
    main()
