#!/bin/sh
# resume_on_ranks.sh - a distributed run stopped at a checkpoint and resumed on another number of ranks ends with
# the files of one process's straight run, byte for byte (docs/architecture.md; the keys of the resumed particles
# are their order in the checkpoint, which is the one-process array).
#
# usage: resume_on_ranks.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR FIRST_RANKS THEN_RANKS T_STOP T_END [--set ...]
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 first=$5 then=$6 stop=$7 end=$8
shift 8
[ -x "$serial" ] || { echo "no program without MPI at $serial (configure and build one: cmake -S . -B build)"; exit 1; }
run="${MPIRUN:-mpirun} --oversubscribe --allow-run-as-root"
rm -rf "$work"
mkdir -p "$work"
"$serial" run "$scene" --out "$work/straight" --quiet --threads 1 --set time.end="$end" "$@" > /dev/null
$run -np "$first" "$mpi" run "$scene" --out "$work/resumed" --quiet --threads 1 --set time.end="$stop" "$@" > /dev/null
$run -np "$then" "$mpi" run --resume "$work/resumed" --quiet --threads 1 --set time.end="$end" > /dev/null
status=0
# scene.resolved.json records the first part's time.end, as in one process's resumed runs.
for f in $(cd "$work/straight" && ls | grep -v -e '^run\.json$' -e '^summary\.json$' -e '^scene\.resolved\.json$'); do
  cmp -s "$work/straight/$f" "$work/resumed/$f" || { echo "$f differs from the straight run's"; status=1; }
done
[ $status -eq 0 ] && echo "np $first to t = $stop, resumed on np $then to t = $end: the straight one-process run's files"
exit $status
