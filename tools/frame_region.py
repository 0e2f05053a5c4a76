#!/usr/bin/python3
"""frame_region.py - statistics of the particles of one frame inside a box: how many, how many broken
(damage above a threshold), and the range of pressure, J and each Cauchy stress component. A quick look at
one place of a run without ParaView (for example the ice passing a support's edge).

    /usr/bin/python3 tools/frame_region.py OUT_DIR FRAME --box XMIN YMIN XMAX YMAX [--material N]
                                           [--damage 0.5] [--list]
FRAME is the frame number (particles_FRAME.vtu, or a distributed run's particles_FRAME.pvtu). --material keeps
one material index (order of the scene's "materials"). --list prints every particle (position, stress, J, damage)
sorted by height then x.
Stresses and pressure in kPa, tension positive; u and w the horizontal and vertical velocity [m/s].
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.frames import add_frame_arguments, frame_file, read_frame  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_frame_arguments(ap, material=False)
    ap.add_argument("--box", type=float, nargs=4, required=True, metavar=("XMIN", "YMIN", "XMAX", "YMAX"))
    ap.add_argument("--material", type=int)
    ap.add_argument("--damage", type=float, default=0.5, help="broken above this damage (default 0.5)")
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    path = frame_file(args.out, args.frame)
    if not os.path.exists(path):
        sys.exit(f"{path}: no such frame")
    pts, f = read_frame(path)
    x0, y0, x1, y1 = args.box
    sel = (pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    if args.material is not None:
        sel &= f["material"] == args.material
    idx = np.flatnonzero(sel)
    print(f"{path}: {idx.size} particles in [{x0:g}, {x1:g}] x [{y0:g}, {y1:g}]")
    if idx.size == 0:
        return
    if "damage" in f:
        print(f"  broken (damage > {args.damage:g}): {(f['damage'][idx] > args.damage).sum()}")
    S = f["stress"][idx] / 1e3 if "stress" in f else None
    rows = [("pressure", f["pressure"][idx] / 1e3), ("J", f["J"][idx]), ("u", f["velocity"][idx, 0]),
            ("w", f["velocity"][idx, 1])]
    if S is not None:
        rows += [("sigma_xx", S[:, 0]), ("sigma_yy", S[:, 4]), ("sigma_xy", S[:, 1])]
    for name, v in rows:
        print(f"  {name:9s} min {v.min():11.4f}  mean {v.mean():11.4f}  max {v.max():11.4f}")
    if args.list:
        for k in idx[np.lexsort((pts[idx, 0], pts[idx, 1]))]:
            s = f["stress"][k] / 1e3 if "stress" in f else np.zeros(9)
            d = f["damage"][k] if "damage" in f else 0.0
            print(f"  x={pts[k, 0]:10.3f} y={pts[k, 1]:9.3f} sxx={s[0]:9.1f} syy={s[4]:9.1f} sxy={s[1]:9.1f}"
                  f" J={f['J'][k]:.4f} damage={d:.2f}")


if __name__ == "__main__":
    main()
