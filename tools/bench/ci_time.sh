#!/usr/bin/env bash
# Times `bash .ci/run` as CI runs it: a clean clone of HEAD in a new folder with ../shared beside
# it, a clean environment, then the CI-time lines and the compiler cache's hit rate for the run.
# --cold empties the compiler cache first (what a machine that never built globe sees); without
# it the cache is what earlier builds left (the usual case: CI on the developer's machine). Needs
# root, as CI (apt, tmpfs, Slurm). Prints the run's CI-time lines and the cache's hits and misses.
#
#   tools/bench/ci_time.sh [--cold] FOLDER
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
COLD=0
if [ "${1:-}" = --cold ]; then COLD=1; shift; fi
FOLDER=${1:?a new folder for the clone}
mkdir -p "$FOLDER"
FOLDER=$(cd "$FOLDER" && pwd)
[ -e "$FOLDER/main" ] && { echo "$FOLDER/main exists already" >&2; exit 1; }
git clone -q "$ROOT" "$FOLDER/main"
ln -sfn "$(cd "$ROOT/../shared" && pwd)" "$FOLDER/shared"
if [ "$COLD" = 1 ]; then ccache -C >/dev/null; fi
ccache -z >/dev/null
status=0
env -i PATH="$PATH" HOME="$HOME" LANG=C.UTF-8 bash "$FOLDER/main/.ci/run" \
  >"$FOLDER/ci.log" 2>&1 || status=$?
echo "commit $(git -C "$FOLDER/main" rev-parse --short HEAD), $([ "$COLD" = 1 ] && echo cold || echo warm) cache, exit $status, log $FOLDER/ci.log"
sed -n '/^== CI time per stage/,$p' "$FOLDER/ci.log"
ccache -s | grep -E '^ *(Hits|Misses|Cacheable|  Direct|  Preprocessed)' || true
exit "$status"
