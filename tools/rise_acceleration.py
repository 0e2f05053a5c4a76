"""rise_acceleration.py - the acceleration of a body released at rest (the buoyancy measurements of
docs/validation.md) from a run's probes.csv: a least-squares line through a velocity column, or a parabola
y(t) = y0 + v0 t + a t^2 / 2 through the height of the centre of mass, y = E_g / (M g) from a
gravitational_energy and a mass probe of the body's material, over the window [T1, T2]; also V(T2) / T2 from the
velocity (or the parabola's velocity at T2).

    python3 tools/rise_acceleration.py RUN/probes.csv --velocity v_y [--window 0.1 0.3]
    python3 tools/rise_acceleration.py RUN/probes.csv --centre pe m [--window 0.1 0.3]

Prints "slope a = ... m/s^2, mean a = ... m/s^2". Not part of the tests.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.io import read_table  # noqa: E402

TOOL = "rise_acceleration"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("probes")
    ap.add_argument("--velocity", help="velocity column (m/s)")
    ap.add_argument("--centre", nargs=2, metavar=("ENERGY", "MASS"),
                    help="gravitational energy (J) and mass (kg) columns of the body's material")
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--window", nargs=2, type=float, default=[0.1, 0.3])
    a = ap.parse_args()
    cols = read_table(TOOL, a.probes, ["time"] + ([a.velocity] if a.velocity else list(a.centre or [])))
    t = cols["time"]
    t1, t2 = a.window
    w = (t >= t1 - 1e-9) & (t <= t2 + 1e-9)
    if a.velocity:
        v = cols[a.velocity]
        slope = np.polyfit(t[w], v[w], 1)[0]
        end = np.argmin(abs(t - t2))
        mean = v[end] / t[end]
    else:
        y = cols[a.centre[0]] / (cols[a.centre[1]] * a.g)
        c2, c1, _ = np.polyfit(t[w], y[w], 2)
        slope = 2 * c2
        # mean acceleration from rest: the parabola's velocity at t2 over t2
        mean = (c1 + 2 * c2 * t2) / t2
    print(f"slope a = {slope:.4f} m/s^2, mean a = {mean:.4f} m/s^2")


if __name__ == "__main__":
    main()
