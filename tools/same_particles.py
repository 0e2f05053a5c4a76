"""same_particles.py - whether two particle frames hold the same particle state, bit for bit: the frames of a
distributed run (a .pvtu joining per-rank .vtu pieces) against one process's .vtu (docs/architecture.md).
The particles of each frame are sorted by their id; then the positions and every point array must be equal
bytewise (NaN included), and the frames' field data (TimeValue, material_names; of the first piece) equal.

    /usr/bin/python3 tools/same_particles.py A.vtu B.pvtu [A2 B2 ...]

Prints one line per pair; exit code 0 if every pair is the same, 1 otherwise, 2 on a usage error.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.frames import first_piece, read_field_data, read_frame  # noqa: E402


def by_id(path):
    points, data = read_frame(path)
    order = np.argsort(data["id"], kind="stable")
    return points[order], {k: v[order] for k, v in data.items()}


def differences(a, b):
    """The names of what differs between frames a and b (empty: the same state)."""
    pa, da = by_id(a)
    pb, db = by_id(b)
    if len(pa) != len(pb):
        return [f"particle count {len(pa)} against {len(pb)}"]
    out = []
    if pa.tobytes() != pb.tobytes():
        out.append("positions")
    for name in sorted(set(da) | set(db)):
        if name not in da or name not in db or da[name].dtype != db[name].dtype or da[name].tobytes() != db[name].tobytes():
            out.append(name)
    fa, fb = read_field_data(first_piece(a)), read_field_data(first_piece(b))
    for name in sorted(set(fa) | set(fb)):
        va, vb = fa.get(name), fb.get(name)
        same = (isinstance(va, list) and va == vb) or (
            isinstance(va, np.ndarray) and isinstance(vb, np.ndarray) and va.tobytes() == vb.tobytes())
        if not same:
            out.append("field data " + name)
    return out


def main(args):
    if len(args) < 2 or len(args) % 2:
        print(__doc__, file=sys.stderr)
        return 2
    status = 0
    for a, b in zip(args[0::2], args[1::2]):
        diff = differences(a, b)
        print(f"{a} and {b}: " + ("the same particle state" if not diff else "differ in " + ", ".join(diff)))
        status |= bool(diff)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
