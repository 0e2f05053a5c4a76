#!/usr/bin/python3
"""plot_frames.py - render 2D particle frames to PNG: water in blue, ice coloured by damage (0 white-grey
intact, 1 red broken). For a quick look without ParaView.

    /usr/bin/python3 tools/plot_frames.py OUT_DIR [--frames 0 10 20] [--png OUT_DIR/frames.png]
With no --frames, six frames evenly spread over the run are drawn, one panel each.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu import read_pvd, read_vtu  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--frames", type=int, nargs="*")
    ap.add_argument("--png")
    args = ap.parse_args()
    frames = read_pvd(args.out)
    if not frames:
        sys.exit(f"{args.out}: no frames in particles.pvd")
    picks = args.frames if args.frames else sorted(set(np.linspace(0, len(frames) - 1, 6).astype(int)))
    fig, axes = plt.subplots(len(picks), 1, figsize=(12, 2.2 * len(picks)), squeeze=False)
    for ax, k in zip(axes[:, 0], picks):
        if not 0 <= k < len(frames):
            sys.exit(f"frame {k} does not exist (0..{len(frames) - 1})")
        t, name = frames[k]
        pts, f = read_vtu(os.path.join(args.out, name))
        mat = f["material"]
        damage = f.get("damage", np.zeros(len(pts)))
        ice = damage.size > 0 and "damage" in f
        water = ~np.isin(mat, np.unique(mat[damage > -1])) if False else None
        # Water: material ids whose particles carry no ice state are drawn blue (damage is 0 for them too),
        # so tell them apart by the pressure-only materials: ice ids are those with any nonzero alpha.
        alpha = f.get("alpha", np.zeros(len(pts)))
        ice_ids = np.unique(mat[alpha != 0]) if ice else []
        is_ice = np.isin(mat, ice_ids)
        s = max(0.5, 2e4 / len(pts))
        ax.scatter(pts[~is_ice, 0], pts[~is_ice, 1], s=s, c="#3a7bd5", linewidths=0)
        sc = ax.scatter(pts[is_ice, 0], pts[is_ice, 1], s=s, c=damage[is_ice], cmap="Reds", vmin=0, vmax=1,
                        linewidths=0)
        ax.set_aspect("equal")
        ax.set_title(f"t = {t:.3g} s", fontsize=9)
    fig.colorbar(sc, ax=axes[:, 0], label="ice damage", shrink=0.6)
    png = args.png or os.path.join(args.out, "frames.png")
    fig.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    main()
