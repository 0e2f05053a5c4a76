#!/usr/bin/python3
"""test_ensemble.py - tests of tools/ensemble (docs/ensembles.md) on tiny members: the calving front at dx = 20 m
for a few seconds of simulated time, and the 3D dam break at its coarsest.

    /usr/bin/python3 tests/tools/test_ensemble.py --cdmpm PATH [--work DIR] [--keep] [-k NAME]

Each test prints PASS or FAIL with the reason; the last line is "N passed, M failed" (exit status 1 if any
failed). Tests: bad specs refused (exit 2, one line naming the spec and the key, nothing written); the member
list a pure function of the spec; a member rerun alone gives its bits; pool 1 and pool 2 give the same products;
SIGKILL mid-way then rerun: finished members not rerun, the same products; calibration against one member's own
outputs; the Slurm array script run as Slurm runs it (and through a real Slurm when `sinfo` answers); the 3D
percentile and exceedance rasters against a direct computation, with the members' georeference and CRS (and
GDAL's reading of them when gdalinfo is installed); Ctrl-C (SIGINT) stops the pool with checkpoints and exit 130.
"""
import argparse
import filecmp
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import warnings

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "tools", "ensemble")
sys.path.insert(0, os.path.join(ROOT, "tools"))
from cdmpm_tools.io import read_asc, read_csv  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from harness import TESTS, Failure, check, test  # noqa: E402

import numpy as np  # noqa: E402

CALVING = os.path.join(ROOT, "scenes", "calving_front_2d.json")
# Tiny calving members: dx = 20 m, to t = 14 s (the first crest passes the 200 m gauge at about 12 s), a
# checkpoint every simulated second, no frames: about a second each on one core.
TINY_SET = ["parameters.dx=20", "time.end=14", "output.frames=false", "time.frame_interval=1",
            "output.checkpoint_every=1"]
PRODUCTS = ["members.csv", "gauges_bands.csv", "hazard_bands.csv", "plots/gauges.png", "plots/hazard_profile.png",
            "plots/icebergs.png"]
MEMBER_FILES = ["probes.csv", "waves.csv", "hazard.csv", "icebergs.csv"]

ARGS = None


