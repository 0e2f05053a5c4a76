# straight_run.sh - sourced by the distributed-run tests that stop a run and resume it (resume_on_ranks.sh,
# fail_on_rank.sh, interrupt_on_ranks.sh): the mpirun command, one process's straight run into WORK/straight, and
# the comparison of a resumed run's files with it.

# The mpirun command line (oversubscribed: more ranks than cores; as root in a container).
run="${MPIRUN:-mpirun} --oversubscribe --allow-run-as-root"

# straight_run SERIAL_CDMPM SCENE WORK T_END [--set ...]: a fresh WORK and one process's run of SCENE to T_END in
# WORK/straight, one thread.
straight_run() {
  serial=$1 scene=$2 work=$3 end=$4
  shift 4
  [ -x "$serial" ] || { echo "no program without MPI at $serial (configure and build one: cmake -S . -B build)"; exit 1; }
  rm -rf "$work"
  mkdir -p "$work"
  "$serial" run "$scene" --out "$work/straight" --quiet --threads 1 --set time.end="$end" "$@" > /dev/null
}

# same_as_straight WORK DIR [NAME ...]: every file of WORK/straight but run.json, summary.json and the NAMEs is
# byte-identical in DIR; names each that differs; returns 1 if any does.
same_as_straight() {
  work=$1 dir=$2
  shift 2
  ok=0
  for f in $(cd "$work/straight" && ls); do
    case " run.json summary.json $* " in *" $f "*) continue ;; esac
    cmp -s "$work/straight/$f" "$dir/$f" || { echo "$f differs from the straight run's"; ok=1; }
  done
  return $ok
}
