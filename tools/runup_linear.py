#!/usr/bin/python3
"""runup_linear.py - the linear-theory run-up of a solitary wave on a plane beach, exact and asymptotic.

Synolakis (1987, J. Fluid Mech. 185, 523) solves the linear shallow-water equations for a wave that crosses a
flat bottom of depth d onto a plane beach of slope 1 : cot(beta), toe at L = d cot(beta) from the still
shoreline. The shoreline elevation is
    R(t) = (2 / pi) Re int_0^inf Phi(k) exp(-i k c t) / (J0(2 k L) - i J1(2 k L)) dk,
Phi(k) the Fourier transform of the incident wave, here H sech^2(gamma x / d), gamma = sqrt(3 H / (4 d)):
Phi(k) = H pi k (d / gamma)^2 / sinh(pi k d / (2 gamma)). For 2 k L >> 1 the kernel tends to
sqrt(pi k L) exp(i (2 k L - pi / 4)) and the largest R to the run-up law R/d = 2.831 sqrt(cot beta) (H/d)^(5/4).
The incident wave's spectrum is centred on k d ~ gamma, so the law needs 2 gamma cot(beta) >> 1, i.e.
sqrt(H/d) >> 0.58 tan(beta). This tool prints both, with the law, for each (H/d, cot beta) given, so that a
run-up measured where that condition does not hold can be set beside the exact linear value.

    /usr/bin/python3 tools/runup_linear.py 0.1:2.5 0.045:5
J0 and J1 come from their integral representations (numpy only).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import fail  # noqa: E402


def bessel_j(n, z):
    """J_n(z) = (1/pi) int_0^pi cos(n theta - z sin theta) d theta, by the trapezoid rule on 2001 points."""
    theta = np.linspace(0.0, np.pi, 2001)
    f = np.cos(n * theta[None, :] - np.asarray(z)[:, None] * np.sin(theta[None, :]))
    return np.trapz(f, theta, axis=1) / np.pi


def runup(h_over_d, cot_beta):
    """(exact linear, asymptotic linear, law) largest shoreline elevation over d."""
    gamma = np.sqrt(0.75 * h_over_d)
    k = np.linspace(1e-6, 40 * gamma, 3000)
    phi = h_over_d * np.pi * k / gamma ** 2 / np.sinh(np.pi * k / (2 * gamma))
    z = 2 * k * cot_beta
    exact = 1 / (bessel_j(0, z) - 1j * bessel_j(1, z))
    asymptotic = np.sqrt(np.pi * k * cot_beta) * np.exp(1j * (z - np.pi / 4))
    t = np.linspace(-80, 80, 2001)
    phase = np.exp(-1j * np.outer(t, k))
    dk = k[1] - k[0]
    r = [(phase @ (phi * g)).real.max() * dk * 2 / np.pi for g in (exact, asymptotic)]
    return r[0], r[1], 2.831 * np.sqrt(cot_beta) * h_over_d ** 1.25


def main():
    cases = []
    for case in sys.argv[1:] or ["0.1:2.5"]:
        try:
            h, c = (float(v) for v in case.split(":"))
        except ValueError:
            fail("runup_linear", f"expected H_over_d:cot_beta, got {case!r}")
        if not (0 < h < 1 and c > 0):
            fail("runup_linear", f"expected 0 < H/d < 1 and cot beta > 0, got {case!r}")
        cases.append((h, c))
    print("H/d, cot beta, 2 gamma cot beta, R/d exact linear, R/d asymptotic linear, R/d law (2.831 ...), exact/law")
    for h, c in cases:
        e, a, law = runup(h, c)
        print(f"{h:g}, {c:g}, {2 * np.sqrt(0.75 * h) * c:.2f}, {e:.4f}, {a:.4f}, {law:.4f}, {e / law:.3f}")


if __name__ == "__main__":
    main()
