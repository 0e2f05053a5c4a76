"""extrude_profile.py - a 3D terrain for the lake-at-rest test: a 2D bed profile (CSV: distance, elevation [m], the
format of the bathymetry boundary's "file", docs/scenes.md#terrain-from-files) extruded across a channel with sloping
side walls, written as an ESRI ASCII grid (.asc) that the 3D bathymetry boundary reads.

    /usr/bin/python3 tools/extrude_profile.py scenes/data/eqip_sermia_profile.csv scenes/data/eqip_sermia_channel.asc \
        --cellsize 20 --width 600 --floor 200 --side-slope 0.75

Elevation at (easting x, northing y), y across the channel in [0, width]:
    z(x, y) = profile(x) + side_slope * max(0, |y - width/2| - floor/2)
a flat floor `floor` metres wide along the channel's centre line, and banks rising at `side_slope` (rise over run) to
both sides. Easting runs over the profile's distance range; cell centres (xllcenter, yllcenter) lie on the profile's
first distance and on y = 0, so the grid covers a domain of the profile's length and the channel's width with
"file_origin" [first distance, 0, elevation of the domain's bottom].
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.io import read_csv  # noqa: E402


def read_profile(path):
    """[(distance, elevation), ...] from the profile's first two columns."""
    distance, elevation = list(read_csv(path).values())[:2]
    return [(float(d), float(z)) for d, z in zip(distance, elevation)]


def interp(pts, x):
    if x <= pts[0][0]:
        return pts[0][1]
    for (x0, z0), (x1, z1) in zip(pts, pts[1:]):
        if x <= x1:
            return z0 + (z1 - z0) * (x - x0) / (x1 - x0)
    return pts[-1][1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("profile")
    ap.add_argument("out")
    ap.add_argument("--cellsize", type=float, default=20.0)
    ap.add_argument("--width", type=float, default=600.0, help="channel width across [m]")
    ap.add_argument("--floor", type=float, default=200.0, help="width of the flat floor [m]")
    ap.add_argument("--side-slope", type=float, default=0.75, help="rise over run of the banks")
    a = ap.parse_args()
    pts = read_profile(a.profile)
    x0, length = pts[0][0], pts[-1][0] - pts[0][0]
    ncols, nrows = round(length / a.cellsize) + 1, round(a.width / a.cellsize) + 1
    with open(a.out, "w") as f:
        f.write(f"ncols {ncols}\nnrows {nrows}\nxllcenter {x0:g}\nyllcenter 0\ncellsize {a.cellsize:g}\nNODATA_value -9999\n")
        for j in reversed(range(nrows)):  # first row the northernmost
            y = j * a.cellsize
            bank = a.side_slope * max(0.0, abs(y - a.width / 2) - a.floor / 2)
            f.write(" ".join(f"{interp(pts, x0 + i * a.cellsize) + bank:.2f}" for i in range(ncols)) + "\n")


if __name__ == "__main__":
    main()
