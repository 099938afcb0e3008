#!/bin/bash
# lafortune's test fixtures: a real single-node Slurm cluster (munged,
# slurmctld, slurmd) and a real OpenSSH server, on 127.0.0.1, each in a
# scratch folder of its own.  Used by test/test_database.m.
#
#   test/cluster.sh slurm-start DIR   write DIR/slurm.conf and a munge key, start
#                                     the three daemons, wait until the node is idle;
#                                     clients then need SLURM_CONF=DIR/slurm.conf
#   test/cluster.sh slurm-stop DIR    cancel the cluster's jobs, stop its daemons
#   test/cluster.sh sshd-start DIR    a host key, a user key, sshd on a free port;
#                                     DIR/ssh_config names the hosts node-a and node-b
#   test/cluster.sh sshd-stop DIR     stop that sshd
#
# Everything stays in DIR (keys, sockets, state, logs, pid files), the daemons
# listen on 127.0.0.1 only, and a stop kills only the process ids its start
# wrote down (and, for Slurm, the job steps of this cluster).  Every wait is
# bounded.  A start that fails prints the daemon's own message and exits 1;
# exit 2 means the Debian packages are missing (slurm-wlm and munge;
# openssh-server and openssh-client).
set -uo pipefail

die () { echo "cluster.sh: $*" >&2; exit 1; }

# a TCP port on 127.0.0.1 that nothing listens on (the start retries if one
# is taken between this check and the daemon's bind)
free_port () {
  local p i
  for i in $(seq 1 50); do
    p=$(( 20000 + RANDOM % 40000 ))
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then
      echo "$p"; return 0
    fi
  done
  die "no free TCP port found on 127.0.0.1"
}

# wait (at most $2 tenths of a second) until command $1 succeeds
wait_for () {
  local i
  for i in $(seq 1 "$2"); do
    eval "$1" >/dev/null 2>&1 && return 0
    sleep 0.1
  done
  return 1
}

# stop the process whose id is in file $1: TERM, then KILL after 5 s
stop_pid () {
  local f=$1 pid
  [ -s "$f" ] || return 0
  pid=$(cat "$f")
  [ "$pid" -gt 1 ] 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null || { rm -f "$f"; return 0; }
  wait_for "! kill -0 $pid" 50 || kill -KILL "$pid" 2>/dev/null
  wait_for "! kill -0 $pid" 20
  rm -f "$f"
}

slurm_start () {
  local d=$1 host user port1 port2 try
  command -v munged >/dev/null && command -v slurmctld >/dev/null && command -v slurmd >/dev/null &&
    command -v sbatch >/dev/null ||
    { echo "cluster.sh: no munged/slurmctld/slurmd/sbatch (Debian packages slurm-wlm and munge)" >&2; exit 2; }
  mkdir -p "$d"/{munge,run,state,spool,log} || die "cannot make folders in $d"
  chmod 700 "$d/munge"; chmod 755 "$d/run"
  head -c 1024 /dev/urandom > "$d/munge/munge.key" && chmod 400 "$d/munge/munge.key"
  munged --socket="$d/run/munge.sock" --key-file="$d/munge/munge.key" \
         --log-file="$d/log/munged.log" --pid-file="$d/run/munged.pid" \
         --seed-file="$d/munge/munged.seed" ||
    die "munged did not start: $(tail -n 3 "$d/log/munged.log" 2>/dev/null)"
  wait_for "[ -S '$d/run/munge.sock' ]" 50 || die "munged made no socket: $(tail -n 3 "$d/log/munged.log")"
  host=$(hostname -s) user=$(id -un)
  export SLURM_CONF="$d/slurm.conf"
  for try in 1 2 3; do
    port1=$(free_port) port2=$(free_port)
    cat > "$SLURM_CONF" <<EOF
# a single-node Slurm cluster for lafortune's tests (test/cluster.sh)
ClusterName=lafortune-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port1
SlurmdPort=$port2
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/run/munge.sock
SlurmUser=$user
SlurmdUser=$user
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/run/slurmctld.pid
SlurmdPidFile=$d/run/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
PlugStackConfig=/dev/null
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
    slurmctld -f "$SLURM_CONF" 2>"$d/log/slurmctld.err" &&
      wait_for "[ -s '$d/run/slurmctld.pid' ] && scontrol ping | grep -q UP" 100 && break
    stop_pid "$d/run/slurmctld.pid"
    [ "$try" = 3 ] && die "slurmctld did not start: $(cat "$d/log/slurmctld.err"; tail -n 5 "$d/log/slurmctld.log" 2>/dev/null)"
  done
  slurmd -f "$SLURM_CONF" 2>"$d/log/slurmd.err" ||
    die "slurmd did not start: $(cat "$d/log/slurmd.err"; tail -n 5 "$d/log/slurmd.log" 2>/dev/null)"
  wait_for "sinfo -h -o %t | grep -qx idle" 200 ||
    die "the node is not idle after 20 s: $(sinfo -h -o '%t %E' 2>&1; tail -n 5 "$d/log/slurmd.log")"
  echo "cluster.sh: Slurm $(sinfo --version | cut -d' ' -f2), one node ($host, $(nproc) CPUs), SLURM_CONF=$SLURM_CONF"
}

