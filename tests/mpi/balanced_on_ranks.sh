#!/bin/sh
# balanced_on_ranks.sh - the load-balance criterion: a distributed run on RANKS ranks writes the files of
# one process byte for byte (ranks_match_one_process.sh) and, after its first repartition, the particle imbalance
# max / mean over the ranks measured at every particle sort stays below LIMIT (summary.json, "distributed":
# max_imbalance_after_first_repartition; parallel/domain.h).
#
# usage: balanced_on_ranks.sh SERIAL_CDMPM MPI_CDMPM SCENE WORK_DIR RANKS LIMIT [--set key=value ...]
set -eu
serial=$1 mpi=$2 scene=$3 work=$4 ranks=$5 limit=$6
shift 6
sh "$(dirname "$0")/ranks_match_one_process.sh" "$serial" "$mpi" "$scene" "$work" "$ranks" "$@"
/usr/bin/python3 - "$work/np$ranks/summary.json" "$limit" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))["distributed"]
limit = float(sys.argv[2])
print("repartitions %d, imbalance: largest %.4f, largest after the first repartition %.4f, last %.4f"
      % (d["repartitions"], d["max_imbalance"], d["max_imbalance_after_first_repartition"], d["last_imbalance"]))
if d["repartitions"] < 1:
    sys.exit("no repartition happened: the criterion is not exercised")
if not d["max_imbalance_after_first_repartition"] < limit:
    sys.exit("imbalance %.4f after the first repartition, not below %g" % (d["max_imbalance_after_first_repartition"], limit))
PY
