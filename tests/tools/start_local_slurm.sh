#!/usr/bin/env bash
# start_local_slurm.sh - a single-node Slurm on this machine for the ensemble tool's tests (docs/ensembles.md#slurm):
# Debian's slurm-wlm and munge, configured for localhost (one node with this machine's cores and memory, one
# partition), the daemons started by hand (no systemd needed). As root; installs the packages if missing.
# Does nothing if `sinfo` already answers. `tests/tools/test_ensemble.py` then also submits through sbatch.
#   bash tests/tools/start_local_slurm.sh [--stop]
# --stop ends the daemons this script started (by the pid files it wrote).
set -euo pipefail
conf=/etc/slurm/slurm.conf
pids=/run/cdmpm-local-slurm
if [ "${1:-}" = --stop ]; then
  for f in "$pids"/*.pid; do [ -f "$f" ] && kill "$(cat "$f")" 2>/dev/null || true; rm -f "$f"; done
  exit 0
fi
if command -v sinfo >/dev/null && timeout 10 sinfo -h -o %a 2>/dev/null | grep -q up; then
  echo "start_local_slurm: Slurm already answers"; exit 0
fi
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge >/dev/null
fi
mkdir -p "$pids" /run/munge /var/log/munge /var/lib/munge /var/spool/slurmctld /var/spool/slurmd /var/log/slurm
chown munge:munge /run/munge /var/log/munge /var/lib/munge
[ -s /etc/munge/munge.key ] || { dd if=/dev/urandom of=/etc/munge/munge.key bs=128 count=1 status=none; chown munge:munge /etc/munge/munge.key; chmod 400 /etc/munge/munge.key; }
if ! munge -n >/dev/null 2>&1; then
  runuser -u munge -- /usr/sbin/munged
  sleep 1
  cp /run/munge/munged.pid "$pids/munged.pid"   # munged's own, written once it has detached
fi
host=$(hostname -s)
node=$(slurmd -C | head -1)   # NodeName=HOST CPUs=... RealMemory=... as slurmd sees this machine
cat > "$conf" <<EOF
# Single-node Slurm written by tests/tools/start_local_slurm.sh
ClusterName=local
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
MpiDefault=none
ProctrackType=proctrack/pgid
TaskPlugin=task/none
ReturnToService=2
SlurmctldPidFile=$pids/slurmctld.pid
SlurmdPidFile=$pids/slurmd.pid
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
$node State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
/usr/sbin/slurmctld
/usr/sbin/slurmd
for _ in $(seq 30); do
  if timeout 5 sinfo -h -o %a 2>/dev/null | grep -q up && timeout 5 sinfo -h -o %t | grep -q idle; then
    echo "start_local_slurm: Slurm is up on $host"; exit 0
  fi
  sleep 1
done
echo "start_local_slurm: Slurm did not come up (logs in /var/log/slurm)" >&2
exit 1
