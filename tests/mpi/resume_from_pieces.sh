#!/bin/sh
# resume_from_pieces.sh - a distributed run's per-rank checkpoint (a manifest checkpoint.bin and one piece
# checkpoint_S_rR.bin per rank, io/checkpoint.h) resumes on another number of ranks and in one process, and the
# run ends with the files of one process's straight run, byte for byte.
#
# usage: resume_from_pieces.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR T1 T2 T_END [--set ...]
#   np 2 to T1 (pieces), resumed on np 3 to T2 (pieces), resumed by SERIAL_CDMPM to T_END (one file). After each
#   part the folder holds one checkpoint: after a distributed part the manifest and exactly one piece per rank of
#   that part, after the one-process part checkpoint.bin alone.
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 t1=$5 t2=$6 end=$7
shift 7
. "$(dirname "$0")/straight_run.sh"
straight_run "$serial" "$scene" "$work" "$end" "$@"
dir="$work/pieces"
status=0
# expect_checkpoint MAGIC PIECES: checkpoint.bin starts with MAGIC and PIECES piece files (none left .tmp) exist.
expect_checkpoint() {
  magic=$(head -c 8 "$dir/checkpoint.bin")
  [ "$magic" = "$1" ] || { echo "checkpoint.bin starts with $magic, expected $1"; status=1; }
  pieces=$(cd "$dir" && ls | grep -c '^checkpoint_.*\.bin' || true)
  [ "$pieces" -eq "$2" ] || { echo "$pieces piece files (expected $2): $(cd "$dir" && ls | grep '^checkpoint_' | tr '\n' ' ')"; status=1; }
  slots=$(cd "$dir" && ls | grep '^checkpoint_.*\.bin$' | cut -c12 | sort -u | wc -l)
  [ "$2" -eq 0 ] || [ "$slots" -eq 1 ] || { echo "pieces of $slots slots left"; status=1; }
}
$run -np 2 "$mpi" run "$scene" --out "$dir" --quiet --threads 1 --set time.end="$t1" "$@" > /dev/null
expect_checkpoint CDMPMCKD 2
$run -np 3 "$mpi" run --resume "$dir" --quiet --threads 1 --set time.end="$t2" > /dev/null
expect_checkpoint CDMPMCKD 3
"$serial" run --resume "$dir" --quiet --threads 1 --set time.end="$end" > /dev/null
expect_checkpoint CDMPMCKA 0
# scene.resolved.json records the first part's time.end, as in one process's resumed runs.
same_as_straight "$work" "$dir" scene.resolved.json || status=1
[ $status -eq 0 ] && echo "pieces of np 2 to t = $t1, np 3 to t = $t2, one process to t = $end: the straight run's files"
exit $status
