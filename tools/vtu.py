"""vtu.py - read cdmpm particle frames (VTK XML UnstructuredGrid, raw appended) into numpy arrays.

    from vtu import read_vtu
    points, fields = read_vtu("out/particles_0010.vtu")   # points: (n, 3); fields: name -> array
    frames = read_pvd("out")                               # [(time, "particles_NNNN.vtu"), ...] in file order
"""
import os
import re
import numpy as np

_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8}


def read_vtu(path):
    data = open(path, "rb").read()
    start = data.index(b'<AppendedData encoding="raw">')
    base = data.index(b"_", start) + 1
    header = data[:start].decode()
    arrays = {}
    for m in re.finditer(r"<DataArray([^>]*)>", header):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        off = base + int(attrs["offset"])
        nbytes = int(np.frombuffer(data, np.uint64, 1, off)[0])
        arr = np.frombuffer(data, _TYPES[attrs["type"]], nbytes // np.dtype(_TYPES[attrs["type"]]).itemsize, off + 8)
        ncomp = int(attrs.get("NumberOfComponents", 1))
        arrays[attrs.get("Name", "")] = arr.reshape(-1, ncomp) if ncomp > 1 else arr
    points = arrays.pop("Points")
    for k in ("connectivity", "offsets", "types"):
        arrays.pop(k, None)
    return points, arrays


def read_pvd(out):
    """The frames listed in OUT/particles.pvd as (time, file name) pairs, in the order written."""
    pvd = open(os.path.join(out, "particles.pvd")).read()
    return [(float(t), f) for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)]
