"""cdmpm_tools.plotting - what the figures of every command share, so that they read alike.

  pyplot(tool)                  matplotlib.pyplot drawing to files (the Agg backend, no display); without
                                matplotlib a one-line error naming TOOL;
  save_figure(fig, path, dpi)   lays the figure out (tight_layout unless it has a layout of its own), writes it and
                                closes it; returns PATH;
  ICE, WATER                    ice coloured by damage from slate grey (intact, readable on white) through amber to
                                dark red (broken): ICE_DAMAGE_COLOURS, ice_colormap(); water in blue: WATER;
  ice_mask(fields, meta, n)     which particles are ice: those whose damage is a number (frames write NaN on
                                materials without damage), or by the material names of older frames;
  robust_range(values)          a colour range from the 1st to the 99th percentile, so a few extreme particles (ice at
                                MPa beside water at kPa) do not wash out the rest;
  probe_units(run_dir)          axis label with units for every column of probes.csv, from the probe types in the
                                run's scene.resolved.json (2D runs: extensive quantities per metre of width).
"""
import numpy as np

from .cli import fail
from .io import probe_list, read_scene

WATER = "#3a7bd5"
# Ice damage 0, 0.5, 1: slate grey (intact), amber, dark red (broken), as RGB in [0, 1] (matplotlib and ParaView).
ICE_DAMAGE_COLOURS = [(0.373, 0.435, 0.502), (0.878, 0.627, 0.188), (0.608, 0.0, 0.0)]


def pyplot(tool):
    """matplotlib.pyplot with the Agg backend; exits via fail() naming TOOL if matplotlib is missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(tool, f"needs numpy and matplotlib (Debian's /usr/bin/python3 with python3-matplotlib): {e}")
    return plt


def save_figure(fig, path, dpi=120, tight=True):
    """FIG written to PATH at DPI and closed; laid out with tight_layout first if TIGHT and the figure has no layout
    engine of its own (layout="constrained"). Returns PATH."""
    if tight and fig.get_layout_engine() is None:
        fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    import matplotlib.pyplot as plt
    plt.close(fig)
    return path


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
    scene = read_scene(run_dir)
    if scene is None:
        return {}
    dim = scene.get("dim", 2)
    labels = {}
    for p in probe_list(scene):
        name, kind = p.get("name"), p.get("type")
        quantity, u2, u3 = _PROBE_UNITS.get(kind, (kind, "", ""))
        unit = u2 if dim == 2 else u3
        label = f"{name}: {quantity}" + (f" [{unit}]" if unit else "")
        labels[name] = label
        if kind in ("rigid_position", "rigid_velocity"):
            for a in "xyz"[:dim]:
                labels[f"{name}_{a}"] = f"{name} {a}: {quantity} [{unit}]"
    return labels
