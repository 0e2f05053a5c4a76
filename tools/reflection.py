#!/usr/bin/python3
"""reflection.py - how much of a wave came back to a gauge: the reflection coefficient of an absorbing boundary
(docs/water.md#absorbing-layer).

    /usr/bin/python3 tools/reflection.py RUN_DIR INCIDENT_DIR [--gauge gauge]

RUN_DIR is a run with the boundary under test; INCIDENT_DIR the same scene in a domain long enough that nothing
comes back to the gauge before the run ends (e.g. `--set parameters.layer_start=44` on
scenes/absorbing_solitary_2d.json). Both records hold the same incident wave, its dispersive tail included, so
their difference at the gauge is what came back:
    R = max_t |eta_run(t) - eta_incident(t)| / max_t |eta_incident(t)|
over the samples both runs hold (the same sampling times). Prints R, the time of the largest difference, the
incident amplitude and, from the mass probe of RUN_DIR when it has one, the water its sinks removed. Needs numpy (Debian's /usr/bin/python3).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import fail  # noqa: E402
from cdmpm_tools.io import read_csv  # noqa: E402

TOOL = "reflection"


def read_probes(run):
    path = os.path.join(run, "probes.csv")
    if not os.path.isfile(path):
        fail(TOOL, f"{path}: no probes.csv (is {run} a cdmpm run folder?)")
    return read_csv(path)


def main():
    import numpy as np
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", help="the run with the absorbing boundary")
    p.add_argument("incident", help="the same scene in a longer domain (the incident wave only)")
    p.add_argument("--gauge", default="gauge", help="the wave gauge's column (default: gauge)")
    args = p.parse_args()
    a, b = read_probes(args.run), read_probes(args.incident)
    for rec, name in ((a, args.run), (b, args.incident)):
        if args.gauge not in rec:
            fail(TOOL, f"{name}/probes.csv: no column {args.gauge!r}")
    n = min(len(a["time"]), len(b["time"]))
    if n == 0 or not np.array_equal(a["time"][:n], b["time"][:n]):
        fail(TOOL, "the two runs do not share their sampling times")
    diff = np.abs(a[args.gauge][:n] - b[args.gauge][:n])
    incident = np.max(np.abs(b[args.gauge][:n]))
    i = int(np.argmax(diff))
    print(f"incident amplitude {incident:.5f} m; largest difference {diff[i]:.5f} m at t = {a['time'][i]:.2f} s; "
          f"R = {diff[i] / incident:.4f} (over t <= {a['time'][n - 1]:.2f} s)")
    if "mass" in a:
        print(f"water removed from {args.run}: {(a['mass'][0] - a['mass'][-1]) / 1000.0:.5f} m^2 (2D, rho 1000 kg/m^3)")

if __name__ == "__main__":
    main()
