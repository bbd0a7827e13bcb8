#!/usr/bin/env bash
# Tiles a pyramid as N shards with GNU parallel, then merges them here:
#   run.sh OUT INPUTS_FILE N [--sshloginfile FILE] [globe-tiler options]
# Without --sshloginfile the shards run on this machine (as many at once as it has cores: pass
# globe-tiler's -j to share them). With it they run on the hosts listed there (GNU parallel's
# format: [ncpus/]host per line; ":" is this machine, without ssh). Over ssh, OUT must be on a file
# system every host and this one share, at the same path, and the inputs (or /vsicurl/ URLs)
# readable there; GLOBE_TILER (default: globe-tiler on each host's PATH) must exist on every host.
# The first failing shard stops the others; rerunning the same command resumes, as each shard
# does. The merge runs only when every shard succeeded.
set -euo pipefail
if [ $# -lt 3 ] || ! [[ $3 =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 OUT INPUTS_FILE N [--sshloginfile FILE] [globe-tiler options]" >&2
  exit 2
fi
# Absolute paths: remote commands start in the login's home directory, not here.
out=$(realpath -m "$1") inputs=$(realpath "$2") n=$3
shift 3
hosts=()
if [ "${1:-}" = --sshloginfile ]; then
  hosts=(--sshloginfile "$(realpath "${2:?--sshloginfile needs a file}")")
  shift 2
fi
tiler=${GLOBE_TILER:-globe-tiler}
if [[ $tiler == */* ]]; then tiler=$(realpath "$tiler"); fi
# -q quotes every word for the (remote) shell, so paths and options with spaces survive; {} is
# the shard index.
parallel --will-cite -q --halt now,fail=1 --line-buffer --tagstring 'shard {}' "${hosts[@]}" \
  "$tiler" --shard "{}/$n" -o "$out" --inputs "$inputs" "$@" ::: $(seq 0 $((n - 1))) </dev/null
"$tiler" merge -o "$out" --inputs "$inputs" "$@"
