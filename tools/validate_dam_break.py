#!/usr/bin/python3
"""validate_dam_break.py - compare the 2D dam break front with Martin & Moyce (1952).

Runs scenes/dam_break_2d.json (a water column of width a = 0.05715 m and height 2a collapsing along a
channel), reads the position of the front from probes.csv and compares it, in the dimensionless variables

    T = t sqrt(2 g / a),   Z = x_front / a,

with the experimental front positions of Martin & Moyce (1952), linearly interpolating the simulated Z at
each experimental T. It prints a table (T, Z_exp, Z_sim, relative error) per resolution and the largest
|relative error| over 1 <= T <= 3.5 (the early times T < 1 depend on how the gate was lifted, the late ones
on the channel's roughness), and plots Z against T with the shallow-water (Ritter) bound Z = 1 + 2T.

Usage (from the repository root, needs numpy and matplotlib, e.g. /usr/bin/python3):

    tools/validate_dam_break.py                        # dx = a/40, run into output/dam_break_validation
    tools/validate_dam_break.py --dx-per-a 16 40 80    # convergence study: one run per resolution
    tools/validate_dam_break.py --out DIR --no-run     # re-analyse a finished run in DIR

With one resolution the run goes into DIR (--out); with several, into DIR/dx_a<N> for each N. The plot goes
to DIR/dam_break_front.png unless --png is given. --no-run skips running cdmpm and uses the finished runs
(summary.json with status "completed") already in place; it is an error if one is missing.

Exit status: 0 if the max |relative error| over 1 <= T <= 3.5 of the finest resolution is within
--tolerance (default 0.10), 1 if not, 2 on a usage error or a failed run.
"""
import argparse
import math
import os
import subprocess
import sys
from pathlib import Path

try:
    import numpy as np
except ImportError:
    sys.exit("validate_dam_break: needs numpy (and matplotlib for the plot), e.g. /usr/bin/python3 with python3-numpy")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools import cli  # noqa: E402
from cdmpm_tools.io import read_csv, read_summary  # noqa: E402
from cdmpm_tools.plotting import pyplot, save_figure  # noqa: E402

TOOL = "validate_dam_break"
REPO = Path(cli.REPO)
SCENE = REPO / "scenes" / "dam_break_2d.json"
A = 0.05715           # column width [m] (the column is a wide and 2a high)
G = 9.81              # gravity of the scene [m/s^2]
T_RANGE = (1.0, 3.5)  # interval of T over which the error is judged


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--cdmpm", default="build/cdmpm", help="cdmpm executable, relative to the repository root "
                   "unless absolute (default: build/cdmpm)")
    p.add_argument("--dx-per-a", type=int, nargs="+", default=[40], metavar="N",
                   help="resolution(s): dx = a/N (default: 40)")
    p.add_argument("--out", default="output/dam_break_validation", help="output directory")
    p.add_argument("--no-run", action="store_true", help="do not run cdmpm; analyse the finished runs in --out")
    p.add_argument("--threads", type=int, help="OpenMP threads for cdmpm (default: all cores)")
    p.add_argument("--data", default=str(REPO / "tests" / "data" / "dam_break_martin_moyce.csv"),
                   help="experimental data, CSV with columns T,Z (default: tests/data/"
                   "dam_break_martin_moyce.csv)")
    p.add_argument("--png", help="plot file (default: OUT/dam_break_front.png)")
    p.add_argument("--tolerance", type=float, default=0.10,
                   help="allowed max |relative error| over 1 <= T <= 3.5 (default: 0.10)")
    return p.parse_args()


def fail(message):
    cli.fail(TOOL, message)


def finished(run_dir):
    summary = read_summary(run_dir)
    return summary is not None and summary.get("status") == "completed"


def run_cdmpm(exe, run_dir, n, threads):
    cmd = [str(exe), "run", str(SCENE), "--out", str(run_dir), "--quiet",
           "--set", f"domain.dx={A / n!r}", "--set", "output.frames=false"]
    if threads:
        cmd += ["--threads", str(threads)]
    print("$ " + " ".join(cmd), flush=True)
    if subprocess.run(cmd).returncode != 0:
        fail(f"cdmpm failed for dx = a/{n}")


def read_front(run_dir):
    """Returns (T, Z) of the simulated front."""
    data = read_csv(run_dir / "probes.csv")
    return data["time"] * math.sqrt(2 * G / A), data["front"] / A


def compare(T_sim, Z_sim, T_exp, Z_exp):
    """Z_sim interpolated at the experimental T (NaN outside the simulated time) and the relative error."""
    Z_at = np.interp(T_exp, T_sim, Z_sim, left=np.nan, right=np.nan)
    return Z_at, (Z_at - Z_exp) / Z_exp


