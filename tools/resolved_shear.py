#!/usr/bin/python3
"""resolved_shear.py - can a 2D ice cliff fail in shear along an inclined plane, from one frame: the largest shear
stress resolved on planes dipping at given angles towards the face, in the ice above a level within a distance of
the front, beside the smallest pure-shear strength Cohesive Cam Clay has within the laboratory ranges.

    /usr/bin/python3 tools/resolved_shear.py OUT_DIR FRAME [--material 0] [--above 150] [--within 100]
                                             [--dips 45 52.5 60] [--ranges PATH]

A plane dipping theta towards +x (the face of a glacier flowing towards +x, as scenes/eqip_sermia_2d.json) has the
unit normal n = (sin theta, cos theta); its traction t = sigma n has the normal part t.n (tension positive) and the
shear part |t x n|, from the frame's Cauchy stress. Also printed: the largest in-plane shear stress
sqrt(((s_xx - s_yy)/2)^2 + s_xy^2) in the same ice. The strength: tau_s = M p0 sqrt(beta / (3 (1 + 2 beta)))
(CohesiveCamClay::shear_strength) with p0 the smallest that gives sigma_t and sigma_c (2D uniaxial strengths,
tools/shear_regime.py) at least the ranges' lower bounds and at most their upper bounds, minimised over
M in [1e-3, 30] and beta in [1e-9, 10] (the infimum is approached as beta -> 0). docs/eqip_sermia.md#what-the-observed-width-and-dip-imply uses it.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import fail  # noqa: E402
from cdmpm_tools.frames import add_frame_arguments, read_material_frame  # noqa: E402
from shear_regime import RANGES, laboratory_ranges, shear, uniaxial  # noqa: E402


def smallest_shear_strength(st_lo, st_hi, sc_lo, sc_hi):
    """Smallest tau_s [Pa] of 2D Cohesive Cam Clay with sigma_t in [st_lo, st_hi] and sigma_c in [sc_lo, sc_hi]."""
    M, beta = np.meshgrid(np.geomspace(1e-3, 30, 400), np.geomspace(1e-9, 10, 400))
    st, sc = uniaxial(M, beta, 2, True), uniaxial(M, beta, 2, False)
    p0 = np.maximum(st_lo / st, sc_lo / sc)
    ok = (p0 * st <= st_hi * 1.0001) & (p0 * sc <= sc_hi * 1.0001)
    tau = np.where(ok, p0 * shear(M, beta), np.inf)
    k = np.unravel_index(np.argmin(tau), tau.shape)
    return tau[k], M[k], beta[k]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_frame_arguments(ap)
    ap.add_argument("--above", type=float, default=150.0, help="only ice above this elevation [m] (sea level)")
    ap.add_argument("--within", type=float, default=100.0, help="only ice within this distance of the front [m]")
    ap.add_argument("--dips", type=float, nargs="+", default=[45.0, 52.5, 60.0], help="plane dips [degrees]")
    ap.add_argument("--ranges", default=RANGES)
    a = ap.parse_args()
    path, pts, d = read_material_frame("resolved_shear", a.out, a.frame, a.material)
    x, y, s = pts[:, 0], pts[:, 1], d["stress"]
    front = x.max()
    sel = (x > front - a.within) & (y > a.above)
    if not sel.any():
        fail("resolved_shear", f"{path}: no ice above {a.above:g} m within {a.within:g} m of the front")
    sxx, sxy, syy = s[:, 0], s[:, 1], s[:, 4]
    print(f"{path}: front at x = {front:.1f} m; {int(sel.sum())} ice particles above {a.above:g} m within "
          f"{a.within:g} m of it")
    tau = np.sqrt((0.5 * (sxx - syy)) ** 2 + sxy ** 2)
    i = np.argmax(np.where(sel, tau, -1))
    print(f"  largest in-plane shear stress {tau[i] / 1e6:.3f} MPa, {front - x[i]:.0f} m behind the front, "
          f"{y[i] - a.above:.0f} m above {a.above:g} m")
    for dip in a.dips:
        t = np.radians(dip)
        nx, ny = np.sin(t), np.cos(t)
        tx, ty = sxx * nx + sxy * ny, sxy * nx + syy * ny
        normal, along = tx * nx + ty * ny, np.abs(ty * nx - tx * ny)
        j = np.argmax(np.where(sel, along, -1))
        print(f"  planes dipping {dip:g} deg: largest resolved shear {along[j] / 1e6:.3f} MPa (normal stress "
              f"{normal[j] / 1e6:.3f} MPa, tension positive), {front - x[j]:.0f} m behind the front")
    _, (st_lo, st_hi), (sc_lo, sc_hi) = laboratory_ranges(a.ranges)
    tau_s, M, beta = smallest_shear_strength(st_lo, st_hi, sc_lo, sc_hi)
    print(f"smallest pure-shear strength in the laboratory ranges (sigma_t {st_lo / 1e6:g}-{st_hi / 1e6:g} MPa, "
          f"sigma_c {sc_lo / 1e6:g}-{sc_hi / 1e6:g} MPa; 2D): tau_s = {tau_s / 1e6:.3f} MPa at M = {M:.3f}, "
          f"beta = {beta:.2e}")


if __name__ == "__main__":
    main()
