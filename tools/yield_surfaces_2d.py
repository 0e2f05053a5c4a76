#!/usr/bin/python3
"""yield_surfaces_2d.py - the Cohesive Cam Clay yield surface of one set of ice parameters in the two 2D conventions
(docs/ice.md, "Two 2D conventions"), drawn in the plane of the in-plane principal stresses (sigma_1, sigma_2),
tension positive, no in-plane shear beyond them.

    /usr/bin/python3 tools/yield_surfaces_2d.py [--tensile-strength 0.83e6] [--friction-angle 37.9] [--beta 0.286]
                                                [--poissons-ratio 0.33] [--out FOLDER] [--force]

Both conventions take p0 from the same `tensile_strength` as the loader does (src/material/ice.h): the uniaxial
strength of the 3x3 state in plane strain, of the 2x2 state in the reference implementation's `cd_mpm`; and M from
the same friction angle, 6 sin(phi)/(3 - sin(phi)) and (8/sqrt(3)) sin(phi)/(3 - sin(phi)). The yield function is
y = (1 + 2 beta) q^2 + M^2 (p + beta p0)(p - p0) (material/cohesive_cam_clay.h); the state is elastic where y < 0.
  plane strain: sigma_zz = nu (sigma_1 + sigma_2) (the out-of-plane stress of an elastic plane-strain state), p and q
                of the 3x3 stress: p = -(s1 + s2 + szz)/3, q = sqrt(3/2) |dev sigma|;
  cd_mpm:       p = -(s1 + s2)/2, q = sqrt(2) |dev sigma| of the 2x2 stress.
Writes FOLDER/yield_surfaces_2d.png (default docs/validation/ice; a folder holding committed files needs --force)
and prints each surface's uniaxial tension, uniaxial compression and pure-shear strengths in the plane.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import REPO, add_output_arguments, output_folder  # noqa: E402
from cdmpm_tools.ice import uniaxial_strength  # noqa: E402
from cdmpm_tools.plotting import pyplot, save_figure  # noqa: E402

TOOL = "yield_surfaces_2d"


def convention(name, phi, beta, sigma_t):
    s = math.sin(math.radians(phi))
    if name == "plane_strain":
        M, n, qf = 6 * s / (3 - s), 3, 1.5
    else:
        M, n, qf = 8 / math.sqrt(3) * s / (3 - s), 2, 2.0
    p0 = sigma_t / float(uniaxial_strength(M, beta, n, qf, True))
    return M, p0


def yield_value(name, s1, s2, nu, M, beta, p0):
    if name == "plane_strain":
        sz = nu * (s1 + s2)
        mean = (s1 + s2 + sz) / 3
        q = np.sqrt(1.5 * ((s1 - mean) ** 2 + (s2 - mean) ** 2 + (sz - mean) ** 2))
        p = -mean
    else:
        mean = (s1 + s2) / 2
        q = np.sqrt(2 * ((s1 - mean) ** 2 + (s2 - mean) ** 2))
        p = -mean
    return (1 + 2 * beta) * q * q + M * M * (p + beta * p0) * (p - p0)


def along(name, direction, nu, M, beta, p0):
    """The stress magnitude at which the ray sigma = r * direction leaves the surface (bisection)."""
    lo, hi = 0.0, 100 * p0
    for _ in range(200):
        mid = (lo + hi) / 2
        (lo, hi) = (mid, hi) if yield_value(name, mid * direction[0], mid * direction[1], nu, M, beta, p0) < 0 else (lo, mid)
    return lo


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tensile-strength", type=float, default=0.825898e6, help="[Pa], the ice key tensile_strength")
    ap.add_argument("--friction-angle", type=float, default=37.93, help="[degrees]")
    ap.add_argument("--beta", type=float, default=0.2864)
    ap.add_argument("--poissons-ratio", type=float, default=0.3256)
    add_output_arguments(ap, "folder of the figure (default docs/validation/ice)")
    a = ap.parse_args()
    if not (a.tensile_strength > 0 and 0 < a.friction_angle < 90 and a.beta > 0 and 0 <= a.poissons_ratio < 0.5):
        print(f"{TOOL}: expected tensile strength > 0, friction angle in (0, 90), beta > 0, Poisson's ratio in [0, 0.5)",
              file=sys.stderr)
        sys.exit(2)
    out = output_folder(TOOL, a.out or os.path.join(REPO, "docs", "validation", "ice"), a.force)
    plt = pyplot(TOOL)
    fig, ax = plt.subplots(figsize=(6.2, 6))
    lo_hi = [0.0, 0.0]
    for name, colour in (("plane_strain", "tab:blue"), ("cd_mpm", "tab:red")):
        M, p0 = convention(name, a.friction_angle, a.beta, a.tensile_strength)
        ut = along(name, (1, 0), a.poissons_ratio, M, a.beta, p0)
        uc = along(name, (-1, 0), a.poissons_ratio, M, a.beta, p0)
        sh = along(name, (1, -1), a.poissons_ratio, M, a.beta, p0)
        print(f"{name}: M = {M:.4g}, p0 = {p0 / 1e6:.4g} MPa; in-plane uniaxial tension {ut / 1e6:.4g} MPa, "
              f"compression {uc / 1e6:.4g} MPa, shear (s1 = -s2) {sh / 1e6:.4g} MPa")
        theta = np.linspace(0, 2 * np.pi, 721)
        r = np.array([along(name, (math.cos(t), math.sin(t)), a.poissons_ratio, M, a.beta, p0) for t in theta])
        label = "plane strain (default)" if name == "plane_strain" else "cd_mpm (reference implementation)"
        x, y = r * np.cos(theta) / 1e6, r * np.sin(theta) / 1e6
        lo_hi = [min(lo_hi[0], x.min(), y.min()), max(lo_hi[1], x.max(), y.max())]
        ax.plot(x, y, color=colour,
                label=f"{label}: M = {M:.3g}, p0 = {p0 / 1e6:.3g} MPa")
    ax.axhline(0, color="0.7", lw=0.6)
    ax.axvline(0, color="0.7", lw=0.6)
    pad = 0.05 * (lo_hi[1] - lo_hi[0])
    ax.set_xlim(lo_hi[0] - pad, lo_hi[1] + pad)
    ax.set_ylim(lo_hi[0] - pad, lo_hi[1] + pad)
    ax.set_aspect("equal")
    ax.set_xlabel("in-plane principal stress sigma_1 [MPa] (tension +)")
    ax.set_ylabel("in-plane principal stress sigma_2 [MPa]")
    ax.set_title(f"tensile strength {a.tensile_strength / 1e6:.3g} MPa, friction angle {a.friction_angle:.3g} deg, "
                 f"beta {a.beta:.3g}", fontsize=9)
    ax.legend(fontsize=8, loc="lower left")
    print(save_figure(fig, os.path.join(out, "yield_surfaces_2d.png")))


if __name__ == "__main__":
    main()
