#!/usr/bin/python3
"""sweep_sliding_block.py - iceberg length against buoyancy: runs scenes/sliding_block_2d.json for a set of
submergence ratios D/H and compares the first iceberg's length L/H with the bending models of the reference
paper:
    linear (reference paper):  L/H = 2 sigma_t / (3 rho_i g H (1 - D/H))
    cantilever, full buoyancy:  L/H = sqrt(sigma_t / (3 g (rho_i H - rho_w D)))
sigma_t is the scene's tensile_strength; tests/engine/test_ice_bar.cpp (IceBar.*) measures that the MPM
ice reaches it in uniaxial tension (peak within 5 %). The linear model is the shear model of the overhang: its
largest shear stress 3 V / (2 H) set equal to a strength; with the ice's own pure-shear strength tau_s
(src/material/cohesive_cam_clay.h shear_strength, measured by tests/engine/test_crack_starts.cpp SimpleShear.*):
    shear model:                L/H = 2 tau_s / (3 rho_i g H (1 - D/H))      (column model_shear)
Each run's recorded crack start (summary.json first_iceberg.crack_start, docs/ice.md) gives the columns
crack_mode (tension / shear), crack_time, crack_x_over_H (from the bed edge, positive beyond it) and
crack_z_over_H (above the bed), and band_tension / band_shear count the events of each mode on the band that
separates the iceberg (summary.json first_iceberg.band_events). DIR/sliding_block_sweep.json holds the models'
inputs.

One plot of several sweeps (e.g. the tension set and the shear set) with both models of each:
    /usr/bin/python3 tools/sweep_sliding_block.py --plot-sets DIR1 DIR2 [--labels A B] --out PNG

    /usr/bin/python3 tools/sweep_sliding_block.py [--cells-per-H 16] [--ratios 0 0.2 ...] [--out DIR] [--jobs 2]
                                                  [--crack-frames DT] [--set PATH=VALUE ...]
Writes DIR/sliding_block_sweep.csv and DIR/sliding_block_sweep.png; each run's outputs are in DIR/D_<ratio>/.
With --crack-frames DT the runs write frames every DT seconds and the CSV gets crack_overhang_over_H: the
overhang (ice front beyond the bed edge) in the first frame with a broken ice particle (damage > 0.5) in the
upper half of the slab within H of the edge, i.e. where the bending crack starts; L/H is the detached
iceberg's length, which also holds any ice behind the edge that the crack cuts off.
A run with no iceberg before the scene's end time reports the overhang it reached (L/H larger than that), as
"no_failure", or as "debris_no_iceberg" when the intact slab got more than H/4 shorter: the overhang broke into pieces
smaller than an iceberg (output.icebergs.min_cells).
The default ratios include neutral buoyancy, D/H = rho_i/rho_w, where the overhang carries no net load.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import CDMPM, REPO  # noqa: E402
from cdmpm_tools.frames import read_pvd, read_vtu  # noqa: E402
from cdmpm_tools.io import read_csv, read_summary  # noqa: E402
from cdmpm_tools.plotting import pyplot, save_figure  # noqa: E402

plt = pyplot("sweep_sliding_block")
SCENE = os.path.join(REPO, "scenes", "sliding_block_2d.json")


def agreement_window(scene, d_max=0.6, band=0.3):
    """Range of s = sigma_t / (rho_i g H) for which the cantilever stays within +-band of the linear model on
    0 <= D/H <= d_max. Their ratio is 1.5 f(d) / sqrt(3 s), f(d) = (1 - d) / sqrt(1 - r d), r = rho_w / rho_i;
    the extremes of f over [0, d_max] (taken on a fine grid) bound s from both sides."""
    r = scene["materials"]["water"]["density"] / scene["materials"]["ice"]["density"]
    shape = [(1 - d) / math.sqrt(1 - r * d) for d in [i * d_max / 100 for i in range(101)]]
    hi, lo = max(shape), min(shape)  # ratio = 1.5 * shape / sqrt(3 s)
    return (1.5 * hi / (1 + band)) ** 2 / 3, (1.5 * lo / (1 - band)) ** 2 / 3


def crack_overhang(run_dir, scene, par):
    """Overhang / H in the first frame with broken ice (damage > 0.5) in the slab's upper half near the edge.
    par: the run's parameters as the program resolved them (summary.json)."""
    H, x_edge, z_bed = par["H"], par["x_edge"], par["z_bed"]
    ice = list(scene["materials"]).index("ice")
    for _, f in sorted(read_pvd(run_dir)):
        pts, fields = read_vtu(os.path.join(run_dir, f))
        m = fields["material"] == ice
        x, y, d = pts[m, 0], pts[m, 1], fields["damage"][m]
        if ((d > 0.5) & (y > z_bed + 0.5 * H) & (abs(x - x_edge) < H)).any():
            return (x.max() - x_edge) / H
    return math.nan


