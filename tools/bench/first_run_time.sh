#!/usr/bin/env bash
# Times the README's two commands as a new user runs them: a fresh clone of HEAD in a scratch
# directory with nothing beside it, `bash tools/setup.sh` then `bash tools/run-tests.sh`, each
# under /usr/bin/time, with ccache off (a cold build, as on a machine that never built globe).
# The Debian packages are installed already on a machine that ran this before, so apt-get only
# checks them; the README says what a truly new machine adds. Writes docs/performance/first-run-time.md.
#
#   tools/bench/first_run_time.sh
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OUT_MD=${OUT_MD:-$ROOT/docs/performance/first-run-time.md}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
COMMIT=$(git -C "$ROOT" rev-parse --short HEAD)
git clone -q "$ROOT" "$WORK/globe"
export CCACHE_DISABLE=1
cd "$WORK/globe"

timed() {  # name command... → seconds on stdout; the command's output in $WORK/name.log
  local name=$1
  shift
  if ! /usr/bin/time -f %e -o "$WORK/$name.time" "$@" >"$WORK/$name.log" 2>&1; then
    tail -40 "$WORK/$name.log" >&2
    echo "$name failed (its time is still recorded; the table says so)" >&2
    echo "$name" >>"$WORK/failed"
  fi
  tail -1 "$WORK/$name.time"
}
minutes() { awk -v s="$1" 'BEGIN {printf "%d min %02d s", s / 60, s % 60}'; }

setup=$(timed setup bash tools/setup.sh)
tests=$(timed tests bash tools/run-tests.sh)
passed=$(grep -Eo '[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$WORK/tests.log" | tail -1)
# CTest's own list ("<TAB>506 - NAME (Skipped)"), not run-tests.sh's "!!!" repeat of it.
skipped=$(grep -Ec '^[[:space:]]+[0-9]+ - .*\(Skipped\)$' "$WORK/tests.log" || true)
{
  echo "# The README's two commands, timed from a fresh clone"
  echo
  echo "A fresh clone of $COMMIT with nothing beside it (no \`../shared\`), ccache off (a cold"
  echo "build), the Debian packages already installed (so \`apt-get\` only checked them), on"
  echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores,"
  echo "$(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo); \`/usr/bin/time\`, wall clock."
  echo "Made by \`tools/bench/first_run_time.sh\` on $(date -u +%Y-%m-%d)."
  echo
  echo "| command | wall s | wall |"
  echo "|---|---|---|"
  echo "| \`bash tools/setup.sh\` (build globe + globe-tiler, tile, render, query, play the flight) | $setup | $(minutes "$setup") |"
  echo "| then \`bash tools/run-tests.sh\` (build the rest in the same \`build/\`, run the suite) | $tests | $(minutes "$tests") |"
  echo
  echo "- suite: $passed; $skipped skipped"
  echo "- goal (issue 47): the second command at most 10 min on a fresh 2-core machine"
  echo "- the test command's stages:"
  grep '^CI-time:' "$WORK/tests.log" | sed 's/^CI-time: */  - /' || true
  if [ -s "$WORK/failed" ]; then echo "- FAILED: $(tr '\n' ' ' <"$WORK/failed")"; fi
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
