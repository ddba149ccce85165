#!/usr/bin/env bash
# A two-node Slurm cluster on this machine, for the render-farm tests (docs/farm.md, Testing):
# one slurmctld and two slurmd (-N node1, -N node2) on loopback, each node with one CPU, one
# munged, every file of theirs in one folder. Needs Debian's slurmctld, slurmd, slurm-client
# and munge (scripts/install-deps.sh) and root (the daemons run as the calling user).
#
#   slurm_cluster.sh start DIR      start it; prints nothing, exits 0 when both nodes are idle,
#                                   77 with a reason on stderr when the daemons cannot run here
#   slurm_cluster.sh env DIR        the line to eval for its client commands (SLURM_CONF)
#   slurm_cluster.sh kill-node DIR NODE
#                                   the node dies: its slurmd and every job process on it are
#                                   killed with SIGKILL, as when the machine loses power
#   slurm_cluster.sh restart-node DIR NODE
#   slurm_cluster.sh stop DIR       stops every daemon and job process it started
set -uo pipefail

skip() { echo "slurm_cluster: cannot run a cluster here: $*" >&2; exit 77; }

# A free TCP port on loopback (the kernel picks it; a race with another program is unlikely
# and shows as a daemon that fails to start).
free_port() {
    python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}

write_config() {
    local dir="$1" ctl_port node1_port node2_port
    ctl_port=$(free_port); node1_port=$(free_port); node2_port=$(free_port)
    cat >"$dir/slurm.conf" <<CONF
ClusterName=clrender-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctl_port
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.%n.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.%n.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
# A dead node is noticed within seconds (a real cluster waits minutes), its jobs end as
# NODE_FAIL and are not requeued, so that a test sees the failure a farm run must survive;
# a dependency that can never be met is cancelled instead of pending for ever.
SlurmdTimeout=8
SlurmctldTimeout=10
ReturnToService=2
JobRequeue=0
MinJobAge=3600
SchedulerParameters=kill_invalid_depend
MessageTimeout=5
NodeName=node1 NodeHostname=localhost NodeAddr=127.0.0.1 Port=$node1_port CPUs=1 RealMemory=2000 State=UNKNOWN
NodeName=node2 NodeHostname=localhost NodeAddr=127.0.0.1 Port=$node2_port CPUs=1 RealMemory=2000 State=UNKNOWN
PartitionName=farm Nodes=node1,node2 Default=YES MaxTime=INFINITE State=UP
CONF
}

start_munge() {
    local dir="$1"
    mkdir -p "$dir/munge"
    chmod 700 "$dir/munge"
    mungekey --create --keyfile="$dir/munge/munge.key" 2>/dev/null ||
        dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 2>/dev/null
    chmod 600 "$dir/munge/munge.key"
    munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
        --seed-file="$dir/munge/munged.seed" 2>"$dir/log/munged.err" ||
        skip "munged did not start: $(tail -1 "$dir/log/munged.err")"
}

start_slurmd() {
    local dir="$1" node="$2"
    mkdir -p "$dir/spool/$node"
    slurmd -f "$dir/slurm.conf" -N "$node" 2>>"$dir/log/slurmd.$node.err" ||
        skip "slurmd -N $node did not start: $(tail -1 "$dir/log/slurmd.$node.log" 2>/dev/null)"
}

# Both nodes idle, or the reason they are not after 60 s.
wait_for_nodes() {
    local dir="$1" states=""
    for _ in $(seq 1 120); do
        states=$(SLURM_CONF="$dir/slurm.conf" sinfo -h -N -o '%N %t' 2>/dev/null | sort | tr '\n' ' ')
        [ "$states" = "node1 idle node2 idle " ] && return 0
        sleep 0.5
    done
    skip "the nodes are not idle after 60 s (sinfo: ${states:-no answer}); see $dir/log"
}

start() {
    local dir="$1"
    for program in munged mungekey slurmctld slurmd sbatch sinfo python3; do
        command -v "$program" >/dev/null || skip "$program is not installed (scripts/install-deps.sh installs it)"
    done
    [ "$(id -u)" -eq 0 ] || skip "the test cluster's daemons need root"
    mkdir -p "$dir/state" "$dir/spool" "$dir/log"
    write_config "$dir"
    start_munge "$dir"
    slurmctld -f "$dir/slurm.conf" -i 2>"$dir/log/slurmctld.err" ||
        skip "slurmctld did not start: $(tail -1 "$dir/log/slurmctld.log" 2>/dev/null)"
    start_slurmd "$dir" node1
    start_slurmd "$dir" node2
    wait_for_nodes "$dir"
}

# Processes of jobs that ran on NODE: their environment names the node.
job_processes_on() {
    local node="$1" pid
    for pid in $(ls /proc | grep -E '^[0-9]+$'); do
        { tr '\0' '\n' <"/proc/$pid/environ"; } 2>/dev/null | grep -qx "SLURMD_NODENAME=$node" && echo "$pid"
    done
}

# slurmstepd processes of the jobs that SLURM says run on NODE.
step_daemons_on() {
    local dir="$1" node="$2" job
    for job in $(SLURM_CONF="$dir/slurm.conf" squeue -h -w "$node" -o '%A' 2>/dev/null); do
        pgrep -f "^slurmstepd: \[$job\." || true
    done
}

kill_node() {
    local dir="$1" node="$2" pids
    pids="$(cat "$dir/slurmd.$node.pid" 2>/dev/null) $(step_daemons_on "$dir" "$node") $(job_processes_on "$node")"
    # shellcheck disable=SC2086
    kill -KILL $pids 2>/dev/null
    rm -f "$dir/slurmd.$node.pid"
}

stop_pid_file() {
    local file="$1" pid
    pid=$(cat "$file" 2>/dev/null) || return 0
    kill "$pid" 2>/dev/null
    for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null
    rm -f "$file"
}

stop() {
    local dir="$1" node
    [ -f "$dir/slurm.conf" ] || return 0
    for node in node1 node2; do
        kill -KILL $(step_daemons_on "$dir" "$node") $(job_processes_on "$node") 2>/dev/null
        stop_pid_file "$dir/slurmd.$node.pid"
    done
    stop_pid_file "$dir/slurmctld.pid"
    stop_pid_file "$dir/munge/munged.pid"
}

command="${1:-}"; dir="${2:-}"
[ -n "$command" ] && [ -n "$dir" ] || { sed -n '2,16p' "$0" >&2; exit 2; }
dir="$(mkdir -p "$dir" && cd "$dir" && pwd)"
case "$command" in
    start) start "$dir" ;;
    env) echo "export SLURM_CONF='$dir/slurm.conf'" ;;
    kill-node) kill_node "$dir" "$3" ;;
    restart-node) start_slurmd "$dir" "$3" ;;
    stop) stop "$dir" ;;
    *) echo "slurm_cluster: unknown command $command" >&2; exit 2 ;;
esac