def print_table(n, T_exp, Z_exp, Z_at, err):
    print(f"\ndx = a/{n}")
    print(f"{'T':>7} {'Z_exp':>7} {'Z_sim':>7} {'rel.err':>8}")
    for t, z_exp, z_sim, e in zip(T_exp, Z_exp, Z_at, err):
        if np.isfinite(z_sim):
            print(f"{t:7.3f} {z_exp:7.3f} {z_sim:7.3f} {e:+8.3f}")
        else:
            print(f"{t:7.3f} {z_exp:7.3f} {'-':>7} {'-':>8}   (after the end of the run)")
    window = (T_exp >= T_RANGE[0]) & (T_exp <= T_RANGE[1])
    worst = np.nanmax(np.abs(err[window])) if np.any(np.isfinite(err[window])) else np.nan
    print(f"max |rel.err| over {T_RANGE[0]:g} <= T <= {T_RANGE[1]:g}: {worst:.3f}")
    return worst


def best_time_shift(T_sim, Z_sim, T_exp, Z_exp):
    """Diagnostic only (the verdict does not use it): the delay dT of the experiment's time origin, 0 <= dT <= 1
    in steps of 0.01, that minimises the max |relative error| of Z_sim(T - dT) over the experimental points the
    run covers. A release that is not instantaneous (a gate or diaphragm removed in a finite time) delays the
    measured front by such a shift; returns (dT, max |rel.err| with it)."""
    best = (0.0, np.inf)
    for shift in np.arange(0.0, 1.0001, 0.01):
        inside = (T_exp - shift >= T_sim[0]) & (T_exp - shift <= T_sim[-1]) & (T_exp >= 0.5)
        if not np.any(inside):
            continue
        e = np.max(np.abs(np.interp(T_exp[inside] - shift, T_sim, Z_sim) / Z_exp[inside] - 1))
        if e < best[1]:
            best = (float(shift), float(e))
    return best


def plot(curves, T_exp, Z_exp, png):
    plt = pyplot(TOOL)
    fig, ax = plt.subplots(figsize=(7, 5))
    t_max = max(T.max() for _, T, _ in curves)
    T = np.linspace(0, t_max, 2)
    ax.plot(T, 1 + 2 * T, "k--", lw=1, label="shallow water (Ritter), Z = 1 + 2T")
    for n, T_sim, Z_sim in curves:
        ax.plot(T_sim, Z_sim, lw=1.5, label=f"cdmpm, dx = a/{n}")
    ax.plot(T_exp, Z_exp, "ko", ms=6, mfc="none", label="Martin & Moyce (1952)")
    ax.axvspan(*T_RANGE, color="0.9", zorder=0, label=f"judged range {T_RANGE[0]:g} ≤ T ≤ {T_RANGE[1]:g}")
    z_max = max(max(Z.max() for _, _, Z in curves), Z_exp[T_exp <= t_max].max())
    ax.set_xlim(0, t_max)
    ax.set_ylim(0.8, 1.1 * z_max)
    ax.set_xlabel(r"$T = t\,\sqrt{2g/a}$  (dimensionless time)")
    ax.set_ylabel(r"$Z = x_{\mathrm{front}}/a$  (dimensionless front position)")
    ax.set_title(f"2D dam break, a = {A} m, column 2a high")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=9)
    print(f"\nplot: {save_figure(fig, png, dpi=120)}")


def main():
    args = parse_args()
    out = Path(args.out)
    exe = Path(args.cdmpm) if Path(args.cdmpm).is_absolute() else REPO / args.cdmpm
    resolutions = sorted(set(args.dx_per_a))
    if any(n <= 0 for n in resolutions):
        fail("--dx-per-a values must be positive")
    needed = [(Path(args.data), "experimental data (--data)")]
    if not args.no_run:
        needed += [(SCENE, "scene"), (exe, "cdmpm executable (--cdmpm; build it first)")]
    for path, what in needed:
        if not path.is_file():
            fail(f"missing {what}: {path}")
    exp = read_csv(args.data)
    T_exp, Z_exp = exp["T"], exp["Z"]

    curves, worst = [], {}
    for n in resolutions:
        run_dir = out if len(resolutions) == 1 else out / f"dx_a{n}"
        if args.no_run:
            if not finished(run_dir):
                fail(f"--no-run, but {run_dir} holds no finished run")
        else:
            run_cdmpm(exe, run_dir, n, args.threads)
        T_sim, Z_sim = read_front(run_dir)
        Z_at, err = compare(T_sim, Z_sim, T_exp, Z_exp)
        worst[n] = print_table(n, T_exp, Z_exp, Z_at, err)
        shift, e_shift = best_time_shift(T_sim, Z_sim, T_exp, Z_exp)
        print(f"diagnostic: with the experiment's time origin delayed by dT = {shift:.2f} "
              f"(t = {1e3 * shift / math.sqrt(2 * G / A):.1f} ms), max |rel.err| over the covered points "
              f"T >= 0.5 is {e_shift:.3f}")
        curves.append((n, T_sim, Z_sim))

    out.mkdir(parents=True, exist_ok=True)
    plot(curves, T_exp, Z_exp, args.png or out / "dam_break_front.png")
    finest = resolutions[-1]
    ok = bool(np.isfinite(worst[finest]) and worst[finest] <= args.tolerance)
    print(f"dx = a/{finest}: max |rel.err| {worst[finest]:.3f} {'<=' if ok else '>'} tolerance {args.tolerance:g}: "
          f"{'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
