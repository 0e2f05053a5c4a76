#!/usr/bin/python3
"""test_handoff.py - the hand-off of a cdmpm run to a depth-averaged far-field model (docs/handoff.md), end to end:
a 2D run (scenes/handoff_2d.json: a solitary wave of H/h = 0.1 in a flat channel) writes snapshots.nc; its snapshot
at t0 (the wave clear of the gauges) starts the linear shallow-water solver of tests/tools/shallow_water.py, which
propagates it over the flat water; at the gauges farther out the solver's free surface matches cdmpm's own gauges
(stations.nc) within 10 %: the crest's height and the front's travel time from t0 (the time eta first reaches
half its crest), while the wave is long (k h < 0.5, k the energy-weighted mean wavenumber of the snapshot's eta).
The time integral of eta is printed too, not held to 10 %: at H/h = 0.1 linear theory gives it 7.5 % larger than
the solitary wave does (the comment in the code says why).

    /usr/bin/python3 tests/tools/test_handoff.py --cdmpm PATH [--work DIR] [--keep] [--cells N]

Also checks the oracle itself against d'Alembert's exact solution (1 % of the crest). Prints the figures and PASS
or FAIL; exit status 1 on failure.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from netCDF4 import Dataset

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shallow_water  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(ROOT, "scenes", "handoff_2d.json")
T0 = 2.0                 # the snapshot that starts the far-field model [s]
GAUGES = ["g30", "g40"]  # farther out than the wave at T0 (crest near x = 16.6 h)
TOLERANCE = 0.10
END = 11.0               # the wave has passed the last gauge (crest there near 9 s)


def values(var):
    return np.ma.filled(var[:].astype(float), np.nan)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cdmpm", required=True)
    ap.add_argument("--work")
    ap.add_argument("--keep", action="store_true")
    ap.add_argument("--cells", type=int, default=6, help="cells per depth (parameters.cells_per_h)")
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="cdmpm_handoff_")
    out = os.path.join(work, "run")
    r = subprocess.run([args.cdmpm, "run", SCENE, "--out", out, "--quiet", "--force",
                        "--set", f"parameters.cells_per_h={args.cells}", "--set", f"time.end={END}"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAIL cdmpm exit {r.returncode}: {r.stderr[-2000:]}")
        sys.exit(1)
    failures = []

    with Dataset(os.path.join(out, "snapshots.nc")) as s:
        times = values(s["time"])
        k0 = int(np.argmin(abs(times - T0)))
        x = values(s["x"])
        eta0, q0 = values(s["eta"])[k0], values(s["hu"])[k0]
        h = float(np.mean(values(s["still_level"]) - values(s["bed"])))
    with Dataset(os.path.join(out, "stations.nc")) as st:
        names = ["".join(ch.decode() for ch in row if ch) for row in np.ma.filled(st["station_name"][:], b"")]
        t = values(st["time"])
        positions = values(st["x"])
        gauge_eta = {n: values(st["eta"])[i] for i, n in enumerate(names)}
        gauge_x = {n: positions[i] for i, n in enumerate(names)}
    if np.isnan(eta0).any():
        failures.append("the snapshot has dry points: not flat water")
        eta0 = np.nan_to_num(eta0)

    # Long waves: k h, k the energy-weighted mean wavenumber of the snapshot's eta (the solitary wave's own
    # k = sqrt(3 H / (4 h^3)) gives k h = 0.27).
    spectrum = np.abs(np.fft.rfft(eta0)) ** 2
    k = 2 * np.pi * np.fft.rfftfreq(len(eta0), x[1] - x[0])
    kh = float(np.sum(k * spectrum) / np.sum(spectrum) * h)
    print(f"snapshot at t0 = {times[k0]:.3f} s: depth h = {h:.4f} m, k h = {kh:.3f} (energy-weighted mean k)")
    if not kh < 0.5:
        failures.append(f"k h = {kh:.3f}: not a long wave")

    # The oracle itself against d'Alembert on the exact solitary profile (eta = H sech^2(k (x - x_c)), q = c eta),
    # 5 s later, before the walls matter: within 1 % of the crest.
    H, kc = 0.1 * h, np.sqrt(3 * 0.1 / 4) / h
    smooth = H / np.cosh(kc * (x - 16 * h)) ** 2
    pts = np.array([25.0, 30.0, 35.0]) * h
    exact = shallow_water.dalembert(x, smooth, np.sqrt(9.81 * h) * smooth, h, 5.0, pts)
    solver = shallow_water.propagate(x, smooth, np.sqrt(9.81 * h) * smooth, h, 0.0, [5.0], pts)[0]
    err = float(np.max(np.abs(exact - solver)) / H)
    print(f"oracle vs d'Alembert after 5 s: {100 * err:.2f} % of the crest")
    if err > 0.01:
        failures.append(f"oracle differs from d'Alembert by {100 * err:.2f} % of the crest")

    after = t >= times[k0] - 1e-9
    predicted = shallow_water.propagate(x, eta0, q0, h, times[k0], t[after], [gauge_x[g] for g in GAUGES])
    for j, g in enumerate(GAUGES):
        measured = gauge_eta[g][after]
        tt = t[after]
        peak_m, peak_p = np.nanmax(measured), np.max(predicted[:, j])
        # The front's travel time from t0: the first time eta reaches half its crest (a crest's own time is blurred
        # by the measured surface, flat over a particle spacing near the top).
        ta_m = tt[np.argmax(np.nan_to_num(measured) >= peak_m / 2)] - times[k0]
        ta_p = tt[np.argmax(predicted[:, j] >= peak_p / 2)] - times[k0]
        vol_m = np.trapz(np.nan_to_num(measured), tt)
        vol_p = np.trapz(predicted[:, j], tt)
        figures = {"crest height": (peak_p, peak_m), "front travel time": (ta_p, ta_m)}
        for what, (p, m) in figures.items():
            rel = abs(p - m) / abs(m)
            print(f"{g} (x = {gauge_x[g]:.1f} m): {what}: shallow water {p:.4f}, cdmpm {m:.4f}, {100 * rel:.1f} %")
            if not rel <= TOLERANCE:
                failures.append(f"{g}: {what} differs by {100 * rel:.1f} % > {100 * TOLERANCE:.0f} %")
        # Reported, not held to 10 %: linear theory carries the volume at sqrt(g h), 5 % slower than the solitary
        # wave's sqrt(g (h + H)), and splits (eta, q) into a right-going part of (eta + q / c) / 2, 2.5 % more
        # volume: 7.5 % more integral of eta dt at H/h = 0.1, before the measured surface's own bias.
        print(f"{g} (x = {gauge_x[g]:.1f} m): integral of eta dt: shallow water {vol_p:.4f}, cdmpm {vol_m:.4f}, "
              f"{100 * abs(vol_p - vol_m) / vol_m:.1f} % (linear theory's volume transport, not checked)")
    for f in failures:
        print("FAIL", f)
    print("PASS" if not failures else f"{len(failures)} failed")
    if not args.work and not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
