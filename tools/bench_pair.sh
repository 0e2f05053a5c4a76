#!/bin/bash
# bench_pair.sh - A/B of two benchmark binaries on a shared host: A and B run at the same time, one per core
# (taskset), one thread each, swapping cores between repetitions, so that both see the same host. Prints per
# case the medians and the median and range of the ratios B/A (docs/performance.md).
#   bash tools/bench_pair.sh FILTER REPS BENCH_A BENCH_B      e.g. bash tools/bench_pair.sh 'ice2d/1' 4 old new
# Cases run at the issue's sizes (CDMPM_BENCH_PARTICLES=issue).
set -euo pipefail
if [ $# -ne 4 ]; then echo "usage: bash tools/bench_pair.sh FILTER REPS BENCH_A BENCH_B" >&2; exit 2; fi
filter=$1; reps=$2; A=$3; B=$4
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
for r in $(seq "$reps"); do
  if (( r % 2 )); then ca=0; cb=1; else ca=1; cb=0; fi
  OMP_NUM_THREADS=1 CDMPM_BENCH_PARTICLES=issue taskset -c $ca "$A" --benchmark_filter="$filter" --benchmark_min_time=1 --benchmark_format=json 2>/dev/null > "$out/A.$r.json" &
  OMP_NUM_THREADS=1 CDMPM_BENCH_PARTICLES=issue taskset -c $cb "$B" --benchmark_filter="$filter" --benchmark_min_time=1 --benchmark_format=json 2>/dev/null > "$out/B.$r.json" &
  wait
done
/usr/bin/python3 - "$reps" "$out" <<'PY'
import json, statistics, sys
reps, out = int(sys.argv[1]), sys.argv[2]
res = {}
for r in range(1, reps + 1):
    a = {x['name']: x['particle_steps_per_second'] for x in json.load(open(f'{out}/A.{r}.json'))['benchmarks']}
    b = {x['name']: x['particle_steps_per_second'] for x in json.load(open(f'{out}/B.{r}.json'))['benchmarks']}
    for n in a:
        res.setdefault(n, []).append((a[n], b[n]))
for n, v in res.items():
    ratios = [y / x for x, y in v]
    print(f"{n}: A {statistics.median(x for x, _ in v) / 1e6:.2f}M  B {statistics.median(y for _, y in v) / 1e6:.2f}M  "
          f"B/A median {statistics.median(ratios):.3f} [{min(ratios):.3f}-{max(ratios):.3f}]")
PY