def apply_sets(scene, sets):
    """The --set PATH=VALUE overrides that the models depend on, applied to the scene as the program applies them.
    The models need numbers: an override of H, a density, the tensile strength or gravity given as an expression
    ("= ...") is refused, because this tool cannot evaluate it."""
    model_inputs = ("parameters.H", "materials.ice.density", "materials.ice.tensile_strength",
                    "materials.water.density", "gravity")
    for item in sets:
        path, _, text = item.partition("=")
        try:
            value = json.loads(text)
        except json.JSONDecodeError:
            value = text
        if path in model_inputs and not isinstance(value, (int, float, list)):
            sys.exit(f"sweep_sliding_block.py: --set {item}: the bending models need a number for {path}")
        node, keys = scene, path.split(".")
        for k in keys[:-1]:
            node = node.setdefault(k, {})
        node[keys[-1]] = value


def glacier_shortening(run_dir):
    """How much shorter the glacier (body 0 of icebergs.csv, the largest intact body) is along the flow in the
    last frame than in the first. Without an iceberg, a slab whose overhang stays whole keeps its length."""
    bergs = read_csv(os.path.join(run_dir, "icebergs.csv"))
    length = bergs["length"][bergs["id"] == 0]
    return float(length[0]) - float(length[-1])


def uniaxial_tension_per_p0(M, beta, dim=2):
    """Uniaxial tensile strength per unit p0 of the yield surface (CohesiveCamClay::uniaxial_strength)."""
    t, cq2 = -1.0 / dim, 1.5 * (dim - 1) / dim
    A, B, C = (1 + 2 * beta) * cq2 + M * M * t * t, M * M * t * (beta - 1), -M * M * beta
    disc = math.sqrt(B * B - 4 * A * C)
    return -2 * C / (B + disc) if B > 0 else (-B + disc) / (2 * A)


def model_inputs(scene):
    """The numbers the models need, from the scene (after --set): H, densities, g, sigma_t and tau_s."""
    ice = scene["materials"]["ice"]
    sigma_t = ice["tensile_strength"]
    M, beta = ice["M"], ice["beta"]
    tau_s = sigma_t * M * math.sqrt(beta / (3 * (1 + 2 * beta))) / uniaxial_tension_per_p0(M, beta)
    return {"H": scene["parameters"]["H"], "rho_i": ice["density"], "rho_w": scene["materials"]["water"]["density"],
            "g": -scene.get("gravity", [0, -9.81])[1], "sigma_t": sigma_t, "tau_s": tau_s, "M": M, "beta": beta}


def model_lengths(m, ratio):
    """(linear with sigma_t, cantilever with buoyancy, shear model with tau_s), each as L/H."""
    H, rho_i, g = m["H"], m["rho_i"], m["g"]
    linear = 2 * m["sigma_t"] / (3 * rho_i * g * H * (1 - ratio)) if ratio < 1 else math.inf
    shear = 2 * m["tau_s"] / (3 * rho_i * g * H * (1 - ratio)) if ratio < 1 else math.inf
    net = rho_i * H - m["rho_w"] * ratio * H
    cantilever = math.sqrt(m["sigma_t"] / (3 * g * net)) if net > 0 else math.inf
    return linear, cantilever, shear


def models(scene, ratio):
    return model_lengths(model_inputs(scene), ratio)[:2]


