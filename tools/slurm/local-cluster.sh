#!/usr/bin/env bash
# A throw-away single-node Slurm cluster on this machine, for the farm test (and for trying the
# farm scripts without a cluster): munged with a freshly generated key, slurmctld and slurmd
# with a generated slurm.conf for this hostname and this machine's cores. Everything lives in
# DIR (config, key, sockets, state, logs); nothing under /etc is read or changed, and the ports
# are picked free so it can run beside a real Slurm. Needs root and the Debian packages
# slurm-wlm and munge (tools/install-deps.sh installs them).
#
#   local-cluster.sh start DIR   # starts the daemons, waits until the node is idle;
#                                # on failure prints the daemons' logs, stops them, exits 1
#   local-cluster.sh stop DIR    # stops every daemon started in DIR (safe to call twice)
#   SLURM_CONF=DIR/slurm.conf sbatch ...   # how clients talk to it
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
cmd=$1
dir=$(realpath -m "$2")

free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

print_logs() {
    for f in "$dir"/log/*.log; do
        [ -f "$f" ] || continue
        echo "----- $f (last 40 lines) -----" >&2
        tail -n 40 "$f" >&2
    done
}

# Stops by the pid files the daemons wrote (never by name: other Slurms may run here). All are
# signalled at once, then waited for (each takes a second or two to shut down).
stop() {
    local name pid pids=()
    for name in slurmd slurmctld munged; do
        [ -f "$dir/run/$name.pid" ] || continue
        pid=$(cat "$dir/run/$name.pid" 2>/dev/null || true)
        rm -f "$dir/run/$name.pid"
        if [ -n "$pid" ] && kill "$pid" 2>/dev/null; then pids+=("$pid"); fi
    done
    for pid in "${pids[@]}"; do
        for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
    done
}

fail() {
    echo "local-cluster: $*" >&2
    print_logs
    stop
    exit 1
}

write_conf() {
    local host cpus ctld_port d_port
    host=$(hostname -s)
    cpus=$(nproc)
    ctld_port=$(free_port)
    d_port=$(free_port)
    while [ "$d_port" = "$ctld_port" ]; do d_port=$(free_port); done
    # proctrack/linuxproc and task/none: no cgroups, so it also runs in containers.
    cat > "$dir/slurm.conf" <<EOF
ClusterName=sweeptrace-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/run/munge.socket
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
# The node is what this file says (nproc may be below the hardware count in a container).
SlurmdParameters=config_overrides
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
}

start() {
    for tool in munged mungekey slurmctld slurmd sinfo scontrol; do
        command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] ||
            fail "'$tool' is not installed (apt-get install slurm-wlm munge, or bash tools/install-deps.sh)"
    done
    export PATH="$PATH:/usr/sbin"
    mkdir -p "$dir"/{run,log,state,spool,munge}
    chmod 700 "$dir/munge"
    write_conf
    export SLURM_CONF="$dir/slurm.conf"

    mungekey --create --keyfile="$dir/munge/munge.key" --force 2>>"$dir/log/munged.log" ||
        fail "mungekey could not create a key"
    chmod 400 "$dir/munge/munge.key"
    # --force: munged refuses to run as root, or with a key outside /etc, unless forced.
    munged --force --key-file="$dir/munge/munge.key" --socket="$dir/run/munge.socket" \
        --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log" \
        --seed-file="$dir/munge/munged.seed" 2>>"$dir/log/munged.log" || fail "munged did not start"
    munge -n -S "$dir/run/munge.socket" | unmunge -S "$dir/run/munge.socket" >/dev/null 2>&1 ||
        fail "munged started but does not answer on $dir/run/munge.socket"

    slurmctld -f "$dir/slurm.conf" -i 2>>"$dir/log/slurmctld.log" || fail "slurmctld did not start"
    slurmd -f "$dir/slurm.conf" -N "$(hostname -s)" 2>>"$dir/log/slurmd.log" || fail "slurmd did not start"

    local state=""
    for _ in $(seq 150); do
        state=$(sinfo -h -N -o '%T' 2>/dev/null | head -n 1 || true)
        [ "$state" = "idle" ] && { echo "local-cluster: node $(hostname -s) idle, $(nproc) cores, SLURM_CONF=$dir/slurm.conf" >&2; return 0; }
        sleep 0.2
    done
    fail "the node did not become idle within 30 s (last state: '${state:-none}')"
}

case "$cmd" in
    start) start ;;
    stop) stop ;;
    *) usage ;;
esac