def work(name):
    d = os.path.join(ARGS.work, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def write_spec(folder, name, spec):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        json.dump(spec, f, indent=1)
    return path


def tiny_spec(members=6, **extra):
    spec = {"scene": CALVING, "set": list(TINY_SET), "members": members, "seed": 11,
            "vary": {"materials.ice.tensile_strength": {"range": [1.5e5, 1.0e6], "scale": "log"},
                     "parameters.notch_depth": {"range": [40, 80]},
                     "parameters.notch_height": {"values": [40, 55]}},
            "thresholds": [0.5, 2]}
    spec.update(extra)
    return spec


def ensemble(*args, **kw):
    return subprocess.run(["/usr/bin/python3", TOOL, *args], capture_output=True, text=True, **kw)


def run_ensemble(spec_path, out, *more):
    r = ensemble("run", spec_path, "--out", out, "--cdmpm", ARGS.cdmpm, *more)
    check(r.returncode == 0, f"ensemble run {spec_path} exited {r.returncode}: {r.stderr.strip()[-400:]}")
    return r


def same_files(a, b, names):
    for n in names:
        pa, pb = os.path.join(a, n), os.path.join(b, n)
        check(os.path.isfile(pa) and os.path.isfile(pb), f"{n} missing in {a} or {b}")
        check(filecmp.cmp(pa, pb, shallow=False), f"{n} differs between {a} and {b}")


_reference = {}


def reference():
    """The uninterrupted tiny ensemble on a pool of 2 (run once, shared by the tests that compare with it)."""
    if "out" not in _reference:
        d = work("reference")
        obs = os.path.join(d, "observed_200m.csv")
        with open(obs, "w") as f:
            f.write("time,gauge_200m\n" + "".join(f"{t},{0.5 * math.sin(t)}\n" for t in range(15)))
        spec = write_spec(d, "tiny.json", tiny_spec(observations={"gauge_200m": obs}))
        run_ensemble(spec, os.path.join(d, "out"), "--pool", "2")
        _reference.update(out=os.path.join(d, "out"), spec=spec)
    return _reference["out"], _reference["spec"]


# ------------------------------------------------------------------------------------------------------ tests
@test
def bad_specs_refused():
    d = work("bad_specs")
    good = tiny_spec(members=2)
    cases = [
        ("unknown_path", {"vary": {"materials.ice.strength": {"range": [1e5, 1e6]}}}, "vary.materials.ice.strength"),
        ("no_such_parameter", {"vary": {"parameters.notch_width": {"range": [1, 2]}}}, "vary.parameters.notch_width"),
        ("empty_range", {"vary": {"parameters.notch_depth": {"range": [50, 50]}}}, "vary.parameters.notch_depth.range"),
        ("reversed_range", {"vary": {"parameters.notch_depth": {"range": [80, 40]}}}, "vary.parameters.notch_depth.range"),
        ("zero_members", {"members": 0}, "members"),
        ("unknown_spec_key", {"memberz": 3}, "memberz"),
        ("log_of_zero", {"vary": {"parameters.notch_depth": {"range": [0, 40], "scale": "log"}}},
         "vary.parameters.notch_depth.range"),
        ("bad_value", {"vary": {"materials.ice.tensile_strength": {"values": [1e6, -5]}}},
         "vary.materials.ice.tensile_strength"),
        ("bad_base_set", {"set": TINY_SET + ["materials.glass.density=1"]}, "set"),
        ("empty_vary", {"vary": {}}, "vary"),
        ("bad_threshold", {"thresholds": [0]}, "thresholds"),
        ("no_scene", {"scene": "scenes/nowhere.json"}, "scene"),
        ("cross_not_multiple", {"lists": "cross", "members": 3}, "members"),
        ("observations_missing", {"observations": {"gauge_200m": "nowhere.csv"}}, "observations.gauge_200m"),
        ("observations_no_column", {"observations": {"gauge_200m": CALVING}}, "observations.gauge_200m"),
    ]
    for name, change, key in cases:
        spec = dict(good)
        spec.update(change)
        path = write_spec(d, f"{name}.json", spec)
        for sub in ("check", "run"):
            out = os.path.join(d, f"out_{name}")
            extra = ["--out", out] if sub == "run" else []
            r = ensemble(sub, path, "--cdmpm", ARGS.cdmpm, *extra)
            lines = r.stderr.strip().splitlines()
            check(r.returncode == 2, f"{name}: {sub} exited {r.returncode}, expected 2 ({r.stderr.strip()})")
            check(len(lines) == 1, f"{name}: {sub}: expected one line on stderr, got {lines}")
            check(lines[0].startswith(f"ensemble: {path}: {key}:"),
                  f"{name}: {sub}: expected 'ensemble: {path}: {key}: ...', got {lines[0]}")
            check("Traceback" not in r.stderr, f"{name}: a traceback")
            check(not os.path.exists(out), f"{name}: {sub} wrote {out}")
    with open(os.path.join(d, "not_json.json"), "w") as f:
        f.write("{\"members\": 2,")
    r = ensemble("check", os.path.join(d, "not_json.json"), "--cdmpm", ARGS.cdmpm)
    check(r.returncode == 2 and "not valid JSON" in r.stderr and len(r.stderr.strip().splitlines()) == 1,
          f"a spec that is not JSON: exit {r.returncode}, {r.stderr.strip()}")


@test
def check_prints_members_and_cost():
    d = work("check")
    path = write_spec(d, "tiny.json", tiny_spec())
    r = ensemble("check", path, "--cdmpm", ARGS.cdmpm)
    check(r.returncode == 0, f"check exited {r.returncode}: {r.stderr}")
    rows = [ln for ln in r.stdout.splitlines() if ln.startswith("  00")]
    check(len(rows) == 6, f"expected one line per member (6), got {len(rows)}")
    check("estimated cost" in r.stdout, "no estimated cost line")


@test
def member_list_is_a_pure_function_of_the_spec():
    d = work("sampling")
    spec = tiny_spec(members=10, seed=5, vary={
        "materials.ice.tensile_strength": {"range": [1e5, 1e6], "scale": "log"},
        "parameters.notch_depth": {"range": [40, 80]},
        "parameters.notch_height": {"values": [40, 50, 60], },
        "parameters.H": {"values": [110, 120]}}, lists="cross")
    spec["members"] = 12
    outs = []
    for k in range(2):
        path = write_spec(d, f"s{k}.json", spec)
        out = os.path.join(d, f"out{k}")
        r = ensemble("run", path, "--out", out, "--cdmpm", ARGS.cdmpm, "--slurm")
        check(r.returncode == 0, f"run --slurm exited {r.returncode}: {r.stderr}")
        with open(os.path.join(out, "ensemble.json")) as f:
            outs.append(json.load(f)["members"])
    check(outs[0] == outs[1], "two writes of the same spec give different member lists")
    members = outs[0]
    n = len(members)
    for key, (lo, hi), log in (("materials.ice.tensile_strength", (1e5, 1e6), True),
                               ("parameters.notch_depth", (40, 80), False)):
        v = np.array([m["values"][key] for m in members])
        x = (np.log(v) - math.log(lo)) / (math.log(hi) - math.log(lo)) if log else (v - lo) / (hi - lo)
        strata = np.sort(np.floor(x * n).astype(int))
        check(list(strata) == list(range(n)), f"{key}: not one member per stratum of the Latin hypercube: {strata}")
    combos = sorted((m["values"]["parameters.notch_height"], m["values"]["parameters.H"]) for m in members)
    expected = sorted((a, b) for a in (40, 50, 60) for b in (110, 120)) * 2
    check(combos == sorted(expected), f"crossed lists: combinations {combos}")
    check([m["values"]["parameters.notch_height"] for m in members[:2]] == [40, 40], "cross: first key not slowest")
    spec["seed"] = 6
    path = write_spec(d, "s_other_seed.json", spec)
    r = ensemble("run", path, "--out", os.path.join(d, "out_other"), "--cdmpm", ARGS.cdmpm, "--slurm")
    with open(os.path.join(d, "out_other", "ensemble.json")) as f:
        other = json.load(f)["members"]
    check(other != members, "another seed gives the same members")


@test
def member_rerun_alone_gives_the_same_bits():
    out, _ = reference()
    mdir = os.path.join(out, "members", "0002")
    with open(os.path.join(mdir, "run.json")) as f:
        run = json.load(f)
    alone = os.path.join(work("alone"), "member")
    cmd = [ARGS.cdmpm, "run", run["scene_file"], "--out", alone, "--quiet", "--threads", "2"]
    for s in run["overrides"]:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == 0, f"rerun alone exited {r.returncode}: {r.stderr}")
    same_files(mdir, alone, MEMBER_FILES)


