#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for trying the annotate array job and for the
# integration test: munged, slurmctld and slurmd run as the current user (root) with every file
# (config, keys, state, logs, sockets) in one folder; nothing under /etc is touched.
#
#   packaging/slurm/local_cluster.sh start DIR   # starts the daemons, waits until the node is idle
#   export SLURM_CONF=DIR/slurm.conf             # then sbatch, squeue, sinfo talk to it
#   packaging/slurm/local_cluster.sh stop DIR    # stops the daemons it started
#
# Needs Debian's slurm-wlm and munge (apt-get install slurm-wlm munge). The node has nproc CPUs;
# ProctrackType=proctrack/linuxproc and TaskPlugin=task/none need no cgroups, so it also runs in
# containers. Ports: $SLURM_LOCAL_PORT and the next one (default: picked from DIR's name).
set -euo pipefail

die() {
  echo "local_cluster.sh: $*" >&2
  exit 1
}

[ $# -eq 2 ] || die "usage: local_cluster.sh start|stop DIR"
action=$1
dir=$(mkdir -p "$2" && cd "$2" && pwd)
# Unix socket paths are limited to 108 bytes: the MUNGE socket and slurmd's spool (step sockets)
# live in a short folder of their own, named after DIR. The daemons' pid files are there too, so a
# cluster left running (a test killed before it could stop it) is stopped by the next start even
# when DIR was wiped in between.
run=/tmp/sagrid-slurm-$(printf '%s' "$dir" | cksum | cut -d' ' -f1)

stop_cluster() {
  export SLURM_CONF=$dir/slurm.conf
  local pidfile pid
  # Jobs first: their steps (slurmstepd) outlive slurmd otherwise.
  if [ -f "$dir/slurm.conf" ] && [ -f "$run/slurmctld.pid" ] &&
    kill -0 "$(cat "$run/slurmctld.pid")" 2> /dev/null; then
    scancel --user="$(id -un)" 2> /dev/null || true
    for _ in $(seq 50); do [ -z "$(squeue -h 2> /dev/null)" ] && break; sleep 0.2; done
  fi
  for pidfile in "$run/slurmd.pid" "$run/slurmctld.pid" "$run/munged.pid"; do
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    # Only the daemon the file names (a stale file may hold a pid reused by another process).
    if [ -n "$pid" ] && [ "$(cat "/proc/$pid/comm" 2> /dev/null)" = "$(basename "$pidfile" .pid)" ]; then
      kill "$pid" 2> /dev/null || true
      for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
      kill -9 "$pid" 2> /dev/null || true
    fi
    rm -f "$pidfile"
  done
  rm -rf "$run"
}

if [ "$action" = stop ]; then
  stop_cluster
  exit 0
fi
[ "$action" = start ] || die "usage: local_cluster.sh start|stop DIR"

for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" > /dev/null 2>&1 || [ -x "/usr/sbin/$tool" ] ||
    die "$tool not found: install Slurm and MUNGE (apt-get install slurm-wlm munge)"
done
PATH=$PATH:/usr/sbin

port=${SLURM_LOCAL_PORT:-$((20000 + $(printf '%s' "$dir" | cksum | cut -d' ' -f1) % 20000))}
host=$(hostname -s)
mkdir -p "$dir/state" "$dir/log"

# MUNGE authenticates the daemons to each other: a private key in DIR, its socket in $run.
if [ ! -s "$dir/munge.key" ]; then
  dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
  chmod 600 "$dir/munge.key"
fi
stop_cluster  # one left running for this DIR
mkdir -p "$run/spool"
munged --key-file="$dir/munge.key" --socket="$run/munge.sock" --pid-file="$run/munged.pid" \
  --log-file="$dir/log/munged.log" --seed-file="$dir/munged.seed" --force ||
  die "munged did not start: see $dir/log/munged.log"

cat > "$dir/slurm.conf" << CONF
ClusterName=sagrid-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$run/munge.sock
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$run/spool
SlurmctldPidFile=$run/slurmctld.pid
SlurmdPidFile=$run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
KillWait=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

slurmctld -f "$SLURM_CONF" || { stop_cluster; die "slurmctld did not start: see $dir/log/slurmctld.log"; }
slurmd -f "$SLURM_CONF" || { stop_cluster; die "slurmd did not start: see $dir/log/slurmd.log"; }
for _ in $(seq 100); do
  if [ "$(sinfo -h -o %t 2> /dev/null)" = idle ]; then
    echo "local_cluster.sh: node $host idle with $(nproc) CPUs; export SLURM_CONF=$SLURM_CONF"
    exit 0
  fi
  sleep 0.2
done
state=$(sinfo -h -o '%t %E' 2>&1 || true)
stop_cluster
die "the node did not become idle within 20 s (sinfo: $state); logs in $dir/log"
