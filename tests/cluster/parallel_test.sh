#!/usr/bin/env bash
# Tiles real elevation as 4 shards with GNU parallel through tools/cluster/parallel/run.sh, once
# on this machine and once through --sshloginfile with the login ":" (GNU parallel's name for this
# machine: the remote path without an ssh server), and checks that each pyramid is byte-identical
# to a one-machine run. Exits 77 (skipped) without GNU parallel (Debian: parallel).
#   parallel_test.sh GLOBE_TILER
set -euo pipefail
tiler=$(realpath "${1:?usage: $0 GLOBE_TILER}")
src=$(cd "$(dirname "$0")/../.." && pwd)
if ! parallel --version 2>/dev/null | grep -q 'GNU parallel'; then
  echo "skipped: GNU parallel missing (Debian: parallel)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# GNU parallel keeps its state under $HOME/.parallel; keep it out of the real home.
export HOME=$tmp/home
mkdir -p "$HOME"

inputs=$tmp/inputs.txt
printf '%s\n' "$src/data/dem/E138N35_FUJI.DEM" "$src/tests/data/dem/gtopo30/N50E008.DEM" \
  "$src/tests/data/dem/gtopo30/N50E009.DEM" >"$inputs"
opts=(--pack-tiles 8 -j 1 -q)
mapfile -t files <"$inputs"
"$tiler" -o "$tmp/single" "${opts[@]}" "${files[@]}"

export GLOBE_TILER=$tiler
bash "$src/tools/cluster/parallel/run.sh" "$tmp/local" "$inputs" 4 "${opts[@]}"
diff -r "$tmp/single" "$tmp/local" || { echo "FAIL: the local sharded pyramid differs"; exit 1; }

# Two logins: ":" (this machine, no ssh) and a host reached through a stand-in for ssh, which
# does what sshd does with GNU parallel's command (drop the host and "--", set SHELL to the
# login shell, run the rest in a shell in the home directory), so the shards it gets go through
# the remote code path: the quoting of the command line and paths that must not depend on the
# current directory. GNU parallel's remote worker runs the job with $SHELL and, without one,
# reports success having run nothing (CI runs with no SHELL; sshd always sets it).
cat >"$tmp/ssh" <<'SSH'
#!/bin/sh
echo "$1" >>"$HOME/ssh.log"
shift
[ "$1" = -- ] && shift
SHELL=$(getent passwd "$(id -u)" | cut -d: -f7)
export SHELL=${SHELL:-/bin/sh}
cd "$HOME" && exec sh -c "$*"
SSH
chmod +x "$tmp/ssh"
printf '%s\n' : "1/$tmp/ssh otherhost" >"$tmp/logins"
bash "$src/tools/cluster/parallel/run.sh" "$tmp/ssh out" "$inputs" 4 --sshloginfile "$tmp/logins" \
  "${opts[@]}"
diff -r "$tmp/single" "$tmp/ssh out" || { echo "FAIL: the --sshloginfile sharded pyramid differs"; exit 1; }
[ -s "$HOME/ssh.log" ] || { echo "FAIL: no shard went through the ssh login"; exit 1; }
echo "OK: 4 GNU parallel shards + merge == one-machine pyramid, locally and through" \
  "--sshloginfile ($(wc -l <"$HOME/ssh.log") shard(s) over ssh)"
