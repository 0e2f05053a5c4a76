#!/usr/bin/python3
"""plot_probes.py - plot the columns of a cdmpm run's probes.csv against time, one panel per column, each axis
labelled with its quantity and unit (from the probe types in the run's scene.resolved.json; in 2D, extensive
quantities are per metre of width). A section probe (docs/scenes.md#section-probe) gets one panel per quantity
(eta, d, u, q; in 3D eta, d, u, v, qx, qy), its stations as lines labelled with their position.

    /usr/bin/python3 tools/plot_probes.py RUN_DIR [--columns p_bottom ke] [--out FOLDER]
The figure goes to FOLDER/probes.png (default: RUN_DIR/plots); a folder holding committed files is refused
(--force overrides). Needs numpy and matplotlib (Debian's /usr/bin/python3).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import add_output_arguments, fail, output_folder  # noqa: E402
from cdmpm_tools.io import probe_list, read_csv, read_scene  # noqa: E402
from cdmpm_tools.plotting import probe_units, pyplot, save_figure  # noqa: E402

TOOL = "plot_probes"

# The quantities of a section probe's stations: column suffix -> axis label.
SECTION_QUANTITIES = {
    "eta": "free-surface elevation eta [m]", "d": "total depth d [m]", "u": "depth-averaged u [m/s]",
    "v": "depth-averaged v [m/s]", "q": "discharge q = d u [m²/s]", "qx": "discharge qx = d u [m²/s]",
    "qy": "discharge qy = d v [m²/s]"}


def section_panels(run, names):
    """[(axis label, [(column, line label), ...]), ...] for the section probes of the run's scene.resolved.json
    whose columns are in `names`, one panel per quantity."""
    panels = []
    for p in probe_list(read_scene(run)):
        if p.get("type") != "section":
            continue
        name = p["name"]
        if "position" in p:  # 2D: one station
            stations = [(name, f"x = {p['position'][0]:g} m")]
            fields = ["eta", "d", "u", "q"]
        else:
            n, a, b = p["points"], p["start"], p["end"]
            stations = []
            for k in range(n):
                f = k / (n - 1)
                x, y = (1 - f) * a[0] + f * b[0], (1 - f) * a[1] + f * b[1]
                stations.append((f"{name}_{k}", f"station {k} ({x:g}, {y:g}) m"))
            fields = ["eta", "d", "u", "v", "qx", "qy"]
        for q in fields:
            lines = [(f"{prefix}_{q}", label) for prefix, label in stations if f"{prefix}_{q}" in names]
            if lines:
                panels.append((f"{name}: {SECTION_QUANTITIES[q]}", lines))
    return panels


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", help="a cdmpm run folder (with probes.csv), or a probes.csv")
    p.add_argument("--columns", nargs="+", help="columns to plot (default: all)")
    add_output_arguments(p, "folder for probes.png (default: the run folder's plots/)")
    args = p.parse_args()
    plt = pyplot(TOOL)
    run = args.run if os.path.isdir(args.run) else os.path.dirname(os.path.abspath(args.run))
    csv = os.path.join(args.run, "probes.csv") if os.path.isdir(args.run) else args.run
    if not os.path.isfile(csv):
        fail(TOOL, f"{csv}: no such file (a run without probes writes none)")
    data = read_csv(csv)
    if "time" not in data:
        fail(TOOL, f"{csv}: no header with a time column")
    text = [n for n, v in data.items() if v.dtype.kind not in "fi"]
    if text:
        fail(TOOL, f"{csv}: not a probes table: column {text[0]} holds text")
    names = [n for n in data if n != "time"]
    columns = args.columns or names
    unknown = [c for c in columns if c not in names]
    if unknown:
        fail(TOOL, f"no column {', '.join(unknown)} in {csv} (has: {', '.join(names)})")
    if not columns:
        fail(TOOL, f"{csv}: no probe columns")
    units = probe_units(run)
    # Sections: one panel per quantity with every station; the other columns one panel each.
    sections = section_panels(run, set(columns))
    in_sections = {c for _, lines in sections for c, _ in lines}
    panels = [(units.get(c, c), [(c, None)]) for c in columns if c not in in_sections] + sections
    folder = output_folder(TOOL, args.out or os.path.join(run, "plots"), args.force)
    fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False, figsize=(7, 1.0 + 2.2 * len(panels)))
    for ax, (label, lines) in zip(axes[:, 0], panels):
        for c, line_label in lines:
            ax.plot(data["time"], data[c], lw=1.2, label=line_label or c)
        if len(lines) > 1 or lines[0][1]:
            ax.legend(fontsize=7, loc="upper right")
        ax.set_ylabel(label, fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    axes[0, 0].set_title(csv, fontsize=8)
    print(save_figure(fig, os.path.join(folder, "probes.png"), dpi=120))
    return 0


if __name__ == "__main__":
    sys.exit(main())
