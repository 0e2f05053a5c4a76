#!/usr/bin/python3
"""volume_fraction.py - how densely a frame's particles fill space: each particle's volume fraction psi on the
grid, the check for particles that pack closer than their J says (docs/water.md, "Packing").

    /usr/bin/python3 tools/volume_fraction.py OUT_DIR FRAME [--material water] [--box XMIN YMIN XMAX YMAX]
                                              [--png FILE]

FRAME is the frame number: OUT_DIR/particles_FRAME.vtu, or a distributed run's particles_FRAME.pvtu.
The particles' reference volumes V0 = volume / J (all materials) are spread to the grid nodes with the quadratic
B-spline weights w_ip of the run (dx from OUT_DIR/scene.resolved.json), psi_i = sum_p w_ip V0_p / dx^dim, and read
back at each particle of the chosen material, psi_p = sum_i w_ip psi_i (the scatter and gather of p2g and g2p).
psi J is the volume fraction the particles claim (their volumes V0 J). A particle's J says how much volume it
should fill, so psi J > 1 is packing: the particles are closer than the pressure, a function of J alone, can see.
Particles seeded on the lattice at 2^dim per cell have psi J = 1 inside the water (a pre-stressed particle's V0 is
its seeded volume over J: sim/seeding.cpp). The faces of slip `walls` are mirrors (the particles are reflected
across them, as boundary_fold does), so psi J = 1 holds up to those walls; other boundaries are not mirrored, and
psi J falls below 1 within about two cells of them and of the free surface.

Prints, for the chosen material (inside --box if given): the particle count, mean and 5/50/95 % points and largest
of psi, J and psi J, and the share of particles with psi J above 1.02 and 1.10. --png draws psi J and J.
Not part of the tests.
"""
import argparse
import itertools
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import fail  # noqa: E402
from cdmpm_tools.frames import add_frame_arguments, first_piece, frame_file, read_field_data, read_frame  # noqa: E402
from cdmpm_tools.io import read_scene  # noqa: E402
from cdmpm_tools.plotting import pyplot, save_figure  # noqa: E402

TOOL = "volume_fraction"


def bspline(u):
    """Base node and the three quadratic B-spline weights of coordinates u (in cells), as p2g uses them."""
    base = np.floor(u - 0.5).astype(np.int64)
    f = u - base
    return base, (0.5 * (1.5 - f) ** 2, 0.75 - (f - 1.0) ** 2, 0.5 * (f - 0.5) ** 2)


def mirrored(x, v0, size, faces, dx):
    """x and v0 with the particles within 3 cells of each mirror face reflected across it (corners too)."""
    for face in faces:
        axis, high = "xyz".index(face[0]), face[1] == "+"
        near = x[:, axis] > size[axis] - 3 * dx if high else x[:, axis] < 3 * dx
        image = x[near].copy()
        image[:, axis] = 2 * size[axis] - image[:, axis] if high else -image[:, axis]
        x, v0 = np.concatenate([x, image]), np.concatenate([v0, v0[near]])
    return x, v0


