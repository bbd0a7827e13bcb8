#!/usr/bin/env bash
# Tiles a pyramid on a Slurm cluster: N shards as one job array, then the merge, which Slurm
# starts only when every shard succeeded (afterok) and cancels if one fails (so it never waits
# forever on a dependency that cannot be met).
#   submit.sh OUT INPUTS_FILE N [globe-tiler options]
# Prints "ARRAY_JOB_ID MERGE_JOB_ID". GLOBE_TILER is the program (default: globe-tiler on the
# nodes' PATH) and SBATCH_EXTRA extra sbatch options for both jobs (e.g. "-p big -t 2:00:00");
# sbatch's own SBATCH_* variables work too. Jobs run in the current directory (their logs too),
# so relative paths must mean the same on the nodes: use a shared file system for OUT.
set -euo pipefail
if [ $# -lt 3 ] || ! [[ $3 =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 OUT INPUTS_FILE N [globe-tiler options]" >&2
  exit 2
fi
out=$1 inputs=$2 n=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
read -r -a extra <<<"${SBATCH_EXTRA:-}"
# The shard count travels in the environment, not from the array's size (see tile-shards.sbatch);
# --export=ALL also carries GLOBE_TILER where a site makes SBATCH_EXPORT=NONE the default.
array=$(sbatch --parsable "${extra[@]}" --export="ALL,GLOBE_TILER_SHARDS=$n" \
  --array="0-$((n - 1))" "$here/tile-shards.sbatch" "$out" "$inputs" "$@")
array=${array%%;*} # --parsable prints "id;cluster" on federations
merge=$(sbatch --parsable "${extra[@]}" --export=ALL --dependency="afterok:$array" \
  --kill-on-invalid-dep=yes "$here/merge.sbatch" "$out" "$inputs" "$@")
merge=${merge%%;*}
echo "$array $merge"
