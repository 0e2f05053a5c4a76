"""cdmpm_tools.io - the tables, records and grids of a run folder.

  read_csv(path)                a CSV file with a header (probes.csv, hazard.csv, waves.csv ...) as column name ->
                                array (an empty field is NaN; a column with a field that is not a number, such as
                                waves.csv's gauge names, is an array of strings; lines starting with # are comments);
  read_table(tool, path, columns)
                                read_csv with one-line errors naming TOOL for a missing file or column;
  read_waves(run)               the run's waves.csv as gauge name -> its row (field name -> text);
  read_summary(run)             the run's summary.json as a dict (None without a readable one);
  read_scene(run)               the run's scene.resolved.json as a dict (None without a readable one);
  probe_list(scene)             the probes of a scene as a list of dicts;
  read_asc(path)                an ESRI ASCII grid (the 3D hazard rasters): (values with NaN for NODATA, header
                                {key: number}, the header's six lines as written, map extent);
  write_asc(path, values, ...)  an ESRI ASCII grid (rows north first, NaN written as NODATA -9999) and its .prj.
"""
import csv
import json
import math
import os

import numpy as np

from .cli import fail


def read_csv(path):
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if line.strip() and not line.startswith("#")]
    if not lines:
        return {}
    header = lines[0].strip().split(",")
    rows = [line.split(",") for line in lines[1:]]
    cols = {}
    for k, name in enumerate(header):
        fields = [r[k] if k < len(r) else "" for r in rows]
        try:
            cols[name] = np.array([float(v) if v != "" else np.nan for v in fields])
        except ValueError:
            cols[name] = np.array(fields)
    return cols


def read_table(tool, path, columns=()):
    """read_csv(PATH); exits via fail() naming TOOL if PATH is missing or lacks one of COLUMNS."""
    if not os.path.isfile(path):
        fail(tool, f"{path}: no such file")
    cols = read_csv(path)
    for c in columns:
        if c not in cols:
            fail(tool, f"{path}: no column '{c}' (columns: {', '.join(cols)})")
    return cols


def read_waves(run):
    """{gauge name: {field: text}} of RUN/waves.csv (a gauge the wave has not reached has empty fields)."""
    with open(os.path.join(run, "waves.csv")) as f:
        return {r["gauge"]: r for r in csv.DictReader(f)}


def _read_json(path):
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def read_summary(run):
    """RUN/summary.json as a dict, or None if the run has none (or one that is not a JSON object)."""
    return _read_json(os.path.join(run, "summary.json"))


def read_scene(run):
    """RUN/scene.resolved.json (the scene as the program resolved it) as a dict, or None without one."""
    return _read_json(os.path.join(run, "scene.resolved.json"))


def probe_list(scene):
    """The probes of SCENE, a list of dicts ({"list": [...]} or a plain list in the scene)."""
    probes = (scene or {}).get("probes", {})
    return probes.get("list", []) if isinstance(probes, dict) else probes


def read_asc(path):
    """(values, header, header_lines, extent) of an ESRI ASCII grid: values with NaN where NODATA_value, header
    {lower-case key: number}, its six lines as written (to write a grid with the same georeference), and the map
    extent [west, east, south, north]."""
    head, lines = {}, []
    with open(path) as f:
        for _ in range(6):
            line = f.readline()
            key, value = line.split()
            head[key.lower()] = float(value)
            lines.append(line.rstrip("\n"))
        data = np.loadtxt(f, ndmin=2)
    data = np.where(data == head.get("nodata_value", np.nan), np.nan, data)
    extent = [head["xllcorner"], head["xllcorner"] + head["ncols"] * head["cellsize"],
              head["yllcorner"], head["yllcorner"] + head["nrows"] * head["cellsize"]]
    return data, head, lines, extent


def write_asc(path, values, xll, yll, cellsize, fmt=".6g", prj=None):
    """VALUES (rows north first) as an ESRI ASCII grid at PATH with lower-left corner (XLL, YLL) and square cells of
    CELLSIZE, each value formatted with FMT and a value that is not finite as NODATA_value -9999; with PRJ (a CRS
    as ESRI WKT), also PATH's .prj."""
    with open(path, "w") as f:
        f.write(f"ncols {len(values[0])}\nnrows {len(values)}\nxllcorner {xll!r}\nyllcorner {yll!r}\n"
                f"cellsize {cellsize!r}\nNODATA_value -9999\n")
        for row in values:
            f.write(" ".join(f"{v:{fmt}}" if math.isfinite(v) else "-9999" for v in row) + "\n")
    if prj is not None:
        with open(os.path.splitext(path)[0] + ".prj", "w") as f:
            f.write(prj + "\n")
