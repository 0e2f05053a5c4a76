#!/usr/bin/python3
"""shear_regime.py - can Cohesive Cam Clay make the sliding block break in shear within the laboratory ranges?

The strengths of the yield surface (src/material/cohesive_cam_clay.h; q = sqrt(3/2)|dev tau|, in 2D of the in-plane
deviator), per unit p0:
    uniaxial tension / compression sigma_t, sigma_c: the root of y(p, q) = 0 along p = -+sigma/d,
        q = sqrt(3/2 (d - 1)/d) sigma (uniaxial_strength);
    pure shear tau_s = M p0 sqrt(beta / (3 (1 + 2 beta)))  (shear_strength; p = 0, q = sqrt(3) tau).
The overhang of length L on a support carries the shear force V = rho_i g (H - D) L (buoyancy at rho_i, as in the
shear model) and the moment of the cantilever with buoyancy; it breaks in
    shear   at L_s / H = 2 tau_s / [3 rho_i g H (1 - D/H)]                 (largest shear stress 3 V / (2 H)),
    bending at L_b / H = sqrt(sigma_t / (3 g (rho_i H - rho_w D)))          (top-fibre stress 6 M / H^2),
and shear governs where L_s < L_b. With s = sigma_t / (rho_i g H) and r = tau_s / sigma_t that is
    r < (3/2) f(D/H) / sqrt(3 s),  f(d) = (1 - d) / sqrt(1 - (rho_w / rho_i) d),
so the smallest reachable r decides. The laboratory ranges (../shared/data/ice_and_water.json) bound
sigma_c / sigma_t from below by 5 MPa / 3.1 MPa = 1.61, which bounds r from below.

    /usr/bin/python3 tools/shear_regime.py [--dim 2] [--ranges PATH] [--M M --beta B --tensile S --H H]
Prints the smallest r over (M, beta) for a set of sigma_c / sigma_t, the height H above which shear governs for
every D/H <= 0.6 with it and the slab's lithostatic stress at its base, rho_i g H, over sigma_c at that height;
and, for one (M, beta, sigma_t, H), sigma_c, tau_s and both lengths at D/H = 0 .. 0.8.
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import REPO  # noqa: E402
from cdmpm_tools.ice import uniaxial_strength  # noqa: E402

RANGES = os.path.join(REPO, "..", "shared", "data", "ice_and_water.json")
G = 9.81


def uniaxial(M, beta, dim, tension):
    """Uniaxial strength per unit p0 (CohesiveCamClay::uniaxial_strength)."""
    return uniaxial_strength(M, beta, dim, 1.5, tension)


def shear(M, beta):
    """Pure-shear strength per unit p0 (CohesiveCamClay::shear_strength)."""
    return M * np.sqrt(beta / (3 * (1 + 2 * beta)))


def laboratory_ranges(path=RANGES):
    """(ice density, (sigma_t lo, hi), (sigma_c lo, hi)) from PATH, or the same numbers without the file."""
    if not os.path.exists(path):
        return 917.0, (0.7e6, 3.1e6), (5e6, 25e6)
    r = json.load(open(path))
    return r["ice_density_kg_m3"], tuple(r["ice_tensile_strength_Pa"]), tuple(r["ice_compressive_strength_Pa"])


def lengths(sigma_t, tau_s, H, d, rho_i, rho_w):
    """(L_s / H, L_b / H): where the overhang breaks in shear and in bending."""
    L_s = 2 * tau_s / (3 * rho_i * G * H * (1 - d))
    L_b = math.sqrt(sigma_t / (3 * G * (rho_i * H - rho_w * d * H)))
    return L_s, L_b


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dim", type=int, default=2)
    ap.add_argument("--ranges", default=RANGES)
    ap.add_argument("--M", type=float, default=0.33)
    ap.add_argument("--beta", type=float, default=0.1)
    ap.add_argument("--tensile", type=float, default=3.1e6, help="sigma_t [Pa]")
    ap.add_argument("--H", type=float, default=500.0, help="slab height [m]")
    ap.add_argument("--water-density", type=float, default=1000.0, help="the scene's water (sliding_block_2d: 1000)")
    a = ap.parse_args()
    rho_w = a.water_density
    rho_i, (st_lo, st_hi), (sc_lo, sc_hi) = laboratory_ranges(a.ranges)
    c_min, c_max = sc_lo / st_hi, sc_hi / st_lo
    f = lambda d: (1 - d) / math.sqrt(1 - rho_w / rho_i * d)
    f_min = min(f(0.6 * i / 100) for i in range(101))  # shear must govern for every D/H <= 0.6
    print(f"{a.dim}D; laboratory ranges: sigma_t {st_lo / 1e6:g}-{st_hi / 1e6:g} MPa, sigma_c {sc_lo / 1e6:g}-"
          f"{sc_hi / 1e6:g} MPa, so sigma_c / sigma_t in [{c_min:.3f}, {c_max:.1f}]")
    Ms = np.geomspace(1e-3, 30, 700)[:, None]
    bs = np.geomspace(1e-4, 100, 700)[None, :]
    st = uniaxial(Ms, bs, a.dim, True)
    ratio_c = uniaxial(Ms, bs, a.dim, False) / st
    ratio_r = shear(Ms, bs) / st
    print("sigma_c/sigma_t | smallest tau_s/sigma_t (M, beta) | s = sigma_t/(rho_i g H) below which shear governs"
          " for all D/H <= 0.6 | H above which (sigma_t = 3.1 MPa) [m] | the slab's weight at its base rho_i g H over"
          " sigma_c there")
    for c in [c_min, 2, 3, 5, 10, c_max]:
        mask = np.abs(ratio_c / c - 1) < 0.01
        k = np.argmin(np.where(mask, ratio_r, np.inf))
        i, j = np.unravel_index(k, ratio_r.shape)
        rmin = ratio_r[i, j]
        s_max = (1.5 * f_min / rmin) ** 2 / 3
        print(f"  {c:6.3f} | {rmin:.3f} (M {Ms[i, 0]:.3g}, beta {bs[0, j]:.3g}) | {s_max:.3f} |"
              f" {st_hi / (rho_i * G * s_max):.0f} | {1 / (s_max * c):.2f}")
    M, beta = a.M, a.beta
    per_p0 = float(uniaxial(M, beta, a.dim, True))
    p0 = a.tensile / per_p0
    sigma_c = float(uniaxial(M, beta, a.dim, False)) * p0
    tau_s = float(shear(M, beta)) * p0
    s = a.tensile / (rho_i * G * a.H)
    print(f"M = {M:g}, beta = {beta:g}, sigma_t = {a.tensile / 1e6:g} MPa: p0 = {p0 / 1e6:.3f} MPa, sigma_c ="
          f" {sigma_c / 1e6:.3f} MPa, tau_s = {tau_s / 1e6:.3f} MPa, tau_s/sigma_t = {tau_s / a.tensile:.3f};"
          f" H = {a.H:g} m, s = {s:.3f}, rho_i g H / sigma_c = {rho_i * G * a.H / sigma_c:.2f}")
    for d in (0, 0.2, 0.4, 0.6, 0.8):
        L_s, L_b = lengths(a.tensile, tau_s, a.H, d, rho_i, rho_w)
        print(f"  D/H = {d:.1f}: shear L/H = {L_s:.3f}, bending L/H = {L_b:.3f}: {'shear' if L_s < L_b else 'bending'}"
              f" governs (H/(2 L_b) = {1 / (2 * L_b):.3f})")


if __name__ == "__main__":
    main()
