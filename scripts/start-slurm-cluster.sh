#!/usr/bin/env bash
# Start a single-node SLURM cluster on this machine, for `make test-slurm`.
#
# Needs root.  Installs Debian's slurm-wlm and munge when missing, writes a
# minimal slurm.conf for this host (its CPUs and memory as `slurmd -C` reads
# them, one partition, no accounting database, no cgroups), and starts munged,
# slurmctld and slurmd by hand (no systemd), then waits until `sinfo` shows the
# node idle.  Idempotent: daemons already running are left alone; a changed
# slurm.conf restarts slurmctld and slurmd.  Nothing is written to the
# repository: configuration in /etc/slurm, state in /var/spool/slurm{ctld,d},
# logs in /var/log/slurm.
#
# Accounting is off (AccountingStorageType=accounting_storage/none), so `sacct`
# has no jobs to report: the Snakemake SLURM executor must query job states with
# `squeue` (status command squeue), which sees a finished job for MinJobAge
# seconds; MinJobAge is set well above the executor's check interval.
set -euo pipefail

CONF_DIR=/etc/slurm
CONF=$CONF_DIR/slurm.conf
CTLD_SPOOL=/var/spool/slurmctld
SLURMD_SPOOL=/var/spool/slurmd
LOG_DIR=/var/log/slurm
CTLD_PID=/run/slurmctld.pid
SLURMD_PID=/run/slurmd.pid
WAIT_SECONDS=${SLURM_START_TIMEOUT:-60}

say() { echo "start-slurm-cluster: $*"; }
die() { echo "start-slurm-cluster: error: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || die "needs root (it installs packages and starts the SLURM daemons)"

# Is the daemon whose pid file is $1 running?
running() { [ -s "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

# Stop the daemon whose pid file is $1 (by its pid), waiting until it is gone.
stop() {
    running "$1" || return 0
    local pid
    pid=$(cat "$1")
    kill "$pid"
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.2; done
    die "process $pid (pid file $1) did not stop"
}

# 1. Packages.
missing=()
for command in slurmctld slurmd sinfo sbatch munged; do
    command -v "$command" > /dev/null || missing+=("$command")
done
if [ ${#missing[@]} -gt 0 ]; then
    say "installing slurm-wlm and munge (missing: ${missing[*]})"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq slurm-wlm munge > /dev/null
fi

# 2. munge: a key, then the daemon (as the munge user, as Debian runs it).
if [ ! -s /etc/munge/munge.key ]; then
    say "creating the munge key"
    install -d -o munge -g munge -m 0700 /etc/munge
    dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 status=none
    chown munge:munge /etc/munge/munge.key
    chmod 0400 /etc/munge/munge.key
fi
install -d -o munge -g munge -m 0755 /run/munge
install -d -o munge -g munge -m 0700 /var/lib/munge /var/log/munge
if ! munge -n 2>/dev/null | unmunge > /dev/null 2>&1; then
    say "starting munged"
    # A stale socket or pid file from a killed munged stops a new one starting.
    if ! running /run/munge/munged.pid; then
        rm -f /run/munge/munged.pid /run/munge/munge.socket.2 /run/munge/munge.socket.2.lock
    fi
    runuser -u munge -- /usr/sbin/munged
    for _ in $(seq 50); do munge -n 2>/dev/null | unmunge > /dev/null 2>&1 && break; sleep 0.2; done
    munge -n | unmunge > /dev/null || die "munged does not answer"
fi

# 3. slurm.conf for this host.
host=$(hostname -s)
# `slurmd -C` prints this machine's node line: CPUs, sockets, cores, threads, memory.
node_line=$(slurmd -C | head -n 1)
case "$node_line" in
    NodeName=*CPUs=*RealMemory=*) ;;
    *) die "unexpected 'slurmd -C' output: $node_line" ;;
esac
node_hardware=${node_line#NodeName=* }
new_conf=$(cat <<EOF
# Written by stickslip's scripts/start-slurm-cluster.sh: a single-node cluster
# for testing the workflow's SLURM profile.  Rewritten (and the daemons
# restarted) when this host's hardware or the script changes.
ClusterName=stickslip
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
MpiDefault=none
SwitchType=switch/none
# No cgroups in this sandbox: track processes through /proc, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
# Cores and memory are the consumable resources.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
# No accounting database: Snakemake must use 'squeue' to follow its jobs.
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
# Keep finished jobs visible to squeue for 10 minutes.
MinJobAge=600
ReturnToService=2
SchedulerType=sched/backfill
StateSaveLocation=$CTLD_SPOOL
SlurmdSpoolDir=$SLURMD_SPOOL
SlurmctldPidFile=$CTLD_PID
SlurmdPidFile=$SLURMD_PID
SlurmctldLogFile=$LOG_DIR/slurmctld.log
SlurmdLogFile=$LOG_DIR/slurmd.log
SlurmctldTimeout=30
SlurmdTimeout=60
NodeName=$host $node_hardware State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
)
install -d -m 0755 "$CONF_DIR" "$LOG_DIR"
install -d -m 0700 "$CTLD_SPOOL" "$SLURMD_SPOOL"
restart=false
if [ ! -f "$CONF" ] || [ "$(cat "$CONF")" != "$new_conf" ]; then
    say "writing $CONF"
    printf '%s\n' "$new_conf" > "$CONF"
    restart=true
fi

# 4. The daemons.
if $restart; then
    stop "$SLURMD_PID"
    stop "$CTLD_PID"
fi
if ! running "$CTLD_PID"; then
    say "starting slurmctld"
    slurmctld
fi
for _ in $(seq 50); do scontrol ping 2>/dev/null | grep -q "is UP" && break; sleep 0.2; done
scontrol ping | grep -q "is UP" || die "slurmctld does not answer; see $LOG_DIR/slurmctld.log"
if ! running "$SLURMD_PID"; then
    say "starting slurmd"
    slurmd
fi

# 5. Wait until the node takes jobs.
state=""
for _ in $(seq $((WAIT_SECONDS * 2))); do
    state=$(sinfo --noheader --nodes "$host" --format %T 2>/dev/null | head -n 1)
    case "$state" in
        idle|mixed|allocated) break ;;
        drain*|down*)
            # A node left down or drained by an earlier run: give it back.
            scontrol update NodeName="$host" State=RESUME 2>/dev/null || true ;;
    esac
    sleep 0.5
done
case "$state" in
    idle|mixed|allocated) ;;
    *) die "node $host is '${state:-unknown}' after ${WAIT_SECONDS} s; see $LOG_DIR/slurmd.log and slurmctld.log" ;;
esac
say "node $host is $state"
sinfo
