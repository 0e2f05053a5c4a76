#!/bin/sh
# resume_on_ranks.sh - a distributed run stopped at a checkpoint and resumed on another number of ranks ends with
# the files of one process's straight run, byte for byte (docs/architecture.md; the keys of the resumed particles
# are their order in the checkpoint, which is the one-process array).
#
# usage: resume_on_ranks.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR FIRST_RANKS THEN_RANKS T_STOP T_END [--set ...]
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 first=$5 then=$6 stop=$7 end=$8
shift 8
. "$(dirname "$0")/straight_run.sh"
straight_run "$serial" "$scene" "$work" "$end" "$@"
$run -np "$first" "$mpi" run "$scene" --out "$work/resumed" --quiet --threads 1 --gather-output --set time.end="$stop" "$@" > /dev/null
$run -np "$then" "$mpi" run --resume "$work/resumed" --quiet --threads 1 --gather-output --set time.end="$end" > /dev/null
status=0
# scene.resolved.json records the first part's time.end, as in one process's resumed runs.
same_as_straight "$work" "$work/resumed" scene.resolved.json || status=1
[ $status -eq 0 ] && echo "np $first to t = $stop, resumed on np $then to t = $end: the straight one-process run's files"
exit $status
