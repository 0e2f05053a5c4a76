#!/bin/sh
# pieces_match_one_process.sh - a distributed run's frames, written as per-rank .vtu pieces under one .pvtu per
# frame (listed in particles.pvd), hold one process's particle state bit for bit (tools/same_particles.py: every
# array of the particles sorted by id), at the same times; every other file of one process's run (probes.csv, the
# hazard products, ...) is byte-identical (docs/architecture.md). Not checkpoint.bin, which lists the
# frames written, here the .pvtu files (the rank-count tests compare it byte for byte with --gather-output).
#
# usage: pieces_match_one_process.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR "RANKS" [--set key=value ...]
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 ranks=$5
shift 5
[ -x "$serial" ] || { echo "no program without MPI at $serial (configure and build one: cmake -S . -B build)"; exit 1; }
tools=$(cd "$(dirname "$0")/../../tools" && pwd)
rm -rf "$work"
mkdir -p "$work"
"$serial" run "$scene" --out "$work/one" --quiet --threads 1 "$@" > /dev/null
frames=$(cd "$work/one" && ls particles_*.vtu)
[ -n "$frames" ] || { echo "the one-process run wrote no frame"; exit 1; }
files=$(cd "$work/one" && ls | grep -v -e '^run\.json$' -e '^summary\.json$' -e '^particles' -e '^checkpoint\.bin$')
status=0
for n in $ranks; do
  "${MPIRUN:-mpirun}" -np "$n" --oversubscribe --allow-run-as-root "$mpi" run "$scene" --out "$work/np$n" --quiet --threads 1 "$@" > /dev/null
  for f in $files; do
    cmp -s "$work/one/$f" "$work/np$n/$f" || { echo "np $n: $f differs from the one-process run's"; status=1; }
  done
  pairs=""
  for f in $frames; do
    p=${f%.vtu}.pvtu
    [ -f "$work/np$n/$p" ] || { echo "np $n: no $p"; status=1; continue; }
    [ "$(ls "$work/np$n/${f%.vtu}"_r*.vtu | wc -l)" -eq "$n" ] || { echo "np $n: not $n pieces for $p"; status=1; }
    pairs="$pairs $work/one/$f $work/np$n/$p"
  done
  /usr/bin/python3 "$tools/same_particles.py" $pairs > "$work/np$n.same" || { grep differ "$work/np$n.same"; status=1; }
  # particles.pvd: the same times, the .pvtu files for the .vtu files.
  sed 's/\.vtu"/.pvtu"/' "$work/one/particles.pvd" | cmp -s - "$work/np$n/particles.pvd" ||
    { echo "np $n: particles.pvd does not list the one-process frames' times and .pvtu files"; status=1; }
  [ $status -eq 0 ] && echo "np $n: $(echo $frames | wc -w) frames of $n pieces hold the one-process particle state; $(echo $files | wc -w) other files byte-identical"
done
exit $status
