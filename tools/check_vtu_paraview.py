"""check_vtu_paraview.py - open .vtu frames with ParaView's own reader and print what it sees: the number of
points, each point array's type, components and range, the field data and the time ParaView reports, and
whether every array equals what tools/cdmpm_tools/frames.py reads from the same file, bit for bit. Not part of the tests.

    xvfb-run -a pvpython tools/check_vtu_paraview.py FRAME.vtu...

(Debian packages paraview, python3-paraview, which brings pvpython and the paraview module, and xvfb.)

Exits 1 if ParaView and cdmpm_tools.frames disagree on any frame.
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import XMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.frames import read_field_data, read_vtu  # noqa: E402


def field_data(grid):
    fd = grid.GetFieldData()
    out = {}
    for i in range(fd.GetNumberOfArrays()):
        arr = fd.GetAbstractArray(i)
        if arr.GetDataTypeAsString() == "string":
            out[arr.GetName()] = [arr.GetValue(k) for k in range(arr.GetNumberOfValues())]
        else:
            out[arr.GetName()] = vtk_to_numpy(arr).tolist()
    return out


def same(a, b):
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def check(path):
    reader = XMLUnstructuredGridReader(FileName=[path])
    reader.UpdatePipeline()
    grid = servermanager.Fetch(reader)
    n = grid.GetNumberOfPoints()
    print(f"{path}: {n} points, {grid.GetNumberOfCells()} cells, ParaView time steps {list(reader.TimestepValues or [])}")
    points, fields = read_vtu(path)
    pv_points = vtk_to_numpy(grid.GetPoints().GetData())
    ok = same(pv_points, points)
    print(f"  Points {pv_points.dtype} x3 range x [{pv_points[:, 0].min():.6g}, {pv_points[:, 0].max():.6g}]"
          f" y [{pv_points[:, 1].min():.6g}, {pv_points[:, 1].max():.6g}] same as cdmpm_tools.frames: {ok}")
    pd = grid.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arr = pd.GetArray(i)
        name, values = arr.GetName(), vtk_to_numpy(arr)
        eq = same(values, fields[name])
        ok &= eq
        print(f"  {name:10s} {str(values.dtype):8s} x{arr.GetNumberOfComponents()} "
              f"range [{values.min():.6g}, {values.max():.6g}] same as cdmpm_tools.frames: {eq}")
    pv_fd, our_fd = field_data(grid), read_field_data(path)
    our_fd = {k: (v if isinstance(v, list) else v.tolist()) for k, v in our_fd.items()}
    print(f"  field data {pv_fd} same as cdmpm_tools.frames: {pv_fd == our_fd}")
    return ok and pv_fd == our_fd and len(fields) == pd.GetNumberOfArrays()


if __name__ == "__main__":
    results = [check(p) for p in sys.argv[1:]]
    print("ParaView and cdmpm_tools.frames agree" if all(results) else "ParaView and cdmpm_tools.frames DISAGREE")
    sys.exit(0 if all(results) else 1)
