#!/usr/bin/python3
"""plot_probes.py - plot columns of a cdmpm probes.csv against time.

    tools/plot_probes.py out/probes.csv --columns p_bottom ke --png out.png

Each column gets its own panel (probes have different units); without --columns, all columns are plotted.
Needs numpy and matplotlib (e.g. /usr/bin/python3).
"""
import argparse
import sys

import numpy as np


def main():
    p = argparse.ArgumentParser(description="Plot columns of a cdmpm probes.csv against time.")
    p.add_argument("csv", help="probes.csv written by cdmpm run")
    p.add_argument("--columns", nargs="+", help="columns to plot (default: all)")
    p.add_argument("--png", default="probes.png", help="output image (default: probes.png)")
    args = p.parse_args()

    data = np.genfromtxt(args.csv, delimiter=",", names=True)
    names = [n for n in data.dtype.names if n != "time"]
    columns = args.columns or names
    unknown = [c for c in columns if c not in names]
    if unknown:
        print(f"plot_probes: no column {', '.join(unknown)} in {args.csv} (has: {', '.join(names)})", file=sys.stderr)
        return 2

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(columns), 1, sharex=True, squeeze=False, figsize=(7, 1.0 + 2.2 * len(columns)))
    for ax, c in zip(axes[:, 0], columns):
        ax.plot(data["time"], data[c], lw=1.2)
        ax.set_ylabel(c)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    axes[0, 0].set_title(args.csv)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"plot: {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
