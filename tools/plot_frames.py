#!/usr/bin/python3
"""plot_frames.py - render 2D particle frames to PNG: water in blue, ice coloured by damage (slate grey intact,
amber, dark red broken), axes in metres. For a quick look without ParaView.

    /usr/bin/python3 tools/plot_frames.py RUN_DIR [--frames 0 10 20] [--field pressure] [--out FOLDER]
With --field, every particle is coloured by that frame field instead (a vector by its magnitude) over its 1st to
99th percentile, so a few extreme particles do not set the range. With no --frames, six frames evenly spread over the run are drawn, one panel each. The figure goes to
FOLDER/frames.png (default: RUN_DIR/plots); a folder holding committed files is refused (--force overrides).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import add_output_arguments, fail, output_folder  # noqa: E402
from cdmpm_tools.frames import read_field_data, read_pvd, read_vtu  # noqa: E402
from cdmpm_tools.plotting import WATER, ice_colormap, ice_mask, pyplot, robust_range, save_figure  # noqa: E402

TOOL = "plot_frames"
UNITS = {"pressure": "Pa", "velocity": "m/s", "J": "-", "damage": "-", "alpha": "-", "p0": "Pa", "mass": "kg",
         "volume": "m^2 (2D)", "stress": "Pa"}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="a cdmpm run folder (with particles.pvd)")
    ap.add_argument("--frames", type=int, nargs="*", help="frame indices to draw")
    ap.add_argument("--field", help="colour all particles by this frame field (e.g. pressure, velocity, J)")
    add_output_arguments(ap, "folder for frames.png (default: RUN/plots)")
    args = ap.parse_args()
    plt = pyplot(TOOL)
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
    loaded = []
    for k in picks:
        path = os.path.join(args.run, frames[k][1])
        try:
            loaded.append((frames[k][0], path, *read_vtu(path), read_field_data(path)))
        except (OSError, ValueError) as e:
            fail(TOOL, f"{path}: cannot read the frame: {e}")
    if args.field:
        missing = [p for _, p, _, f, _ in loaded if args.field not in f]
        if missing:
            fail(TOOL, f"{missing[0]}: no field {args.field} (has: {', '.join(sorted(loaded[0][3]))})")

        def values(f, n):
            v = np.asarray(f[args.field], dtype=float).reshape(n, -1)
            return v[:, 0] if v.shape[1] == 1 else np.linalg.norm(v, axis=1)

        lo, hi = robust_range(np.concatenate([values(f, len(p)) for _, _, p, f, _ in loaded]))
    first = loaded[0][2]
    span = np.ptp(first[:, 0]) / max(np.ptp(first[:, 1]), 1e-30)
    fig, axes = plt.subplots(len(picks), 1, figsize=(11, 0.6 + max(1.6, min(10.0 / span, 4.0)) * len(picks)), squeeze=False,
                             layout="constrained")
    cmap, sc = ice_colormap(), None
    for ax, (t, path, pts, f, meta) in zip(axes[:, 0], loaded):
        ice = ice_mask(f, meta, len(pts))
        s = max(0.5, 2e4 / len(pts))
        if args.field:
            sc = ax.scatter(pts[:, 0], pts[:, 1], s=s, c=values(f, len(pts)), cmap="viridis", vmin=lo, vmax=hi, linewidths=0)
            ax.set_aspect("equal")
            ax.set_ylabel("z [m]")
            ax.set_title(f"t = {t:.3g} s, {args.field} (1st-99th percentile range)", fontsize=9)
            continue
        ax.scatter(pts[~ice, 0], pts[~ice, 1], s=s, c=WATER, linewidths=0, label="water")
        if ice.any():
            sc = ax.scatter(pts[ice, 0], pts[ice, 1], s=s, c=f["damage"][ice], cmap=cmap, vmin=0, vmax=1,
                            linewidths=0)
        ax.set_aspect("equal")
        ax.set_ylabel("z [m]")
        ax.set_title(f"t = {t:.3g} s", fontsize=9)
    axes[-1, 0].set_xlabel("x [m]")
    if sc is not None:
        label = (f"{args.field} [{UNITS.get(args.field, '?')}]" if args.field else "ice damage [-] (0 intact, 1 broken)")
        fig.colorbar(sc, ax=axes[:, 0], label=label, shrink=0.6)
    print(save_figure(fig, os.path.join(folder, f"frames_{args.field}.png" if args.field else "frames.png"), dpi=110))


if __name__ == "__main__":
    main()