slurm_stop () {
  local d=$1 f
  export SLURM_CONF="$d/slurm.conf"
  if [ -s "$d/run/slurmctld.pid" ] && [ -f "$SLURM_CONF" ]; then
    scancel --full --quiet --user="$(id -un)" 2>/dev/null
    # the cancelled jobs leave the queue (their slurmstepd end with them)
    wait_for "! squeue -h | grep -q ." 100
  fi
  stop_pid "$d/run/slurmd.pid"
  stop_pid "$d/run/slurmctld.pid"
  stop_pid "$d/run/munged.pid"
  return 0
}

sshd_start () {
  local d=$1 port try user
  command -v sshd >/dev/null || [ -x /usr/sbin/sshd ] ||
    { echo "cluster.sh: no sshd (Debian package openssh-server)" >&2; exit 2; }
  command -v ssh >/dev/null && command -v ssh-keygen >/dev/null ||
    { echo "cluster.sh: no ssh (Debian package openssh-client)" >&2; exit 2; }
  mkdir -p "$d" && chmod 700 "$d"
  rm -f "$d/host_key" "$d/user_key"
  ssh-keygen -q -t ed25519 -N '' -C lafortune-test-host -f "$d/host_key" || die "ssh-keygen failed"
  ssh-keygen -q -t ed25519 -N '' -C lafortune-test-user -f "$d/user_key" || die "ssh-keygen failed"
  cp "$d/user_key.pub" "$d/authorized_keys"
  # sshd started by root needs its privilege-separation folder (Debian's
  # service makes it at boot; a container without an init system has none)
  if [ "$(id -u)" = 0 ] && [ ! -d /run/sshd ]; then
    mkdir -p /run/sshd && chmod 755 /run/sshd && touch "$d/made-run-sshd"
  fi
  user=$(id -un)
  for try in 1 2 3; do
    port=$(free_port)
    cat > "$d/sshd_config" <<EOF
ListenAddress 127.0.0.1
Port $port
HostKey $d/host_key
PidFile $d/sshd.pid
AuthorizedKeysFile $d/authorized_keys
PasswordAuthentication no
KbdInteractiveAuthentication no
UsePAM no
StrictModes no
PermitRootLogin prohibit-password
AllowUsers $user
EOF
    "$(command -v sshd || echo /usr/sbin/sshd)" -f "$d/sshd_config" -E "$d/sshd.log" &&
      wait_for "[ -s '$d/sshd.pid' ]" 50 && break
    stop_pid "$d/sshd.pid"
    [ "$try" = 3 ] && die "sshd did not start: $(tail -n 5 "$d/sshd.log" 2>/dev/null)"
  done
  echo "[127.0.0.1]:$port $(cut -d' ' -f1-2 "$d/host_key.pub")" > "$d/known_hosts"
  cat > "$d/ssh_config" <<EOF
Host node-a node-b
  HostName 127.0.0.1
  Port $port
  User $user
  IdentityFile $d/user_key
  IdentitiesOnly yes
  UserKnownHostsFile $d/known_hosts
  StrictHostKeyChecking yes
  BatchMode yes
  ConnectTimeout 10
EOF
  wait_for "ssh -F '$d/ssh_config' node-a true" 100 ||
    die "ssh to the test server fails: $(ssh -F "$d/ssh_config" node-a true 2>&1; tail -n 5 "$d/sshd.log")"
  echo "cluster.sh: $(ssh -V 2>&1 | cut -d, -f1) on 127.0.0.1:$port, hosts node-a and node-b in $d/ssh_config"
}

sshd_stop () {
  local d=$1
  stop_pid "$d/sshd.pid"
  if [ -f "$d/made-run-sshd" ]; then rmdir /run/sshd 2>/dev/null; rm -f "$d/made-run-sshd"; fi
  return 0
}

[ $# = 2 ] || die "usage: test/cluster.sh slurm-start|slurm-stop|sshd-start|sshd-stop DIR"
dir=$(cd "$2" 2>/dev/null && pwd) || { mkdir -p "$2" && dir=$(cd "$2" && pwd); } || die "no folder $2"
case $1 in
  slurm-start) slurm_start "$dir" ;;
  slurm-stop) slurm_stop "$dir" ;;
  sshd-start) sshd_start "$dir" ;;
  sshd-stop) sshd_stop "$dir" ;;
  *) die "unknown command $1 (slurm-start, slurm-stop, sshd-start, sshd-stop)" ;;
esac
