#!/usr/bin/python3
"""plot_frames.py - render 2D particle frames to PNG: water in blue, ice coloured by damage (slate grey intact,
amber, dark red broken), axes in metres. For a quick look without ParaView.

    /usr/bin/python3 tools/plot_frames.py RUN_DIR [--frames 0 10 20] [--out FOLDER]
With no --frames, six frames evenly spread over the run are drawn, one panel each. The figure goes to
FOLDER/frames.png (default: RUN_DIR/plots); a folder holding committed files is refused (--force overrides).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_style import WATER, fail, ice_colormap, ice_mask, output_folder  # noqa: E402

TOOL = "plot_frames"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="a cdmpm run folder (with particles.pvd)")
    ap.add_argument("--frames", type=int, nargs="*", help="frame indices to draw")
    ap.add_argument("--out", help="folder for frames.png (default: RUN/plots)")
    ap.add_argument("--force", action="store_true", help="allow a folder with committed files")
    args = ap.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
        from vtu import read_field_data, read_pvd, read_vtu
    except ImportError as e:
        fail(TOOL, f"needs numpy and matplotlib (Debian's /usr/bin/python3 with python3-matplotlib): {e}")
    if not os.path.isfile(os.path.join(args.run, "particles.pvd")):
        fail(TOOL, f"{args.run}: no particles.pvd (not a cdmpm run folder, or a run without frames)")
    frames = read_pvd(args.run)
    if not frames:
        fail(TOOL, f"{args.run}: no frames in particles.pvd")
    picks = args.frames if args.frames else sorted(set(np.linspace(0, len(frames) - 1, 6).astype(int)))
    bad = [k for k in picks if not 0 <= k < len(frames)]
    if bad:
        fail(TOOL, f"frame {bad[0]} does not exist (0..{len(frames) - 1})")
    folder = output_folder(TOOL, args.out or os.path.join(args.run, "plots"), args.force)
    first = read_vtu(os.path.join(args.run, frames[picks[0]][1]))[0]
    span = np.ptp(first[:, 0]) / max(np.ptp(first[:, 1]), 1e-30)
    fig, axes = plt.subplots(len(picks), 1, figsize=(11, 0.6 + max(1.6, min(10.0 / span, 4.0)) * len(picks)), squeeze=False,
                             layout="constrained")
    cmap, sc = ice_colormap(), None
    for ax, k in zip(axes[:, 0], picks):
        t, name = frames[k]
        path = os.path.join(args.run, name)
        try:
            pts, f = read_vtu(path)
            meta = read_field_data(path)
        except (OSError, ValueError) as e:
            fail(TOOL, f"{path}: cannot read the frame: {e}")
        ice = ice_mask(f, meta, len(pts))
        s = max(0.5, 2e4 / len(pts))
        ax.scatter(pts[~ice, 0], pts[~ice, 1], s=s, c=WATER, linewidths=0, label="water")
        if ice.any():
            sc = ax.scatter(pts[ice, 0], pts[ice, 1], s=s, c=f["damage"][ice], cmap=cmap, vmin=0, vmax=1,
                            linewidths=0)
        ax.set_aspect("equal")
        ax.set_ylabel("z [m]")
        ax.set_title(f"t = {t:.3g} s", fontsize=9)
    axes[-1, 0].set_xlabel("x [m]")
    if sc is not None:
        fig.colorbar(sc, ax=axes[:, 0], label="ice damage [-] (0 intact, 1 broken)", shrink=0.6)
    png = os.path.join(folder, "frames.png")
    fig.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    main()
