#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for the scheduler tests (root, Debian's
# slurm-wlm and munge). `start` is idempotent; `stop` ends the daemons it started.
#   bash scripts/slurm_local.sh start|stop|status
set -euo pipefail
state=/tmp/ffp-slurm
conf=/etc/slurm/slurm.conf
case "${1:-status}" in
  start)
    command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v munged >/dev/null ||
      { echo "slurm_local: slurm-wlm and munge are not installed (bash scripts/setup.sh --tests)" >&2; exit 3; }
    [ "$(id -u)" = 0 ] || { echo "slurm_local: needs root to start munged, slurmctld and slurmd" >&2; exit 3; }
    if sinfo -h -o %T 2>/dev/null | grep -qE '^(idle|mixed|allocated)'; then exit 0; fi
    # Never overwrite a real cluster's configuration: only one this script wrote.
    if [ -e "$conf" ] && ! grep -q '^ClusterName=ffp-local$' "$conf"; then
      echo "slurm_local: $conf exists and is not ours (ClusterName=ffp-local): leaving it alone" >&2
      exit 3
    fi
    mkdir -p "$state"/spool/ctld "$state"/spool/d "$state"/log /run/munge /var/lib/munge /var/log/munge
    chown munge:munge /run/munge /var/lib/munge /var/log/munge 2>/dev/null || true
    [ -s /etc/munge/munge.key ] || mungekey --create --keyfile=/etc/munge/munge.key
    chown munge:munge /etc/munge/munge.key 2>/dev/null || true
    chmod 400 /etc/munge/munge.key
    pgrep -x munged >/dev/null || su -s /bin/sh munge -c /usr/sbin/munged 2>/dev/null || /usr/sbin/munged --force
    host=$(hostname -s)
    cpus=$(nproc)
    memory_mb=$(awk '/MemTotal/ {print int($2 / 1024 * 0.9)}' /proc/meminfo)
    cat > "$conf" <<CONF
ClusterName=ffp-local
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$state/spool/ctld
SlurmdSpoolDir=$state/spool/d
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host CPUs=$cpus RealMemory=$memory_mb State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    printf 'ConstrainCores=no\n' > /etc/slurm/cgroup.conf
    pgrep -x slurmctld >/dev/null || slurmctld
    pgrep -x slurmd >/dev/null || slurmd
    for _ in $(seq 1 30); do
      if sinfo -h -o %T 2>/dev/null | grep -qE '^(idle|mixed|allocated)'; then
        # Up only if it runs a job: a node that registers but cannot start tasks would
        # leave a test waiting on its queue.
        if timeout 60 sbatch --wait --quiet --output=/dev/null --wrap true >/dev/null 2>&1; then exit 0; fi
        echo "slurm_local: the node is up but a trivial job did not run within 60 s; see $state/log" >&2
        exit 4
      fi
      sleep 1
    done
    echo "slurm_local: the node did not come up; see $state/log" >&2
    exit 4
    ;;
  stop)
    pkill -x slurmd || true
    pkill -x slurmctld || true
    ;;
  status)
    sinfo
    ;;
esac
