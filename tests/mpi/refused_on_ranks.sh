#!/bin/sh
# refused_on_ranks.sh - a scene that one process runs but a distributed run cannot (ice with `contact`: the solids'
# own field, sim/field_contact.h, is not in the halo exchange) is refused on RANKS ranks with exit code 2, a message
# containing EXPECTED, and no output folder written.
#
# usage: refused_on_ranks.sh MPI_CDMPM SCENE WORK_DIR RANKS EXPECTED [--set ...]
set -eu
mpi=$1 scene=$2 work=$3 ranks=$4 expected=$5
shift 5
run="${MPIRUN:-mpirun} --oversubscribe --allow-run-as-root"
rm -rf "$work"
mkdir -p "$work"
rc=0
$run -np "$ranks" "$mpi" run "$scene" --out "$work/out" --quiet --threads 1 "$@" > "$work/refused.log" 2>&1 || rc=$?
status=0
[ $rc -eq 2 ] || { echo "exit code $rc, expected 2"; status=1; }
grep -q -F "$expected" "$work/refused.log" || { echo "no message '$expected' in:"; cat "$work/refused.log"; status=1; }
[ ! -e "$work/out" ] || { echo "the refused run wrote $work/out:"; ls "$work/out"; status=1; }
[ $status -eq 0 ] && echo "refused on $ranks ranks with exit code 2: $(grep -F "$expected" "$work/refused.log" | head -1)"
exit $status