@test
def products_same_bits_for_pool_1_and_2():
    out2, spec = reference()
    out1 = os.path.join(work("pool1"), "out")
    run_ensemble(spec, out1, "--pool", "1")
    same_files(out1, out2, PRODUCTS)
    for m in range(6):
        same_files(os.path.join(out1, "members", f"{m:04d}"), os.path.join(out2, "members", f"{m:04d}"), MEMBER_FILES)
    t = read_csv(os.path.join(out2, "members.csv"))
    check(list(t["status"]) == ["completed"] * 6, f"statuses {list(t['status'])}")
    check(np.isfinite(t["gauge_200m_arrival"]).any(), "no member's first crest reached the 200 m gauge")
    check(np.isfinite(t["iceberg_failure_width"]).any(), "no member calved")


def wait_for(cond, timeout, what):
    t0 = time.monotonic()
    while not cond():
        if time.monotonic() - t0 > timeout:
            raise Failure(f"timed out waiting for {what}")
        time.sleep(0.02)


def summary_status(mdir):
    try:
        with open(os.path.join(mdir, "summary.json")) as f:
            return json.load(f).get("status")
    except (OSError, ValueError):
        return None


def kill_and_resume(name, kill_members_too):
    ref, spec = reference()
    out = os.path.join(work(name), "out")
    p = subprocess.Popen(["/usr/bin/python3", TOOL, "run", spec, "--out", out, "--cdmpm", ARGS.cdmpm, "--pool", "1"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    m0, m1 = os.path.join(out, "members", "0000"), os.path.join(out, "members", "0001")
    wait_for(lambda: summary_status(m0) == "completed", 120, "member 0 to complete")
    wait_for(lambda: os.path.isfile(os.path.join(m1, "checkpoint.bin")), 120, "member 1's first checkpoint")
    cdmpm_pids = []
    if kill_members_too:
        r = subprocess.run(["pgrep", "-f", "--", f"--out {m1}"], capture_output=True, text=True)
        cdmpm_pids = [int(x) for x in r.stdout.split()]
    p.send_signal(signal.SIGKILL)
    for pid in cdmpm_pids:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    p.wait()
    check(p.returncode == -signal.SIGKILL, f"the ensemble ended by itself ({p.returncode}) before the kill")
    check(summary_status(m1) != "completed", "member 1 had completed before the kill: no member was mid-way")
    stamp = os.stat(os.path.join(m0, "summary.json")).st_mtime_ns
    with open(os.path.join(m0, "cdmpm.log")) as f:
        log0 = f.read()
    r = run_ensemble(spec, out, "--pool", "1")
    check(os.stat(os.path.join(m0, "summary.json")).st_mtime_ns == stamp, "finished member 0 was rerun")
    with open(os.path.join(m0, "cdmpm.log")) as f:
        check(f.read() == log0, "member 0's log changed: it was rerun")
    with open(os.path.join(m1, "cdmpm.log")) as f:
        log1 = f.read()
    check("run --resume" in log1, f"member 1 was not resumed from its checkpoint: {log1}")
    check("0 finished" not in r.stdout and "1 to resume" in r.stdout, f"second call's plan: {r.stdout.splitlines()[:4]}")
    same_files(out, ref, PRODUCTS)
    for m in range(6):
        same_files(os.path.join(out, "members", f"{m:04d}"), os.path.join(ref, "members", f"{m:04d}"), MEMBER_FILES)


@test
def sigkill_mid_way_then_rerun_gives_the_same_products():
    kill_and_resume("sigkill", kill_members_too=False)


@test
def sigkill_with_its_members_then_rerun_gives_the_same_products():
    kill_and_resume("sigkill_all", kill_members_too=True)


@test
def ctrl_c_stops_the_pool_with_checkpoints():
    _, spec = reference()
    out = os.path.join(work("sigint"), "out")
    p = subprocess.Popen(["/usr/bin/python3", TOOL, "run", spec, "--out", out, "--cdmpm", ARGS.cdmpm, "--pool", "2"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    m0 = os.path.join(out, "members", "0000")
    wait_for(lambda: os.path.isfile(os.path.join(m0, "checkpoint.bin")), 120, "member 0's first checkpoint")
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)
    check(p.returncode == 130, f"exit {p.returncode} after SIGINT, expected 130 ({err.strip()})")
    statuses = [summary_status(os.path.join(out, "members", f"{m:04d}")) for m in range(6)]
    check("interrupted" in statuses, f"no member interrupted: {statuses}")
    check(None in statuses, f"members kept starting after SIGINT: {statuses}")
    check(not os.path.exists(os.path.join(out, "members.csv")), "aggregated although interrupted")


@test
def calibration_finds_the_synthetic_truth():
    ref, _ = reference()
    d = work("calibration")
    t = read_csv(os.path.join(ref, "members.csv"))
    # The truth: the member that calved with the smallest index; targets: its failure width and its first
    # crest's arrival at the 200 m gauge, each within 0.1 %.
    truth = int(next(k for k in range(len(t["member"])) if np.isfinite(t["iceberg_failure_width"][k])
                     and np.isfinite(t["gauge_200m_arrival"][k])))
    used = ["iceberg_failure_width", "gauge_200m_arrival"]
    targets = {"targets": [{"quantity": q, "observed": float(t[q][truth]), "sigma": 1e-3 * abs(float(t[q][truth]))}
                           for q in used], "n_sigma": 1,
               "compare": [{"quantity": "gauge_200m_amplitude", "label": "first crest at 200 m [m]",
                            "observed": [0.01, 0.02], "paper": 0.015}]}
    tpath = write_spec(d, "targets.json", targets)
    out = os.path.join(d, "out")
    shutil.copytree(ref, out)
    r = ensemble("calibrate", out, tpath)
    check(r.returncode == 0, f"calibrate exited {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "calibration.json")) as f:
        cal = json.load(f)
    check(truth in cal["accepted"], f"member {truth} not accepted: {cal['accepted']}")
    check(cal["misfit"][str(truth)] == 0.0, f"its misfit is {cal['misfit'][str(truth)]}, not 0")
    check(cal["best"][0] == truth, f"the lowest misfit is member {cal['best'][0]}")
    check(cal["accepted_count"] < len(t["member"]), "every member accepted: the targets select nothing")
    for key, p in cal["parameters"].items():
        v = t[key][truth]
        check(p["accepted"][0] <= v <= p["accepted"][1], f"{key} = {v} outside the accepted range {p['accepted']}")
    checked = 0
    for q, e in cal["predicted"].items():
        check(q not in used, f"{q}, used for selection, is among the predictions")
        v = t[q][truth]
        if np.isfinite(v):
            a = e["accepted"]
            check(a["p5"] <= v <= a["p95"], f"{q} = {v} outside the predicted band [{a['p5']}, {a['p95']}]")
            checked += 1
    check(checked >= 5, f"only {checked} predicted quantities checked")
    # The comparison with the observations: the accepted band holds the truth's own value.
    (c,) = cal["compare"]
    v = float(t["gauge_200m_amplitude"][truth])
    check(c["accepted"]["n"] >= 1 and c["accepted"]["min"] <= v <= c["accepted"]["max"],
          f"compare: the accepted band {c['accepted']} misses the truth's {v}")
    check(c["prior"]["n"] >= c["accepted"]["n"], f"compare: fewer members overall than accepted: {c}")
    with open(os.path.join(out, "calibration.md")) as f:
        md = f.read()
    check("accepted" in md, "calibration.md without the accepted count")
    check("| first crest at 200 m [m] | 0.01-0.02 | 0.015 |" in md, "calibration.md without the comparison row")
    badc = write_spec(d, "bad_compare.json", dict(targets, compare=[{"quantity": "gauge_200m_amplitude",
                                                                     "paper": [2, 1]}]))
    r = ensemble("calibrate", out, badc)
    check(r.returncode == 2 and f"{badc}: compare.0.paper:" in r.stderr and len(r.stderr.strip().splitlines()) == 1,
          f"a reversed paper range: exit {r.returncode}, {r.stderr.strip()}")
    bad = write_spec(d, "bad_targets.json", {"targets": [{"quantity": "iceberg_colour", "observed": 1, "sigma": 1}]})
    r = ensemble("calibrate", out, bad)
    check(r.returncode == 2 and f"{bad}: targets.0.quantity:" in r.stderr and len(r.stderr.strip().splitlines()) == 1,
          f"an unknown target quantity: exit {r.returncode}, {r.stderr.strip()}")
    # An iceberg target where no member calved (the column absent from members.csv): none accepted, not an error.
    nocalve = os.path.join(d, "nocalve")
    shutil.copytree(ref, nocalve)
    t2 = read_csv(os.path.join(nocalve, "members.csv"))
    keep = [k for k in t2 if not k.startswith("iceberg_")]
    with open(os.path.join(nocalve, "members.csv"), "w") as f:
        f.write(",".join(keep) + "\n")
        for i in range(len(t2["member"])):
            f.write(",".join("" if isinstance(t2[k][i], float) and not np.isfinite(t2[k][i]) else str(t2[k][i])
                             for k in keep) + "\n")
    r = ensemble("calibrate", nocalve, tpath)
    check(r.returncode == 0, f"calibrate without any iceberg exited {r.returncode}: {r.stderr}")
    with open(os.path.join(nocalve, "calibration.json")) as f:
        check(json.load(f)["accepted_count"] == 0, "a member accepted on an iceberg no member made")


def slurm_up():
    if not shutil.which("sbatch") or not shutil.which("sinfo"):
        return False
    try:
        r = subprocess.run(["sinfo", "-h", "-o", "%a"], capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return r.returncode == 0 and "up" in r.stdout


@test
def slurm_array_tasks_give_the_same_members():
    ref, spec = reference()
    out = os.path.join(work("slurm_tasks"), "out")
    r = ensemble("run", spec, "--out", out, "--cdmpm", ARGS.cdmpm, "--slurm", "--sbatch=--time=00:10:00")
    check(r.returncode == 0, f"run --slurm exited {r.returncode}: {r.stderr}")
    array = os.path.join(out, "slurm", "array.sh")
    with open(array) as f:
        text = f.read()
    check("#SBATCH --array=0-5\n" in text, "array.sh has no --array=0-5")
    check("#SBATCH --time=00:10:00\n" in text, "array.sh lacks the --sbatch option")
    check(not os.path.exists(os.path.join(out, "members", "0000", "summary.json")), "--slurm ran members")
    for k in range(6):
        env = dict(os.environ, SLURM_ARRAY_TASK_ID=str(k), SLURM_JOB_ID="1", SLURM_ARRAY_JOB_ID="1")
        r = subprocess.run(["bash", array], env=env, capture_output=True, text=True)
        check(r.returncode == 0, f"array task {k} exited {r.returncode}: {r.stderr}")
    r = subprocess.run(["bash", os.path.join(out, "slurm", "aggregate.sh")], capture_output=True, text=True)
    check(r.returncode == 0, f"aggregate.sh exited {r.returncode}: {r.stderr}")
    for m in range(6):
        same_files(os.path.join(out, "members", f"{m:04d}"), os.path.join(ref, "members", f"{m:04d}"), MEMBER_FILES)
    same_files(out, ref, PRODUCTS)
    env = dict(os.environ, SLURM_ARRAY_TASK_ID="0")
    r = subprocess.run(["bash", array], env=env, capture_output=True, text=True)
    check(r.returncode == 0 and "nothing to do" in r.stdout, f"a finished member's task reran it: {r.stdout}")


@test
def slurm_tasks_with_ranks_run_under_the_launcher():
    ref, spec = reference()
    out = os.path.join(work("slurm_launcher"), "out")
    # A launcher is any command that runs the rest of the line (srun, mpirun -np N); env stands in for it here.
    r = ensemble("run", spec, "--out", out, "--cdmpm", ARGS.cdmpm, "--slurm", "--ranks", "3", "--threads", "2",
                 "--launcher", "env CDMPM_TEST_LAUNCHED=1", "--max-parallel", "2")
    check(r.returncode == 0, f"run --slurm --ranks 3 exited {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "slurm", "array.sh")) as f:
        text = f.read()
    for line in ("#SBATCH --array=0-5%2", "#SBATCH --ntasks=3", "#SBATCH --cpus-per-task=2"):
        check(line + "\n" in text, f"array.sh lacks {line}")
    r = subprocess.run(["bash", os.path.join(out, "slurm", "array.sh")], env=dict(os.environ, SLURM_ARRAY_TASK_ID="4"),
                       capture_output=True, text=True)
    check(r.returncode == 0, f"array task 4 exited {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "members", "0004", "cdmpm.log")) as f:
        first = f.readline()
    check(first.startswith(f"$ env CDMPM_TEST_LAUNCHED=1 {ARGS.cdmpm} run ") and "--threads 2" in first,
          f"member 4 did not run under the launcher with 2 threads: {first}")
    same_files(os.path.join(out, "members", "0004"), os.path.join(ref, "members", "0004"), MEMBER_FILES)
    r = ensemble("run", spec, "--out", os.path.join(out, "x"), "--cdmpm", ARGS.cdmpm, "--ranks", "2")
    check(r.returncode == 2 and "--ranks: only with --slurm" in r.stderr, f"--ranks without --slurm: {r.stderr}")


@test
def slurm_real_submission():
    if ARGS.start_slurm:
        r = subprocess.run(["bash", os.path.join(ROOT, "tests", "tools", "start_local_slurm.sh")],
                           capture_output=True, text=True)
        check(r.returncode == 0, f"start_local_slurm.sh failed: {r.stderr.strip()}")
    if not slurm_up():
        print("  (no Slurm controller answers sinfo: the submission through sbatch is not tested; "
              "--start-slurm starts one)")
        return "skip"
    ref, spec = reference()
    out = os.path.join(work("slurm_real"), "out")
    r = ensemble("run", spec, "--out", out, "--cdmpm", ARGS.cdmpm, "--slurm", "--submit")
    check(r.returncode == 0, f"run --slurm --submit exited {r.returncode}: {r.stderr}")
    wait_for(lambda: os.path.isfile(os.path.join(out, "plots", "icebergs.png")), 300, "the aggregation job")
    time.sleep(0.5)
    same_files(out, ref, PRODUCTS)
    for m in range(6):
        same_files(os.path.join(out, "members", f"{m:04d}"), os.path.join(ref, "members", f"{m:04d}"), MEMBER_FILES)


@test
def failed_and_unstable_members_are_recorded_and_the_others_go_on():
    d = work("failed")
    # Member 1 goes unstable (a horizontal gravity of 1000 m/s^2 throws the water out of the domain: cdmpm exit 3);
    # member 2's run fails (exit 1) through a wrapper of cdmpm that fails the runs with notch_depth 70.
    wrapper = os.path.join(d, "cdmpm_failing")
    with open(wrapper, "w") as f:
        f.write("#!/bin/bash\n"
                "if [ \"$1\" = run ]; then for a in \"$@\"; do if [ \"$a\" = parameters.notch_depth=70 ]; then\n"
                "  echo 'cdmpm: error: out of memory, allocating the grid' >&2; exit 1; fi; done; fi\n"
                f"exec {ARGS.cdmpm} \"$@\"\n")
    os.chmod(wrapper, 0o755)
    spec = tiny_spec(members=4, vary={"parameters.notch_depth": {"values": [50, 60, 70, 55]},
                                      "gravity.0": {"values": [0, 1000, 0, 0]}})
    spec["set"] = [s for s in TINY_SET if not s.startswith("time.end")] + ["time.end=3"]
    path = write_spec(d, "spec.json", spec)
    out = os.path.join(d, "out")
    r = ensemble("run", path, "--out", out, "--cdmpm", wrapper)
    check(os.path.isfile(os.path.join(out, "members.csv")), f"no members.csv ({r.stderr.strip()})")
    t = read_csv(os.path.join(out, "members.csv"))
    check(list(t["status"]) == ["completed", "unstable", "failed", "completed"], f"statuses {list(t['status'])}")
    check(r.returncode == 1, f"exit {r.returncode} with members not completed, expected 1")
    check(t["reason"][2] == "cdmpm: error: out of memory; allocating the grid", f"failed member's reason {t['reason'][2]}")
    check(t["reason"][1] != "" and t["reason"][0] == "", f"reasons {list(t['reason'])}")
    stamps = [os.stat(os.path.join(out, "members", f"{m:04d}", "cdmpm.log")).st_mtime_ns for m in range(4)]
    r = ensemble("run", path, "--out", out, "--cdmpm", ARGS.cdmpm)
    t = read_csv(os.path.join(out, "members.csv"))
    check(list(t["status"]) == ["completed", "unstable", "completed", "completed"],
          f"after the rerun: statuses {list(t['status'])}")
    check(r.returncode == 1, f"rerun: exit {r.returncode} with an unstable member, expected 1")
    after = [os.stat(os.path.join(out, "members", f"{m:04d}", "cdmpm.log")).st_mtime_ns for m in range(4)]
    check([a == b for a, b in zip(stamps, after)] == [True, True, False, True],
          "the rerun should run the failed member only")


@test
def rasters_3d_percentiles_and_georeference():
    d = work("rasters")
    spec = {"scene": os.path.join(ROOT, "scenes", "dam_break_3d.json"),
            "set": ["domain.dx=0.0142875", "output.frames=false",
                    'georeference={"easting":512345.5,"northing":7712345.25,"crs":"EPSG:32624"}'],
            "members": 5, "seed": 3, "vary": {"materials.water.bulk_modulus": {"range": [2e5, 8e5], "scale": "log"},
                                              "time.end": {"range": [0.04, 0.2]}},
            "thresholds": [0.005, 0.02]}
    path = write_spec(d, "dam3d.json", spec)
    out = os.path.join(d, "out")
    run_ensemble(path, out)
    members = [os.path.join(out, "members", f"{m:04d}") for m in range(5)]
    for q in ("max_elevation", "arrival_time", "inundation_depth"):
        stack = np.array([read_asc(os.path.join(m, f"{q}.asc"))[0] for m in members])
        if q == "arrival_time":
            stack = np.where(np.isnan(stack), np.inf, stack)
        head_lines = read_asc(os.path.join(members[0], f"{q}.asc"))[2]
        for p in (10, 50, 90):
            got, _, lines, _ = read_asc(os.path.join(out, "rasters", f"{q}_p{p}.asc"))
            check(lines == head_lines, f"{q}_p{p}.asc header {lines} != the members' {head_lines}")
            with np.errstate(invalid="ignore"), warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)  # all-NaN cells: NaN, as expected
                if q == "arrival_time":  # never reached: larger than any time (numpy's interpolation has no inf)
                    want = np.percentile(np.where(np.isinf(stack), 1e30, stack), p, axis=0)
                    want = np.where(want > 1e20, np.nan, want)
                else:
                    want = np.nanpercentile(stack, p, axis=0)
            check(np.array_equal(np.isnan(got), np.isnan(want)), f"{q}_p{p}: NODATA cells differ from numpy's")
            ok = np.isnan(want) | (np.abs(got - want) <= 1e-9 * np.maximum(1.0, np.abs(want)))
            check(ok.all(), f"{q}_p{p}: differs from numpy's percentile in {int((~ok).sum())} cells")
        check(np.isfinite(stack).any(), f"{q}: every cell undefined: nothing tested")
        if q == "arrival_time":
            check((np.isfinite(stack).any(axis=0) & np.isinf(stack).any(axis=0)).any(),
                  "no cell reached in some members only: the never-reached rule is not tested")
    elev = np.array([read_asc(os.path.join(m, "inundation_depth.asc"))[0] for m in members])
    for t in (0.005, 0.02):
        got = read_asc(os.path.join(out, "rasters", f"p_depth_exceed_{t:g}m.asc"))[0]
        with np.errstate(invalid="ignore"):
            want = (elev > t).mean(axis=0)
        check(np.allclose(got, want), f"p_depth_exceed_{t:g}m differs from the direct count")
    depth_any = read_asc(os.path.join(out, "rasters", "p_depth_exceed_0.005m.asc"))[0]
    check(((depth_any > 0) & (depth_any < 1)).any() or (depth_any == 1).any(), "no cell ever inundated: nothing tested")
    if shutil.which("gdalinfo"):
        info = subprocess.run(["gdalinfo", "-json", os.path.join(out, "rasters", "max_elevation_p50.asc")],
                              capture_output=True, text=True)
        ref = subprocess.run(["gdalinfo", "-json", os.path.join(members[0], "max_elevation.asc")],
                             capture_output=True, text=True)
        check(info.returncode == 0, f"gdalinfo cannot open the raster: {info.stderr}")
        a, b = json.loads(info.stdout), json.loads(ref.stdout)
        check(a["geoTransform"] == b["geoTransform"] and a["size"] == b["size"],
              f"GDAL reads {a['geoTransform']} {a['size']}, the member's {b['geoTransform']} {b['size']}")
        check(a["geoTransform"][0] == 512345.5 and a["geoTransform"][1] == 0.0142875,
              f"GDAL's origin and cell size {a['geoTransform']}, expected the scene's easting 512345.5 and dx")
        # The members' CRS beside the raster (their .prj), as GDAL reads it.
        check("UTM zone 24N" in a.get("coordinateSystem", {}).get("wkt", ""),
              f"GDAL reads no UTM zone 24N CRS for max_elevation_p50.asc: {a.get('coordinateSystem')}")
    else:
        print("  (gdalinfo not installed: the GDAL reading is not tested)")


def main():
    global ARGS
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cdmpm", default=os.path.join(ROOT, "build", "cdmpm"), help="the cdmpm program")
    ap.add_argument("--work", help="work folder (default: a new temporary folder, removed unless --keep)")
    ap.add_argument("--keep", action="store_true", help="keep the work folder")
    ap.add_argument("--start-slurm", action="store_true",
                    help="start a single-node Slurm first (tests/tools/start_local_slurm.sh: root, apt)")
    ap.add_argument("-k", dest="only", action="append", default=[], help="run only tests whose name contains this")
    ARGS = ap.parse_args()
    ARGS.cdmpm = os.path.abspath(ARGS.cdmpm)
    if not os.access(ARGS.cdmpm, os.X_OK):
        print(f"test_ensemble: --cdmpm: {ARGS.cdmpm}: no such program", file=sys.stderr)
        sys.exit(2)
    temporary = ARGS.work is None
    ARGS.work = os.path.abspath(ARGS.work or tempfile.mkdtemp(prefix="test_ensemble_"))
    passed = failed = skipped = 0
    t_all = time.monotonic()
    for fn in TESTS:
        if ARGS.only and not any(o in fn.__name__ for o in ARGS.only):
            continue
        t0 = time.monotonic()
        try:
            result = fn()
        except Failure as e:
            failed += 1
            print(f"FAIL {fn.__name__} ({time.monotonic() - t0:.1f} s): {e}", flush=True)
            continue
        if result == "skip":
            skipped += 1
            print(f"SKIP {fn.__name__}", flush=True)
        else:
            passed += 1
            print(f"PASS {fn.__name__} ({time.monotonic() - t0:.1f} s)", flush=True)
    if temporary and not ARGS.keep and not failed:
        shutil.rmtree(ARGS.work, ignore_errors=True)
    else:
        print(f"work folder: {ARGS.work}")
    print(f"({skipped} skipped, {time.monotonic() - t_all:.0f} s)")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
