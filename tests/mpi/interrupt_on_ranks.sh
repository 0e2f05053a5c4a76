#!/bin/sh
# interrupt_on_ranks.sh - Ctrl-C (SIGINT to mpirun) stops a distributed run with a checkpoint, as one process does
# (run/interrupt.h: mpirun sends SIGTERM to every rank, which all stop after the same step and write the
# checkpoint), with a non-zero exit code; resumed on THEN_RANKS it ends with the files of one process's straight run,
# byte for byte (docs/architecture.md).
#
# usage: interrupt_on_ranks.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR RANKS THEN_RANKS T_END FRAME [--set ...]
#   The signal is sent once the frame file FRAME (e.g. particles_0003.vtu) exists.
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 ranks=$5 then=$6 end=$7 frame=$8
shift 8
. "$(dirname "$0")/straight_run.sh"
straight_run "$serial" "$scene" "$work" "$end" "$@"
$run -np "$ranks" "$mpi" run "$scene" --out "$work/stopped" --quiet --threads 1 --gather-output --set time.end="$end" "$@" \
  > "$work/stopped.log" 2>&1 &
pid=$!
waited=0
while [ ! -f "$work/stopped/$frame" ] && [ $waited -lt 600 ]; do sleep 0.2; waited=$((waited + 1)); done
kill -INT $pid
rc=0
wait $pid || rc=$?
status=0
[ $rc -ne 0 ] || { echo "the interrupted run exited with code 0"; status=1; }
grep -q '"status": "interrupted"' "$work/stopped/summary.json" ||
  { echo "summary.json does not say interrupted (did the run end before the signal?)"; cat "$work/stopped.log"; exit 1; }
$run -np "$then" "$mpi" run --resume "$work/stopped" --quiet --threads 1 --gather-output > /dev/null
same_as_straight "$work" "$work/stopped" || status=1
[ $status -eq 0 ] && echo "np $ranks interrupted (exit code $rc), resumed on np $then: the straight run's files"
exit $status
