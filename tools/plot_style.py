"""plot_style.py - what every cdmpm plotting tool shares, so their figures read alike and they behave alike:

  fail(tool, message)           one line on stderr and exit status 2, instead of a traceback;
  output_folder(tool, folder)   creates the folder the user named; refuses a folder inside the repository's
                                committed tree (docs/, scenes/, ...) unless --force, so no tool overwrites
                                committed figures by default;
  robust_range(values)          a colour range from the 1st to the 99th percentile, so a few extreme particles
                                (ice at MPa beside water at kPa) do not wash out the rest;
  ICE, WATER                    ice coloured by damage from slate grey (intact, readable on white) through
                                amber to dark red (broken); water in blue;
  ice_mask(fields, meta)        which particles are ice: those whose damage is a number (frames write NaN on
                                materials without damage), or by the material names of older frames;
  probe_units(run_dir)          axis label with units for every column of probes.csv, from the probe types in
                                the run's scene.resolved.json (2D runs: extensive quantities per metre of width);
  read_csv(path)                a CSV file with a header (probes.csv, hazard.csv, waves.csv ...) as column name ->
                                array (an empty field is NaN; a column with a field that is not a number, such as
                                waves.csv's gauge names, is an array of strings);
  read_asc(path)                an ESRI ASCII grid (the 3D hazard rasters): (values with NaN for NODATA, header
                                {key: number}, the header's six lines as written, map extent);
  add_frame_arguments(ap)       the arguments OUT FRAME [--material M] that read_material_frame takes;
  read_material_frame(tool, out, frame, material, needs)
                                frame FRAME of run OUT (particles_FRAME.vtu): its path, and the positions and fields
                                of one material's particles; one-line errors for a missing frame, field or material;
  run_cdmpm(tool, scene, out)   runs build/cdmpm on a scene with --set values, printing the command; a failed run
                                ends the tool with one line (the program's own messages are above it).
"""
import json
import os
import subprocess
import sys

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CDMPM = os.path.join(REPO, "build", "cdmpm")
WATER = "#3a7bd5"


def fail(tool, message):
    print(f"{tool}: {message}", file=sys.stderr)
    sys.exit(2)


