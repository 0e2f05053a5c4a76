"""check_pvd_paraview.py - open runs' particles.pvd with ParaView's own reader and print, at each of its times, the
number of particles ParaView sees (a distributed run's .pvd lists .pvtu files that join per-rank .vtu pieces;
docs/architecture.md "Distributed runs"). Given two runs (e.g. one process's and a 3-rank run's), exit 1 unless
both list the same times with the same particle counts. Not part of the tests.

    xvfb-run -a pvpython tools/check_pvd_paraview.py RUN [OTHER_RUN]

(Debian packages paraview, python3-paraview, which brings pvpython and the paraview module, and xvfb.)
"""
import os
import sys

from paraview.simple import PVDReader


def counts(run):
    """[(time, number of points)] of RUN/particles.pvd, as ParaView reads it."""
    reader = PVDReader(FileName=os.path.join(run, "particles.pvd"))
    out = []
    for t in list(reader.TimestepValues or [0.0]):
        reader.UpdatePipeline(t)
        out.append((t, reader.GetDataInformation().GetNumberOfPoints()))
    return out


if __name__ == "__main__":
    if not 1 <= len(sys.argv[1:]) <= 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    runs = [counts(run) for run in sys.argv[1:]]
    for run, c in zip(sys.argv[1:], runs):
        print(f"{run}: {len(c)} frames, particles per frame {sorted(set(n for _, n in c))}, times {c[0][0]} .. {c[-1][0]}")
    if len(runs) == 2:
        agree = runs[0] == runs[1]
        print("same times and particle counts" if agree else "times or particle counts DIFFER")
        sys.exit(0 if agree else 1)
