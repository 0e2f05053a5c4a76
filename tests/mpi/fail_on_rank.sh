#!/bin/sh
# fail_on_rank.sh - a rank that fails to allocate ends the whole distributed run with a message naming the rank and
# the cause and a non-zero exit code; the frames and checkpoint written before are intact, and resuming from them
# ends with the files of one process's straight run, byte for byte (docs/architecture.md). The failure is
# injected (run/fault_injection.h): rank FAIL_RANK throws std::bad_alloc at the end of step FAIL_STEP.
#
# usage: fail_on_rank.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR RANKS FAIL_RANK FAIL_STEP T_END [--set ...]
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 ranks=$5 fail_rank=$6 fail_step=$7 end=$8
shift 8
. "$(dirname "$0")/straight_run.sh"
straight_run "$serial" "$scene" "$work" "$end" "$@"
status=0
rc=0
CDMPM_TEST_FAIL_RANK=$fail_rank CDMPM_TEST_FAIL_STEP=$fail_step \
  $run -np "$ranks" "$mpi" run "$scene" --out "$work/failed" --quiet --threads 1 --gather-output --set time.end="$end" "$@" \
  > "$work/failed.log" 2>&1 || rc=$?
[ $rc -ne 0 ] || { echo "the run with a failing rank exited with code 0"; status=1; }
expected="cdmpm: error (rank $fail_rank of $ranks): out of memory"
grep -q -F "$expected" "$work/failed.log" || { echo "no message '$expected' in:"; cat "$work/failed.log"; status=1; }
[ -f "$work/failed/checkpoint.bin" ] || { echo "no checkpoint left by the failed run"; exit 1; }
[ ! -f "$work/failed/summary.json" ] || { echo "the failed run wrote summary.json: it did not stop at step $fail_step"; status=1; }
$run -np "$ranks" "$mpi" run --resume "$work/failed" --quiet --threads 1 --gather-output > /dev/null
same_as_straight "$work" "$work/failed" || status=1
[ $status -eq 0 ] && echo "rank $fail_rank of $ranks failed at step $fail_step (exit code $rc); resumed: the straight run's files"
exit $status
