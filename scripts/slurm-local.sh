#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, for tests and for trying `sdfreel slurm`:
#   scripts/slurm-local.sh install        Debian's munge, slurmctld, slurmd, slurm-client
#   scripts/slurm-local.sh start DIR      munged, slurmctld and slurmd with all state in DIR
#   scripts/slurm-local.sh stop DIR       stops them and removes DIR
# start writes DIR/slurm.conf (localhost, this machine's cores) and DIR/env; `. DIR/env` points
# sbatch, squeue and scontrol at this cluster (SLURM_CONF). Nothing outside DIR is touched: no
# systemd, no /etc/slurm, no /etc/munge; ports are picked free so that two clusters can coexist.
# Needs root (slurmd runs the jobs as their submitter).
set -euo pipefail

die() { echo "slurm-local: $*" >&2; exit 1; }

install_packages() {
  local packages=(munge slurmctld slurmd slurm-client) missing=() p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "installing: ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

port_in_use() { (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }

# Two consecutive free TCP ports from a range unlikely to be taken (Slurm's own defaults are
# 6817-6818; a system cluster may use them).
free_port_pair() {
  local p
  for ((p = 16817 + RANDOM % 2000; p < 20000; p += 2)); do
    port_in_use "$p" || port_in_use "$((p + 1))" || { echo "$p"; return; }
  done
  die "no free port pair found"
}

write_conf() {
  local dir=$1 port=$2 cpus
  cpus=$(nproc)
  cat >"$dir/slurm.conf" <<EOF
# A minimal single-node cluster: this machine is controller and compute node.
ClusterName=sdfreel
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
# No cgroups (containers and chroots often have none): track processes by parent id.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
# One CPU per task by default, so the node runs as many array tasks at once as it has cores.
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# Schedule at once on submission and completion; keep finished jobs visible for 10 minutes.
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
MinJobAge=600
ReturnToService=2
SlurmdTimeout=60
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
  # slurmd 22.05 always loads a cgroup plugin, even when no other plugin uses it, and its default
  # ("autodetect") fails where /sys/fs/cgroup has nothing mounted (a chroot, some containers).
  # Naming cgroup/v1 skips the detection; loading it touches no cgroup file system, and with the
  # plugins above nothing asks it to. ("disabled", the clean way, exists only in later releases.)
  echo "CgroupPlugin=cgroup/v1" >"$dir/cgroup.conf"
}

start() {
  local dir=$1
  [ "$(id -u)" -eq 0 ] || die "start needs root"
  for t in munged slurmctld slurmd sbatch; do
    command -v "$t" >/dev/null || [ -x "/usr/sbin/$t" ] || die "$t is missing: run $0 install"
  done
  mkdir -p "$dir"
  dir=$(cd "$dir" && pwd)
  [ ! -e "$dir/slurmctld.pid" ] || die "$dir already holds a cluster (stop it first)"
  chmod 700 "$dir"
  mkdir -p "$dir/ctld" "$dir/spool"
  local port
  port=$(free_port_pair)
  write_conf "$dir" "$port"
  echo "export SLURM_CONF=$dir/slurm.conf" >"$dir/env"

  # munge: a fresh key, socket and logs inside DIR. --force: munged refuses root without it.
  dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
  chmod 600 "$dir/munge.key"
  /usr/sbin/munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/munged.pid" --seed-file="$dir/munged.seed" \
    --log-file="$dir/munged.log" || start_failed "$dir" "munged did not start"

  export SLURM_CONF=$dir/slurm.conf
  # Both daemons fork into the background; -i / -c: start clean, ignore saved state.
  /usr/sbin/slurmctld -i -c || start_failed "$dir" "slurmctld did not start"
  /usr/sbin/slurmd -N localhost || start_failed "$dir" "slurmd did not start"

  # Ready when the node is idle (up to 60 s; slurmd registers within seconds).
  local i state=""
  for ((i = 0; i < 120; ++i)); do
    state=$(sinfo -h -n localhost -o %T 2>/dev/null || true)
    [ "$state" = idle ] && { echo "slurm-local: up in $dir (ports $port, $((port + 1)))" >&2; return; }
    sleep 0.5
  done
  start_failed "$dir" "the node did not become idle (state '$state')"
}

# Shows the daemons' last log lines, stops whatever did start, and fails saying why.
start_failed() {
  local dir=$1 log
  for log in munged slurmctld slurmd; do
    [ ! -s "$dir/$log.log" ] || tail -n 20 "$dir/$log.log" >&2
  done
  stop "$dir"
  die "$2"
}

stop_pid_file() {
  local f=$1 pid i
  [ -s "$f" ] || return 0
  pid=$(cat "$f")
  kill "$pid" 2>/dev/null || return 0
  for ((i = 0; i < 50; ++i)); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.2
  done
  kill -9 "$pid" 2>/dev/null || true
}

stop() {
  local dir=$1
  [ -d "$dir" ] || return 0
  # Running jobs first: slurmd's children would otherwise outlive it.
  if [ -f "$dir/slurm.conf" ] && [ -s "$dir/slurmctld.pid" ]; then
    SLURM_CONF=$dir/slurm.conf scancel --full --quiet --partition=local 2>/dev/null || true
  fi
  stop_pid_file "$dir/slurmd.pid"
  stop_pid_file "$dir/slurmctld.pid"
  stop_pid_file "$dir/munged.pid"
  rm -rf "$dir"
}

case "${1:-}" in
  install) install_packages ;;
  start) [ $# -eq 2 ] || die "usage: $0 start DIR"; start "$2" ;;
  stop) [ $# -eq 2 ] || die "usage: $0 stop DIR"; stop "$2" ;;
  *) die "usage: $0 install | start DIR | stop DIR" ;;
esac
