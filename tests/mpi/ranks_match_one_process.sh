#!/bin/sh
# ranks_match_one_process.sh - a distributed run gives the files of one process (docs/architecture.md).
#
# usage: ranks_match_one_process.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR "RANKS" [--set key=value ...]
# Runs SCENE once with SERIAL_CDMPM (a build without MPI) and then with `mpirun -np N MPI_CDMPM` for every N in
# RANKS (oversubscribed: more ranks than cores), one OpenMP thread each, frames gathered into one .vtu
# (--gather-output), and requires every output file of the
# one-process run except run.json and summary.json (command line, wall times) to be byte-identical in every
# distributed run: probes.csv, every frame particles_NNNN.vtu and particles.pvd, the checkpoint, the hazard
# products. Exit code 0 if all match, 1 otherwise (the first difference is named).
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 ranks=$5
shift 5
[ -x "$serial" ] || { echo "no program without MPI at $serial (configure and build one: cmake -S . -B build)"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
"$serial" run "$scene" --out "$work/one" --quiet --threads 1 "$@" > /dev/null
files=$(cd "$work/one" && ls | grep -v -e '^run\.json$' -e '^summary\.json$')
[ -n "$files" ] || { echo "the one-process run wrote nothing"; exit 1; }
status=0
for n in $ranks; do
  "${MPIRUN:-mpirun}" -np "$n" --oversubscribe --allow-run-as-root "$mpi" run "$scene" --out "$work/np$n" --quiet --threads 1 --gather-output "$@" > /dev/null
  for f in $files; do
    if ! cmp -s "$work/one/$f" "$work/np$n/$f"; then
      echo "np $n: $f differs from the one-process run's: $(cmp "$work/one/$f" "$work/np$n/$f" 2>&1 | head -1)"
      status=1
    fi
  done
  [ $status -eq 0 ] && echo "np $n: $(echo $files | wc -w) files byte-identical to the one-process run's"
done
exit $status