def volume_fraction(x, v0, at, size, faces, dx):
    """psi at the points `at`: the spread of the volumes v0 at x (mirrored at `faces`), read back at `at`."""
    dim = x.shape[1]
    xs, vs = mirrored(x, v0, size, faces, dx)
    lo = -4
    shape = tuple(int(np.ceil(s / dx)) + 9 for s in size)
    grid = np.zeros(shape)
    base, w = zip(*(bspline(xs[:, a] / dx) for a in range(dim)))
    for o in itertools.product(range(3), repeat=dim):
        idx = tuple(base[a] + o[a] - lo for a in range(dim))
        keep = np.all([(i >= 0) & (i < n) for i, n in zip(idx, shape)], axis=0)
        wt = np.prod([w[a][o[a]] for a in range(dim)], axis=0)
        np.add.at(grid, tuple(i[keep] for i in idx), (wt * vs)[keep])
    grid /= dx ** dim
    base, w = zip(*(bspline(at[:, a] / dx) for a in range(dim)))
    psi = np.zeros(len(at))
    for o in itertools.product(range(3), repeat=dim):
        idx = tuple(np.clip(base[a] + o[a] - lo, 0, shape[a] - 1) for a in range(dim))
        psi += np.prod([w[a][o[a]] for a in range(dim)], axis=0) * grid[idx]
    return psi


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_frame_arguments(ap, material=False)
    ap.add_argument("--material", default="water", help="the material's name (default water)")
    ap.add_argument("--box", type=float, nargs="+", metavar="X", help="XMIN YMIN [ZMIN] XMAX YMAX [ZMAX]")
    ap.add_argument("--png", help="draw psi J and J of the material's particles (2D runs)")
    args = ap.parse_args()

    frame = frame_file(args.out, args.frame)
    scene_path = os.path.join(args.out, "scene.resolved.json")
    for p in (frame, scene_path):
        if not os.path.isfile(p):
            fail(TOOL, f"{p}: no such file")
    scene = read_scene(args.out)
    dim, dx, size = scene["dim"], scene["domain"]["dx"], scene["domain"]["size"]
    all_faces = [a + side for a in "xyz"[:dim] for side in "-+"]  # walls.cpp: faces default to all of them
    faces = sorted({f for b in scene.get("boundaries", []) if b.get("type") == "walls" and b.get("condition") == "slip"
                    for f in b.get("faces", all_faces)})
    if args.png and dim != 2:
        fail(TOOL, "--png draws 2D runs only")
    points, fields = read_frame(frame)
    meta = read_field_data(first_piece(frame))
    names = meta.get("material_names", [])
    if args.material not in names:
        fail(TOOL, f"{frame}: no material '{args.material}' (the frame has {', '.join(names) or 'none'})")
    of_material = fields["material"] == names.index(args.material)
    x = points[:, :dim].astype(np.float64)
    J = fields["J"].astype(np.float64)
    v0 = fields["volume"].astype(np.float64) / J
    mine = of_material.copy()
    if args.box:
        if len(args.box) != 2 * dim:
            fail(TOOL, f"--box takes {2 * dim} numbers in {dim}D, got {len(args.box)}")
        lo, hi = np.array(args.box[:dim]), np.array(args.box[dim:])
        mine &= np.all((x >= lo) & (x <= hi), axis=1)
    if not mine.any():
        fail(TOOL, f"{frame}: no particle of '{args.material}'" + (" in the box" if args.box else ""))
    psi = volume_fraction(x, v0, x[mine], size, faces, dx)
    j = J[mine]
    print(f"{frame}: {mine.sum()} particles of '{args.material}'"
          f"{' in the box' if args.box else ''}; mirrors at {', '.join(faces) or 'no face'}")
    print(f"{'':8}{'mean':>8}{'5 %':>8}{'50 %':>8}{'95 %':>8}{'largest':>9}")
    for name, v in (("psi", psi), ("J", j), ("psi J", psi * j)):
        q = np.percentile(v, [5, 50, 95])
        print(f"{name:8}{v.mean():8.4f}{q[0]:8.4f}{q[1]:8.4f}{q[2]:8.4f}{v.max():9.4f}")
    for limit in (1.02, 1.10):
        print(f"psi J > {limit:.2f}: {100 * np.mean(psi * j > limit):.1f} % of the particles")
    if args.png:
        plt = pyplot(TOOL)
        fig, ax = plt.subplots(2, 1, figsize=(10, 10))
        for a, v, lim, title in ((ax[0], psi * j, (0.85, 1.15), "claimed volume fraction psi J"), (ax[1], j, (0.97, 1.03), "J")):
            sc = a.scatter(x[mine, 0], x[mine, 1], c=v, s=0.5, vmin=lim[0], vmax=lim[1], cmap="coolwarm")
            a.scatter(x[~of_material, 0], x[~of_material, 1], s=0.5, c="k")
            a.set_aspect("equal")
            a.set_title(f"{title}, t = {meta['TimeValue'][0]:g} s")
            fig.colorbar(sc, ax=a)
        print(f"wrote {save_figure(fig, args.png, dpi=90, tight=False)}")


if __name__ == "__main__":
    main()
