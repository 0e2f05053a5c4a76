#!/usr/bin/python3
"""cliff_stress.py - how close a 2D ice cliff is to calving, from one frame: the largest principal (tensile)
stress sigma_1 of the ice in bands of distance behind the front, with where it sits and how many particles are
broken there, and the deepest broken particle below the ice surface (the depth a crack has reached).

    /usr/bin/python3 tools/cliff_stress.py OUT_DIR FRAME [--material 0] [--damage 0.5]
                                           [--bands 0 40 80 120 160 200 300 500 900]

sigma_1 = (s_xx + s_yy)/2 + sqrt(((s_xx - s_yy)/2)^2 + s_xy^2) from the frame's Cauchy stress (tension
positive), in kPa. The front is the largest x of the ice and the surface its largest y (a flat-topped glacier
flowing towards +x, as scenes/eqip_sermia_2d.json). docs/eqip_sermia.md uses it to compare the settled state with
the crevasse-depth criterion.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_style import add_frame_arguments, read_material_frame  # noqa: E402


def principal_tension(stress):
    """Largest in-plane principal stress of 9-component (row-major) Cauchy stresses."""
    sxx, sxy, syy = stress[:, 0], stress[:, 1], stress[:, 4]
    return 0.5 * (sxx + syy) + np.sqrt((0.5 * (sxx - syy)) ** 2 + sxy ** 2)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_frame_arguments(ap)
    ap.add_argument("--damage", type=float, default=0.5, help="broken above this damage (default 0.5)")
    ap.add_argument("--bands", type=float, nargs="+", default=[0, 40, 80, 120, 160, 200, 300, 500, 900],
                    help="band edges, metres behind the front (ascending)")
    args = ap.parse_args()
    path, pts, f = read_material_frame("cliff_stress", args.out, args.frame, args.material, ("stress", "damage"))
    x, y = pts[:, 0], pts[:, 1]
    s1 = principal_tension(f["stress"]) / 1e3
    broken = np.nan_to_num(f["damage"]) > args.damage
    front, top = x.max(), y.max()
    behind = front - x
    print(f"{path}: {len(x)} ice particles, front at x = {front:.1f} m, surface at y = {top:.1f} m")
    for lo, hi in zip(args.bands[:-1], args.bands[1:]):
        k = (behind >= lo) & (behind < hi)
        if not k.any():
            continue
        i = np.flatnonzero(k)[np.argmax(s1[k])]
        print(f"  {lo:5.0f}-{hi:5.0f} m behind the front: sigma_1 max {s1[i]:8.1f} kPa at x = {x[i]:7.1f}, "
              f"y = {y[i]:6.1f} m; broken {np.sum(k & broken)}")
    if broken.any():
        i = np.flatnonzero(broken)[np.argmin(y[broken])]
        print(f"  broken: {broken.sum()}; deepest {top - y[i]:.1f} m below the surface, {behind[i]:.1f} m behind "
              f"the front")
    else:
        print("  broken: 0")


if __name__ == "__main__":
    main()
