"""cdmpm_tools.ice - strengths of the Cohesive Cam Clay yield surface, as material/cohesive_cam_clay.h computes them.

  uniaxial_strength(M, beta, n, q_factor, tension)   uniaxial strength per unit p0 of the n x n state whose q^2 is
                                                     q_factor |dev sigma|^2 (3D and plane strain: n = 3, 1.5; the
                                                     reference 2D convention: n = 2, 2): the root of y(p, q) = 0 along
                                                     p = -+sigma/n (CohesiveCamClay::uniaxial_strength); numpy arrays
                                                     or numbers.
"""
import numpy as np


def uniaxial_strength(M, beta, n, q_factor, tension):
    t = (-1.0 if tension else 1.0) / n
    cq2 = q_factor * (n - 1) / n
    a = (1 + 2 * beta) * cq2 + M * M * t * t
    b = M * M * t * (beta - 1)
    c = -M * M * beta
    disc = np.sqrt(b * b - 4 * a * c)
    return np.where(b > 0, -2 * c / (b + disc), (-b + disc) / (2 * a))
