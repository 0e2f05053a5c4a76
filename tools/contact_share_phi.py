"""contact_share_phi.py - the part of a flat face's water pressure force that a contact share passes to the body,
as a function of where the face lies between two grid planes (docs/changelog.md, "The stall").

A half-space of water at pressure p against a flat face pushes the grid node at signed distance d from the face
(d > 0 outside the body, in cells) with the force p w(d), w the quadratic B-spline; the nodes' forces sum to p.
The contact (sim/rigid_contact.h, sim/field_contact.h) passes a node's force to the body in proportion to its
share c, a function of the node's body mass fraction f(d) (the B-spline integrated over the body's side). So the
body receives Phi(s) = sum_k c(f(k - s)) w(k - s) of the force, s the face's offset from a grid plane (0 to 1).

    python3 tools/contact_share_phi.py [--steps 10]

Prints Phi(s) for the shipped share (linear in f from 0.05 to 0.2) and for three shares that make Phi the same
at every offset (gamma = 1 - Phi = 1/8, 1/32 and 0: full contact at every node the body reaches). Not part of
the tests.
"""
import argparse


def w(x):
    x = abs(x)
    if x < 0.5:
        return 0.75 - x * x
    if x < 1.5:
        return 0.5 * (1.5 - x) ** 2
    return 0.0


def fraction(d):
    """Body mass fraction of a node at distance d outside a flat face (inside: d < 0)."""
    if d <= -1.5:
        return 1.0
    if d >= 1.5:
        return 0.0
    if d >= 0.5:
        return (1.5 - d) ** 3 / 6.0
    if d >= -0.5:
        return 0.5 - (0.75 * d - d ** 3 / 3.0)
    return 1.0 - (1.5 + d) ** 3 / 6.0


def shipped(d):
    return min(max((fraction(d) - 0.05) / 0.15, 0.0), 1.0)


def invariant(gamma):
    """c = 1 up to d = a, then 1 - g/w with g(u) + g(u + 1) = gamma, so that Phi = 1 - gamma at every offset."""
    if gamma == 0:
        return lambda d: 1.0 if d < 1.5 else 0.0
    a = 0.5 - (2.0 * gamma) ** 0.5  # where w(a + 1) = gamma: c = 1 below a

    def c(d):
        if d <= a:
            return 1.0
        if d <= 0.5:
            return 1.0 - (gamma - w(d + 1.0)) / w(d)
        if w(d) <= gamma:
            return 0.0
        return 1.0 - gamma / w(d)
    return c


def phi(c, s):
    return sum(c(k - s) * w(k - s) for k in range(-3, 4))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=10, help="offsets from 0 to 1 in this many steps")
    args = ap.parse_args()
    shares = [("shipped", shipped), ("gamma 1/8", invariant(0.125)), ("gamma 1/32", invariant(0.03125)),
              ("full", invariant(0.0))]
    print("offset " + " ".join(f"{n:>11}" for n, _ in shares))
    for i in range(args.steps + 1):
        s = i / args.steps
        print(f"{s:6.2f} " + " ".join(f"{phi(c, s):11.3f}" for _, c in shares))
    print("share at d = 0.5, 0.75, 1.0 cells outside the face: " +
          "; ".join(f"{n} " + ", ".join(f"{c(d):.2f}" for d in (0.5, 0.75, 1.0)) for n, c in shares))


if __name__ == "__main__":
    main()
