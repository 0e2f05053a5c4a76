"""cdmpm_tools.frames - read cdmpm particle frames (VTK XML UnstructuredGrid, raw appended) into numpy arrays.

    from cdmpm_tools.frames import first_piece, read_field_data, read_frame, read_pvd, read_vtu
    points, fields = read_vtu("out/particles_0010.vtu")   # points: (n, 3); fields: name -> array
    meta = read_field_data("out/particles_0010.vtu")      # e.g. {"TimeValue": array([2.]), "material_names": ["water", "ice"]}
    frames = read_pvd("out")                               # [(time, "particles_NNNN.vtu"), ...] in file order
    points, fields = read_frame("out/particles_0010.pvtu")  # .vtu or a distributed run's .pvtu
    meta = read_field_data(first_piece("out/particles_0010.pvtu"))
    path = frame_file("out", 10)                           # out/particles_0010.vtu, or its .pvtu in a distributed run

For commands that take a run folder and a frame number: add_frame_arguments(ap) (OUT FRAME [--material M]) and
read_material_frame(tool, out, frame, material, needs), the positions and fields of one material's particles with
one-line errors for a missing frame, field or material.

Reads appended data with header_type UInt64, uncompressed (a UInt64 byte count, then the values) or
compressed with compressor="vtkZLibDataCompressor" (a UInt64 header [blocks, block size, size of a partial
last block or 0, compressed size of each block], then one zlib stream per block); see the VTK file formats
documentation, "XML File Formats". String arrays (FieldData) are NUL-terminated strings, one per tuple.
"""
import os
import re
import zlib

import numpy as np

from .cli import fail

_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8,
          "String": np.uint8}


def _decode(data, off, compressed):
    """The uncompressed bytes of the appended array whose header starts at byte OFF of DATA."""
    if not compressed:
        nbytes = int(np.frombuffer(data, np.uint64, 1, off)[0])
        return data[off + 8:off + 8 + nbytes]
    nblocks, block, last = (int(v) for v in np.frombuffer(data, np.uint64, 3, off))
    sizes = np.frombuffer(data, np.uint64, nblocks, off + 24).astype(np.int64)
    at = off + 24 + 8 * nblocks
    out = []
    for b, size in enumerate(sizes):
        raw = zlib.decompress(data[at:at + size])
        expected = last if b == nblocks - 1 and last else block
        if len(raw) != expected:
            raise ValueError(f"zlib block {b} holds {len(raw)} bytes, expected {expected}")
        out.append(raw)
        at += size
    return b"".join(out)


def _sections(path):
    """{section: {array name: array}} for the FieldData, PointData, Points and Cells sections of PATH."""
    data = open(path, "rb").read()
    start = data.index(b'<AppendedData encoding="raw">')
    base = data.index(b"_", start) + 1
    header = data[:start].decode()
    root = re.search(r"<VTKFile([^>]*)>", header).group(1)
    compressed = 'compressor="vtkZLibDataCompressor"' in root
    if "compressor=" in root and not compressed:
        raise ValueError(f"{path}: unsupported compressor")
    out = {}
    for sec in re.finditer(r"<(FieldData|PointData|Points|Cells)>(.*?)</\1>", header, re.S):
        arrays = out.setdefault(sec.group(1), {})
        for m in re.finditer(r"<DataArray([^>]*)>", sec.group(2)):
            attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
            raw = _decode(data, base + int(attrs["offset"]), compressed)
            if attrs["type"] == "String":
                arrays[attrs["Name"]] = [s.decode() for s in raw.split(b"\0")[:-1]]
                continue
            arr = np.frombuffer(raw, _TYPES[attrs["type"]])
            ncomp = int(attrs.get("NumberOfComponents", 1))
            arrays[attrs.get("Name", "")] = arr.reshape(-1, ncomp) if ncomp > 1 else arr
    return out


def read_vtu(path):
    """(points (n, 3), {point-data name: array}) of the frame at PATH."""
    sec = _sections(path)
    return sec["Points"]["Points"], sec.get("PointData", {})


def read_field_data(path):
    """{name: numpy array, or list of str for String arrays} of the frame's FieldData ({} without one)."""
    return _sections(path).get("FieldData", {})


def read_pvd(out):
    """The frames listed in OUT/particles.pvd as (time, file name) pairs, in the order written."""
    pvd = open(os.path.join(out, "particles.pvd")).read()
    return [(float(t), f) for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)]


def read_pvtu(path):
    """(points (n, 3), {point-data name: array}) of a distributed run's frame: the .vtu pieces the .pvtu at PATH
    lists (Piece Source, relative to its folder), concatenated in the listed order."""
    folder = os.path.dirname(path)
    pieces = re.findall(r'<Piece Source="([^"]+)"', open(path).read())
    if not pieces:
        raise ValueError(f"{path}: lists no piece")
    parts = [read_vtu(os.path.join(folder, p)) for p in pieces]
    points = np.concatenate([p[0] for p in parts])
    data = {name: np.concatenate([p[1][name] for p in parts]) for name in parts[0][1]}
    return points, data


def read_frame(path):
    """read_vtu or read_pvtu, by the file's extension."""
    return read_pvtu(path) if path.endswith(".pvtu") else read_vtu(path)


def first_piece(path):
    """The file whose field data stands for the frame: the .vtu itself, or a .pvtu's first piece."""
    if not path.endswith(".pvtu"):
        return path
    piece = re.search(r'<Piece Source="([^"]+)"', open(path).read()).group(1)
    return os.path.join(os.path.dirname(path), piece)


def frame_file(out, frame):
    """OUT/particles_FRAME.vtu (FRAME a frame number), or a distributed run's particles_FRAME.pvtu when only that
    exists; the .vtu path if neither does."""
    path = os.path.join(out, f"particles_{frame:04d}.vtu")
    if not os.path.isfile(path) and os.path.isfile(path[:-3] + "pvtu"):
        return path[:-3] + "pvtu"
    return path


def add_frame_arguments(ap, material=True):
    """Positional OUT (a run's folder) and FRAME (its frame number); with MATERIAL, also --material (default 0, the
    ice), the material index read_material_frame takes."""
    ap.add_argument("out")
    ap.add_argument("frame", type=int)
    if material:
        ap.add_argument("--material", type=int, default=0, help="material index of the ice (default 0)")


def read_material_frame(tool, out, frame, material, needs=("stress",)):
    """(path, positions, fields) of the particles of material index MATERIAL in frame FRAME of the run in OUT."""
    path = frame_file(out, frame)
    if not os.path.exists(path):
        fail(tool, f"{path}: no such frame")
    pts, f = read_frame(path)
    missing = [k for k in ("material",) + tuple(needs) if k not in f]
    if missing:
        fail(tool, f"{path}: the frame has no {' or '.join(missing)} field (a 2D run with ice writes them)")
    sel = f["material"] == material
    if not sel.any():
        fail(tool, f"{path}: no particle of material {material}")
    return path, pts[sel], {k: v[sel] for k, v in f.items()}
