#!/bin/sh
# dry_run_matches_run.sh - `cdmpm run --dry-run --ranks N` (run/run_plan.h) against a distributed run of one step on
# N ranks: every rank's particles as planned, exactly (summary.json distributed.particles_per_rank: no particle
# crosses a block in the first step of a scene at rest); rank 0's halo bytes of that step equal to the planned
# patches, velocities and mirror-zone blocks when EXACT_HALO is 1, at least those otherwise (a well-balanced bed's
# layer adds its ghost nodes and a second scatter, which the plan does not count).
#
# usage: dry_run_matches_run.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR RANKS EXACT_HALO [--set key=value ...]
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 ranks=$5 exact=$6
shift 6
rm -rf "$work"
mkdir -p "$work"
"$serial" run "$scene" --dry-run --ranks "$ranks" "$@" > "$work/plan.json"
"${MPIRUN:-mpirun}" --allow-run-as-root --oversubscribe -np "$ranks" "$mpi" run "$scene" --out "$work/run" --quiet --threads 1 \
  --steps 1 "$@"
/usr/bin/python3 - "$work/plan.json" "$work/run/summary.json" "$exact" <<'PY'
import json, sys
plan = json.load(open(sys.argv[1]))
run = json.load(open(sys.argv[2]))
exact = sys.argv[3] == "1"
planned = [r["particles"] for r in plan["per_rank"]]
measured = [int(n) for n in run["distributed"]["particles_per_rank"]]
print("particles per rank: planned", planned, "run", measured)
if planned != measured:
    sys.exit("the dry run's partition is not the run's")
halo_plan = plan["per_rank"][0]["halo_bytes_per_step"]
halo_run = run["distributed"]["rank0_halo_bytes"] / run["steps"]
print("rank 0 halo bytes per step: planned %d, run %d" % (halo_plan, halo_run))
if halo_run < halo_plan or (exact and halo_run != halo_plan):
    sys.exit("rank 0's halo bytes differ from the plan's")
PY
