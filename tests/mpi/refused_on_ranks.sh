#!/bin/sh
# refused_on_ranks.sh - a scene with a feature a distributed run does not support yet is refused up front on more
# than one rank: exit code 2 and a message naming the feature (parallel/distributable.h), never a wrong run.
#
# usage: refused_on_ranks.sh MPI_CDMPM SCENE WORK_DIR "EXPECTED TEXT" [--set key=value ...]
set -u
mpi=$1 scene=$2 work=$3 expected=$4
shift 4
rm -rf "$work"
mkdir -p "$work"
"${MPIRUN:-mpirun}" -np 2 --oversubscribe --allow-run-as-root "$mpi" run "$scene" --out "$work/out" --quiet "$@" \
  > "$work/stdout" 2> "$work/stderr"
code=$?
[ $code -eq 2 ] || { echo "exit code $code, expected 2"; cat "$work/stderr"; exit 1; }
grep -q "$expected" "$work/stderr" || { echo "the message does not name '$expected':"; cat "$work/stderr"; exit 1; }
[ ! -e "$work/out/probes.csv" ] || { echo "the refused run wrote outputs"; exit 1; }
echo "refused with exit code 2: $(head -1 "$work/stderr")"
