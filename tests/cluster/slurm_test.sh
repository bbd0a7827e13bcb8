#!/usr/bin/env bash
# Tiles real elevation on a real one-node Slurm cluster through tools/cluster/slurm/submit.sh (a
# 3-task job array, then the merge job depending on it) and checks that the pyramid is byte-
# identical to a one-machine run. munged, slurmctld and slurmd are started here with their own
# key, configuration, sockets and state in a temporary directory, on 127.0.0.1 only, and are
# always stopped. Needs root (slurmd starts jobs as any user) and Debian's slurm-wlm and munge;
# exits 77 (skipped) without them.
#   slurm_test.sh GLOBE_TILER
set -euo pipefail
tiler=$(realpath "${1:?usage: $0 GLOBE_TILER}")
src=$(cd "$(dirname "$0")/../.." && pwd)
PATH=$PATH:/usr/sbin:/sbin # the daemons, where a non-login PATH lacks them
if [ "$(id -u)" -ne 0 ]; then echo "skipped: needs root"; exit 77; fi
for cmd in munged slurmctld slurmd sbatch scontrol scancel sinfo python3; do
  command -v "$cmd" >/dev/null || { echo "skipped: $cmd missing (Debian: slurm-wlm munge)"; exit 77; }
done
# An outer Slurm job's variables would leak into sbatch and the jobs.
while read -r v; do unset "$v"; done < <(compgen -e | grep -E '^(SLURM|SBATCH|SALLOC)_' || true)

tmp=$(mktemp -d)
pids=()
cleanup() {
  set +e
  if [ -f "$tmp/slurm.conf" ] && [ ${#pids[@]} -gt 1 ]; then
    # Cancel what still runs first: slurmstepd and the jobs outlive a stopped slurmd.
    scancel --full --user=root >/dev/null 2>&1
    for _ in $(seq 20); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.5; done
  fi
  # Each slurmstepd holds a socket in the spool directory until it has exited.
  for _ in $(seq 20); do compgen -G "$tmp/spool/localhost_*" >/dev/null || break; sleep 0.5; done
  # slurmd, slurmctld, then munged, which the other two talk to while they stop.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
    kill "${pids[i]}" 2>/dev/null
    for _ in $(seq 20); do kill -0 "${pids[i]}" 2>/dev/null || break; sleep 0.5; done
    kill -9 "${pids[i]}" 2>/dev/null
    wait "${pids[i]}" 2>/dev/null
  done
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' INT TERM
fail() {
  echo "FAIL: $*"
  for f in "$tmp"/jobs/*.out "$tmp"/*.log; do [ -f "$f" ] && { echo "--- $f"; tail -n 30 "$f"; }; done
  exit 1
}

# munged insists that everyone may traverse its socket's directory and no one else reads the key.
chmod 755 "$tmp"
if command -v mungekey >/dev/null; then
  mungekey --create --keyfile="$tmp/munge.key"
else
  dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
fi
chmod 600 "$tmp/munge.key"
munged --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" \
  --pid-file="$tmp/munged.pid" --seed-file="$tmp/munged.seed" --log-file="$tmp/munged.log" \
  >>"$tmp/munged.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$tmp/munge.socket" ] && break; sleep 0.1; done
[ -S "$tmp/munge.socket" ] || fail "munged did not start"

# Two free ports on 127.0.0.1 (a running site Slurm keeps 6817/6818).
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/jobs"
# No cgroups (a container has no systemd to delegate them) and no accounting database. The
# controller must be this host's name; NoInAddrAny keeps both daemons on 127.0.0.1.
# kill_invalid_depend: a failed shard cancels the merge instead of leaving it pending.
cat >"$tmp/slurm.conf" <<CONF
ClusterName=globetest
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
CommunicationParameters=NoCtldInAddrAny,NoInAddrAny
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerParameters=kill_invalid_depend
ReturnToService=2
MinJobAge=3600
MpiDefault=none
SwitchType=switch/none
MailProg=/bin/true
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" >/dev/null 2>&1 &
pids+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" >/dev/null 2>&1 &
pids+=($!)
for _ in $(seq 60); do [ "$(sinfo -h -n localhost -o %t 2>/dev/null)" = idle ] && break; sleep 0.5; done
[ "$(sinfo -h -n localhost -o %t 2>/dev/null)" = idle ] || fail "the node did not come up idle"

inputs=$tmp/inputs.txt
printf '%s\n' "$src/data/dem/E138N35_FUJI.DEM" "$src/tests/data/dem/gtopo30/N50E008.DEM" \
  "$src/tests/data/dem/gtopo30/N50E009.DEM" >"$inputs"
opts=(--pack-tiles 8 -j 1 -q)
cd "$tmp/jobs"
ids=$(GLOBE_TILER=$tiler bash "$src/tools/cluster/slurm/submit.sh" "$tmp/sharded" "$inputs" 3 \
  "${opts[@]}") || fail "submit.sh failed"
read -r array merge <<<"$ids"
echo "shards: job $array, merge: job $merge"
# The one-machine pyramid meanwhile.
mapfile -t files <"$inputs"
"$tiler" -o "$tmp/single" "${opts[@]}" "${files[@]}"

state() { scontrol show job -o "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | paste -sd,; }
deadline=$((SECONDS + 300))
while :; do
  s=$(state "$merge")
  case $s in
    COMPLETED) break ;;
    FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE)
      fail "merge job $merge $s (shards: $(state "$array"))" ;;
  esac
  [ $SECONDS -lt $deadline ] || fail "merge job $merge still ${s:-unknown} after 300 s (shards: $(state "$array"))"
  sleep 1
done
[ "$(state "$array")" = COMPLETED ] || fail "shard tasks: $(state "$array")"
[ "$(scontrol show job -o "$array" | grep -c JobState=COMPLETED)" = 3 ] || fail "not 3 shard tasks"
diff -r "$tmp/single" "$tmp/sharded" || fail "the sharded pyramid differs from the one-machine one"
echo "OK: 3 Slurm shards + merge == one-machine pyramid ($(find "$tmp/sharded" -type f | wc -l) files)"