def _tracked_files_under(folder):
    """Committed files of the repository inside FOLDER (empty if FOLDER is outside it or git is missing)."""
    folder = os.path.realpath(folder)
    if os.path.commonpath([folder, REPO]) != REPO:
        return []
    try:
        out = subprocess.run(["git", "-C", REPO, "ls-files", "--", os.path.relpath(folder, REPO)],
                             capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return []
    return out.split()


def output_folder(tool, folder, force=False):
    """Creates FOLDER for a tool's outputs and returns it; refuses one that holds committed files."""
    tracked = _tracked_files_under(folder)
    if tracked and not force:
        fail(tool, f"{folder} holds committed files ({tracked[0]}, ...): name another folder, "
                   "or add --force to replace the committed figures on purpose")
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as e:
        fail(tool, f"cannot create output folder {folder}: {e.strerror}")
    return folder


def robust_range(values, lo=1.0, hi=99.0):
    """(vmin, vmax): the LO-th and HI-th percentiles of the finite VALUES (a non-empty range)."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return 0.0, 1.0
    a, b = np.percentile(v, [lo, hi])
    if b <= a:
        a, b = a - 0.5 * max(abs(a), 1.0), b + 0.5 * max(abs(b), 1.0)
    return float(a), float(b)


# Ice damage 0, 0.5, 1: slate grey (intact), amber, dark red (broken), as RGB in [0, 1] (matplotlib and ParaView).
ICE_DAMAGE_COLOURS = [(0.373, 0.435, 0.502), (0.878, 0.627, 0.188), (0.608, 0.0, 0.0)]


def ice_colormap():
    from matplotlib.colors import LinearSegmentedColormap
    return LinearSegmentedColormap.from_list("ice_damage", ICE_DAMAGE_COLOURS)


def ice_mask(fields, meta, n):
    """Boolean mask of the ice particles of a frame."""
    if "damage" in fields:
        d = np.asarray(fields["damage"], dtype=float)
        if np.isnan(d).any():
            return ~np.isnan(d)
    names = meta.get("material_names") if meta else None
    if names is not None and "material" in fields:
        ice_ids = [k for k, name in enumerate(names) if "ice" in name.lower()]
        return np.isin(fields["material"], ice_ids)
    return np.zeros(n, dtype=bool)


# Units of each probe type's columns: (quantity, unit in 2D, unit in 3D).
_PROBE_UNITS = {
    "wave_gauge": ("surface elevation", "m", "m"),
    "front": ("front position", "m", "m"),
    "pressure": ("pressure", "Pa", "Pa"),
    "kinetic_energy": ("kinetic energy", "J/m", "J"),
    "gravitational_energy": ("gravitational energy", "J/m", "J"),
    "elastic_energy": ("elastic energy", "J/m", "J"),
    "total_energy": ("total energy", "J/m", "J"),
    "mass": ("mass", "kg/m", "kg"),
    "rigid_position": ("position", "m", "m"),
    "rigid_velocity": ("velocity", "m/s", "m/s"),
    "rigid_angle": ("angle", "rad", "rad"),
}


def probe_units(run_dir):
    """{column: axis label with units} for the probes of the run in RUN_DIR (empty if it has no resolved scene)."""
    path = os.path.join(run_dir, "scene.resolved.json")
    try:
        scene = json.load(open(path))
    except (OSError, ValueError):
        return {}
    dim = scene.get("dim", 2)
    labels = {}
    probes = scene.get("probes", {})
    for p in probes.get("list", []) if isinstance(probes, dict) else probes:
        name, kind = p.get("name"), p.get("type")
        quantity, u2, u3 = _PROBE_UNITS.get(kind, (kind, "", ""))
        unit = u2 if dim == 2 else u3
        label = f"{name}: {quantity}" + (f" [{unit}]" if unit else "")
        labels[name] = label
        if kind in ("rigid_position", "rigid_velocity"):
            for a in "xyz"[:dim]:
                labels[f"{name}_{a}"] = f"{name} {a}: {quantity} [{unit}]"
    return labels


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        rows = [line.rstrip("\n").split(",") for line in f if line.strip()]
    cols = {}
    for k, name in enumerate(header):
        fields = [r[k] if k < len(r) else "" for r in rows]
        try:
            cols[name] = np.array([float(v) if v != "" else np.nan for v in fields])
        except ValueError:
            cols[name] = np.array(fields)
    return cols


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


def run_cdmpm(tool, scene, out, threads=None, sets=(), force=True):
    """build/cdmpm run SCENE --out OUT --quiet [--force] [--threads N] [--set S ...]; exits via fail() if it fails."""
    cmd = [CDMPM, "run", scene, "--out", out, "--quiet"] + (["--force"] if force else [])
    if threads:
        cmd += ["--threads", str(threads)]
    for s in sets:
        cmd += ["--set", s]
    print("running:", " ".join(cmd), flush=True)
    if subprocess.run(cmd).returncode != 0:
        fail(tool, f"the run of {os.path.basename(scene)} failed (its messages are above; outputs in {out})")


def add_frame_arguments(ap):
    """Positional OUT (a run's folder) and FRAME (its frame number), and --material (default 0, the ice)."""
    ap.add_argument("out")
    ap.add_argument("frame", type=int)
    ap.add_argument("--material", type=int, default=0, help="material index of the ice (default 0)")


def read_material_frame(tool, out, frame, material, needs=("stress",)):
    """(path, positions, fields) of the particles of material index MATERIAL in frame FRAME of the run in OUT."""
    from vtu import read_vtu

    path = os.path.join(out, f"particles_{frame:04d}.vtu")
    if not os.path.exists(path):
        fail(tool, f"{path}: no such frame")
    pts, f = read_vtu(path)
    missing = [k for k in ("material",) + tuple(needs) if k not in f]
    if missing:
        fail(tool, f"{path}: the frame has no {' or '.join(missing)} field (a 2D run with ice writes them)")
    sel = f["material"] == material
    if not sel.any():
        fail(tool, f"{path}: no particle of material {material}")
    return path, pts[sel], {k: v[sel] for k, v in f.items()}
