#!/usr/bin/env bash
# A single-node SLURM cluster on this machine, for the sweep tests and for trying
# `ppsynth sweep run --slurm` without a real cluster. Debian's munge, slurmctld, slurmd and
# slurm-client (installed by scripts/setup.sh); no systemd needed.
#
# Usage: scripts/slurm_cluster.sh start|stop|status|env [STATE_DIR]
#   start   writes STATE_DIR/slurm.conf and starts munged, slurmctld and slurmd from it
#   stop    stops the three daemons this script started (by their pid files) and keeps the logs
#   status  sinfo against the cluster, exit 0 when the node is up
#   env     prints `export SLURM_CONF=...` for the clients (eval "$(... env)")
# STATE_DIR defaults to $PPSYNTH_SLURM_DIR or /tmp/ppsynth-slurm-$UID. Everything the cluster
# writes (config, munge key and socket, spool, state, logs, pid files) stays in it: the
# system's /etc/slurm and /etc/munge are neither read nor changed. The clients find the
# cluster through SLURM_CONF only.
#
# Why these settings: as root without systemd, only SlurmUser=root, proctrack/linuxproc and
# task/none start (cgroup plugins need systemd's hierarchy); RealMemory must stay below what
# `slurmd -C` measures or the node is drained; ports other than SLURM's defaults keep it away
# from a real installation on the same machine.
set -euo pipefail

cmd="${1:-}"
state="${2:-${PPSYNTH_SLURM_DIR:-/tmp/ppsynth-slurm-$(id -u)}}"
conf="$state/slurm.conf"
node="ppsynth-node"

die() { echo "slurm_cluster: $*" >&2; exit 2; }
need() { command -v "$1" >/dev/null 2>&1 || die "$1 not found (scripts/setup.sh installs munge, slurmctld, slurmd, slurm-client)"; }

# pid_alive PIDFILE NAME: the pid file names a live process called NAME (a stale pid file of
# an earlier session may name a pid the system has given to another process since).
pid_alive() { [ -f "$1" ] && [ "$(cat "/proc/$(cat "$1")/comm" 2>/dev/null)" = "$2" ]; }

wait_for() {  # wait_for SECONDS DESCRIPTION COMMAND...
  local limit="$1" what="$2"; shift 2
  for _ in $(seq 1 $((limit * 5))); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 0.2
  done
  die "$what did not come up within ${limit}s (logs in $state/log)"
}

node_idle() { SLURM_CONF="$conf" sinfo -h -N -n "$node" -o '%t' 2>/dev/null | grep -Eq '^(idle|mix|alloc)'; }

start() {
  need munged; need slurmctld; need slurmd; need sinfo
  [ "$(id -u)" -eq 0 ] || die "start needs root (slurmd runs jobs as their users)"
  if pid_alive "$state/run/slurmctld.pid" slurmctld && pid_alive "$state/run/slurmd.pid" slurmd; then echo "slurm_cluster: already running ($conf)"; return 0; fi
  stop >/dev/null  # what is left of a cluster half up (a daemon died, a session ended)
  mkdir -p "$state"/{run,log,spool,ctld,munge}
  chmod 700 "$state" "$state/munge"

  [ -f "$state/munge/munge.key" ] || mungekey --create --keyfile="$state/munge/munge.key" >/dev/null
  chmod 600 "$state/munge/munge.key"
  munged --force --socket="$state/munge/munge.sock" --key-file="$state/munge/munge.key" \
    --pid-file="$state/run/munged.pid" --log-file="$state/log/munged.log" \
    --seed-file="$state/munge/munged.seed"
  wait_for 10 munged test -S "$state/munge/munge.sock"

  local cpus mem
  cpus="$(nproc)"
  mem="$(slurmd -C | sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' | head -1)"
  mem=$(( mem * 9 / 10 ))
  cat > "$conf" <<EOF
# Written by scripts/slurm_cluster.sh: a single-node cluster for ppsynth's tests.
ClusterName=ppsynth
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$state/munge/munge.sock
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
SchedulerType=sched/backfill
JobRequeue=1
ReturnToService=2
MpiDefault=none
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/run/slurmctld.pid
SlurmdPidFile=$state/run/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
MinJobAge=300
KillWait=30
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=$(hostname) CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF
  # -c: start with an empty queue. The run directories, not the controller, hold a sweep's
  # state (`ppsynth sweep status`), and jobs of an earlier test must not come back.
  slurmctld -f "$conf" -c
  wait_for 20 slurmctld env SLURM_CONF="$conf" scontrol ping
  slurmd -f "$conf" -N "$node"
  wait_for 30 "the node $node" node_idle
  echo "slurm_cluster: up; export SLURM_CONF=$conf"
}

stop() {
  local d
  for d in slurmd slurmctld munged; do
    if pid_alive "$state/run/$d.pid" "$d"; then
      local pid; pid="$(cat "$state/run/$d.pid")"
      kill "$pid" 2>/dev/null || true
      for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
      kill -9 "$pid" 2>/dev/null || true
    fi
    rm -f "$state/run/$d.pid"
  done
  echo "slurm_cluster: stopped (logs in $state/log)"
}

case "$cmd" in
  start) start ;;
  stop) stop ;;
  status) [ -f "$conf" ] || die "no cluster configured in $state"; SLURM_CONF="$conf" sinfo; node_idle ;;
  env) echo "export SLURM_CONF=$conf" ;;
  *) echo "usage: scripts/slurm_cluster.sh start|stop|status|env [STATE_DIR]" >&2; exit 2 ;;
esac
