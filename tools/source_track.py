#!/usr/bin/python3
"""source_track.py - a recorded calving source from a 2D run's frames, for a replayed body (rigid key `track`,
io/source_track.h, docs/scenes.md#rigid-bodies).

    /usr/bin/python3 tools/source_track.py RUN --region XMIN XMAX --origin X Z [--material ice] [--spacing H]
                                           [--end T] --out FILE

RUN is a 2D run's output folder with particle frames (output.frames true; every frame becomes a record, so choose
time.frame_interval for the motion, e.g. 0.25 s). The material's particles that lie in XMIN <= x <= XMAX at the first
frame are the source. FILE gets their displacement field on a lattice of spacing H (default: twice the run's dx, read
from its scene.resolved.json): for each lattice node, the share of its cell (H x H about the node) that they filled at
the first frame, and at every frame up to T the mean displacement since the first frame of the particles in that cell
(an empty cell takes that of the nearest filled one). Positions are given relative to the run's point (X, Z), so a
scene places the track with "origin": the same point in its own coordinates (e.g. the front at sea level).
Prints the lattice, the records and the source's area (m^2 per metre of width) and the area that moved more than
H / 2 by the last record: the calved cross-section, which times a width across the front gives a volume.
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import fail  # noqa: E402
from cdmpm_tools.frames import read_field_data, read_pvd, read_vtu  # noqa: E402

TOOL = "source_track"


def material_particles(run, frame, material):
    """Positions (n, 2), ids and volumes of MATERIAL's particles in one frame file of RUN."""
    path = os.path.join(run, frame)
    points, fields = read_vtu(path)
    names = list(read_field_data(path)["material_names"])
    if material not in names:
        fail(TOOL, f"{path}: no material '{material}' (materials: {', '.join(names)})")
    for need in ("id", "volume", "material"):
        if need not in fields:
            fail(TOOL, f"{path}: no field '{need}'")
    m = fields["material"] == names.index(material)
    return points[m, :2], fields["id"][m].astype(np.int64), fields["volume"][m]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("--region", nargs=2, type=float, required=True, metavar=("XMIN", "XMAX"))
    ap.add_argument("--origin", nargs=2, type=float, required=True, metavar=("X", "Z"))
    ap.add_argument("--material", default="ice")
    ap.add_argument("--spacing", type=float)
    ap.add_argument("--end", type=float, default=float("inf"))
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    if not os.path.isdir(a.run):
        fail(TOOL, f"{a.run}: not a run folder")
    frames = [(t, f) for t, f in read_pvd(a.run) if t <= a.end + 1e-9]
    if len(frames) < 2:
        fail(TOOL, f"{a.run}: fewer than 2 frames up to t = {a.end} s (run with output.frames true)")
    h = a.spacing
    if h is None:
        scene = json.load(open(os.path.join(a.run, "scene.resolved.json")))
        h = 2 * float(scene["domain"]["dx"])
    if not h > 0:
        fail(TOOL, f"--spacing: expected a length > 0, got {h}")
    x0, ids0, vol = material_particles(a.run, frames[0][1], a.material)
    keep = (x0[:, 0] >= a.region[0]) & (x0[:, 0] <= a.region[1])
    if not keep.any():
        fail(TOOL, f"{a.run}: no {a.material} particle in {a.region[0]} <= x <= {a.region[1]} at t = {frames[0][0]}")
    order = np.argsort(ids0[keep])
    ids, X, area = ids0[keep][order], x0[keep][order] - np.array(a.origin), vol[keep][order]
    lo = np.floor(X.min(0) / h) * h
    n = (np.ceil((X.max(0) - lo) / h)).astype(int) + 1
    cell = np.rint((X - lo) / h).astype(int)
    node = cell[:, 0] + n[0] * cell[:, 1]
    nodes = n[0] * n[1]
    count = np.bincount(node, minlength=nodes)
    fill = np.minimum(np.bincount(node, weights=area, minlength=nodes) / h**2, 1.0)
    filled = np.flatnonzero(count)
    centres = lo + np.stack(np.unravel_index(np.arange(nodes), (n[1], n[0]))[::-1], 1) * h
    nearest = filled[np.argmin(((centres[:, None, :] - centres[None, filled, :]) ** 2).sum(2), 1)]
    records, last = [], X
    for t, f in frames:
        x, i, _ = material_particles(a.run, f, a.material)
        at = {k: j for j, k in enumerate(i.tolist())}
        pos = last.copy()  # a particle no longer in the frame (removed by a sink) keeps its last position
        for j, k in enumerate(ids.tolist()):
            if k in at:
                pos[j] = x[at[k]] - np.array(a.origin)
        last = pos
        u = pos - X
        mean = np.stack([np.bincount(node, weights=u[:, c], minlength=nodes) for c in (0, 1)], 1)
        mean[filled] /= count[filled, None]
        records.append((t - frames[0][0], mean[nearest]))
    moved = np.linalg.norm(records[-1][1][node], axis=1) > h / 2
    with open(a.out, "w") as out:
        out.write(f"# A calving source recorded from {os.path.abspath(a.run)} by tools/source_track.py\n")
        out.write(f"# {a.material} in {a.region[0]} <= x <= {a.region[1]}, relative to ({a.origin[0]}, {a.origin[1]})\n")
        out.write("cdmpm_source_track 1\n")
        out.write(f"lattice {n[0]} {n[1]} {lo[0]:.6g} {lo[1]:.6g} {h:.6g}\n")
        out.write("fill " + " ".join(f"{v:.3g}" for v in fill) + "\n")
        out.write(f"times {len(records)}\n")
        for t, u in records:
            out.write(f"{t:.6g} " + " ".join(f"{v:.3f}" for v in u.ravel()) + "\n")
    print(f"{a.out}: lattice {n[0]} x {n[1]} at {h:g} m, {len(records)} records to t = {records[-1][0]:g} s; "
          f"source {area.sum():.0f} m^2, moved more than {h / 2:g} m: {area[moved].sum():.0f} m^2 per metre of width")


if __name__ == "__main__":
    main()