def plot_sets(dirs, labels, png):
    """One plot: for each sweep folder its measured L/H (filled: crack started in tension, open: in shear) and its
    two models (cantilever with buoyancy, dashed; shear model with tau_s, solid), in the set's colour."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    d = np.linspace(0, 0.95, 200)
    for k, (folder, label) in enumerate(zip(dirs, labels)):
        colour = f"C{k}"
        m = json.load(open(os.path.join(folder, "sliding_block_sweep.json")))
        rows = list(csv.DictReader(open(os.path.join(folder, "sliding_block_sweep.csv"))))
        ax.plot(d, [model_lengths(m, x)[1] for x in d], "--", color=colour, label=f"{label}: cantilever with buoyancy")
        ax.plot(d, [model_lengths(m, x)[2] for x in d], "-", color=colour,
                label=f"{label}: shear model, tau_s = {m['tau_s'] / 1e6:.2f} MPa")
        for mode, face in (("tension", colour), ("shear", "none")):
            pts = [(float(r["D_over_H"]), float(r["L_over_H"])) for r in rows
                   if r["status"] == "iceberg" and r.get("crack_mode") == mode]
            if pts:
                ax.plot(*zip(*pts), "o", color=colour, mfc=face, label=f"{label}: cdmpm, crack starts in {mode}")
        pts = [(float(r["D_over_H"]), float(r["L_over_H"])) for r in rows if r["status"] != "iceberg"]
        if pts:
            ax.plot(*zip(*pts), "^", color=colour, label=f"{label}: cdmpm, no iceberg (overhang reached)")
    ax.set_xlabel("D/H")
    ax.set_ylabel("L/H")
    ax.set_ylim(0, 2.5)
    ax.legend(fontsize=7)
    ax.set_title("sliding block: iceberg length, both sets and both models", fontsize=9)
    print(save_figure(fig, png, dpi=120))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells-per-H", type=int, default=16)
    ap.add_argument("--ratios", type=float, nargs="*",
                    help="D/H values (default: 0 0.2 0.4 0.6 0.8 0.9 rho_i/rho_w 0.95 1.0, neutral buoyancy included)")
    ap.add_argument("--out", default="out/sliding_block_sweep")
    ap.add_argument("--cdmpm", default=CDMPM)
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--jobs", type=int, default=1, help="cases run at once (e.g. 2 on 2 cores)")
    ap.add_argument("--crack-frames", type=float, metavar="DT",
                    help="write frames every DT s and report the overhang at which the crack starts")
    ap.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                    help="passed on to every run (repeatable), e.g. --set parameters.push_speed=1")
    ap.add_argument("--plot-sets", nargs="+", metavar="DIR", help="plot these sweeps together (no runs) into --out PNG")
    ap.add_argument("--labels", nargs="+", help="the sets' names for --plot-sets")
    args = ap.parse_args()
    if args.plot_sets:
        labels = args.labels or [os.path.basename(os.path.normpath(x)) for x in args.plot_sets]
        return plot_sets(args.plot_sets, labels, args.out)
    scene = json.load(open(SCENE))
    apply_sets(scene, args.set)
    H = scene["parameters"]["H"]
    if args.ratios is None:
        neutral = scene["materials"]["ice"]["density"] / scene["materials"]["water"]["density"]
        args.ratios = [0, 0.2, 0.4, 0.6, 0.8, 0.9, round(neutral, 4), 0.95, 1.0]
    os.makedirs(args.out, exist_ok=True)
    ice = scene["materials"]["ice"]
    s_scene = ice["tensile_strength"] / (ice["density"] * -scene.get("gravity", [0, -9.81])[1] * H)
    s_lo, s_hi = agreement_window(scene)
    print(f"sigma_t / (rho_i g H) = {s_scene:.3f}; the cantilever is within 30 % of the linear model for every"
          f" D/H <= 0.6 only if it lies in [{s_lo:.3f}, {s_hi:.3f}]", flush=True)
    def run(r):
        run_dir = os.path.join(args.out, f"D_{r:g}")
        cmd = [args.cdmpm, "run", SCENE, "--out", run_dir, "--quiet", "--set", f"parameters.D_over_H={r}",
               "--set", f"parameters.cells_per_H={args.cells_per_H}"]
        cmd += (["--set", f"time.frame_interval={args.crack_frames}"] if args.crack_frames
                else ["--set", "output.frames=false"])
        if args.threads:
            cmd += ["--threads", str(args.threads)]
        for extra in args.set:
            cmd += ["--set", extra]
        print(" ".join(cmd), flush=True)
        rc = subprocess.run(cmd).returncode
        summary = read_summary(run_dir)
        first = summary.get("first_iceberg")
        if summary["parameters"]["H"] != H:
            sys.exit(f"sweep_sliding_block.py: the run resolved H = {summary['parameters']['H']}, the models use {H}")
        linear, cantilever, shear = model_lengths(model_inputs(scene), r)
        if rc == 0 and first:
            status, L_H, t = "iceberg", first["length"] / H, first["time"]
        else:
            # No iceberg: report the overhang reached (ice front beyond the bed edge, where the front starts)
            # as a lower bound.
            front = read_csv(os.path.join(run_dir, "probes.csv"))["ice_front"]
            overhang = float(front.max() - front[0])
            status = "no_failure" if rc == 0 else f"exit_{rc}"
            if rc == 0 and glacier_shortening(run_dir) > 0.25 * H:
                # The intact slab got shorter without an iceberg: the overhang broke into pieces smaller than
                # output.icebergs.min_cells (debris).
                status = "debris_no_iceberg"
            L_H, t = overhang / H, summary["sim_time"]
        crack = (first or {}).get("crack_start") or {}
        par = summary["parameters"]
        print(f"D/H = {r:g}: {status}, L/H = {L_H:.3f} (linear model {linear:.3f}, cantilever {cantilever:.3f},"
              f" shear model {shear:.3f}), crack starts in {crack.get('mode', '-')}, t = {t:.1f} s,"
              f" wall {summary['wall_time']:.0f} s", flush=True)
        row = {"D_over_H": r, "L_over_H": L_H, "status": status, "time": t, "model_linear": linear,
               "model_cantilever": cantilever, "model_shear": shear, "crack_mode": crack.get("mode", ""),
               "crack_time": crack.get("time", math.nan),
               "crack_x_over_H": (crack["x"] - par["x_edge"]) / H if crack else math.nan,
               "crack_z_over_H": (crack["y"] - par["z_bed"]) / H if crack else math.nan,
               "band_tension": ((first or {}).get("band_events") or {}).get("tension", ""),
               "band_shear": ((first or {}).get("band_events") or {}).get("shear", ""),
               "wall_time": summary["wall_time"]}
        if args.crack_frames:
            row["crack_overhang_over_H"] = crack_overhang(run_dir, scene, summary["parameters"])
            print(f"D/H = {r:g}: crack starts at an overhang of {row['crack_overhang_over_H']:.3f} H", flush=True)
        return row

    # --jobs runs that many cases at once (each with --threads 1 unless --threads is given): on 2 cores,
    # two single-threaded runs use the machine better than one two-threaded run at a time.
    if args.jobs > 1 and not args.threads:
        args.threads = 1
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        # Highest D/H first: the runs near neutral buoyancy are the long ones (they go on to an overhang of 5H),
        # and starting them first keeps both jobs busy to the end.
        rows = sorted(pool.map(run, sorted(args.ratios, reverse=True)), key=lambda row: row["D_over_H"])
    json.dump(model_inputs(scene), open(os.path.join(args.out, "sliding_block_sweep.json"), "w"), indent=1)
    path = os.path.join(args.out, "sliding_block_sweep.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    fig, ax = plt.subplots(figsize=(6, 4))
    d = np.linspace(0, 0.99, 200)
    lin = [models(scene, x)[0] for x in d]
    can = [models(scene, x)[1] for x in d]
    ax.plot(d, lin, "k-", label="linear model 2σt/[3ρi g H(1-D/H)]")
    ax.plot(d, can, "k--", label="cantilever with buoyancy")
    ax.plot(d, [model_lengths(model_inputs(scene), x)[2] for x in d], "k:", label="shear model 2τs/[3ρi g H(1-D/H)]")
    for status, marker, label in (("iceberg", "o", ""), ("no_failure", "^", " (no failure: overhang reached)"),
                                  ("debris_no_iceberg", "x", " (broke into debris: overhang reached)")):
        pts = [(row["D_over_H"], row["L_over_H"]) for row in rows if row["status"] == status]
        if pts:
            ax.plot(*zip(*pts), marker, label="cdmpm" + label)
    if args.crack_frames:
        pts = [(row["D_over_H"], row["crack_overhang_over_H"]) for row in rows if row["status"] == "iceberg"]
        if pts:
            ax.plot(*zip(*pts), "s", mfc="none", label="cdmpm, overhang where the crack starts")
    ax.set_xlabel("D/H")
    ax.set_ylabel("L/H")
    ax.set_ylim(0, 8)
    ax.legend(fontsize=8)
    ax.set_title(f"sliding block, H/dx = {args.cells_per_H}" + "".join(f", {x}" for x in args.set), fontsize=9)
    print(path)
    print(save_figure(fig, os.path.join(args.out, "sliding_block_sweep.png"), dpi=120))


if __name__ == "__main__":
    sys.exit(main())
