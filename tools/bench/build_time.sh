#!/usr/bin/env bash
# Cold build times of the ways the project can be built, measured in one run on one machine:
# per variant, an empty build directory configured like tools/configure.sh (RelWithDebInfo) with
# ccache off, then `globe` + `globe-tiler` (what tools/setup.sh builds), then everything else
# (what tools/run-tests.sh adds). Variants run in turn, ROUNDS times each, interleaved; the table
# gives the median wall times and their ratios to the plain build. Writes docs/performance/build-time.md.
#
#   tools/bench/build_time.sh [ROUNDS] [VARIANT...]
#
# Variants (default: plain unity unity-g): plain: file by file; unity: GLOBE_UNITY_BUILD (the
# default configuration); unity-g: unity with the tests' full debug info instead of -g1; pch: file
# by file with precompiled headers.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
ROUNDS=${1:-1}
shift || true
VARIANTS=("$@")
[ ${#VARIANTS[@]} -gt 0 ] || VARIANTS=(plain unity unity-g)
OUT_MD=${OUT_MD:-$ROOT/docs/performance/build-time.md}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export CCACHE_DISABLE=1

flagsOf() {
  case $1 in
    plain) echo "-DGLOBE_UNITY_BUILD=OFF" ;;
    unity) echo "-DGLOBE_UNITY_BUILD=ON" ;;
    unity-g) echo "-DGLOBE_UNITY_BUILD=ON -DGLOBE_FULL_DEBUG_INFO=ON" ;;
    pch) echo "-DGLOBE_UNITY_BUILD=OFF -DGLOBE_PRECOMPILED_HEADERS=ON" ;;
    *) echo "unknown variant $1" >&2; exit 2 ;;
  esac
}

seconds() { local start=$1; echo "$(($(date +%s%N) - start))" | awk '{printf "%.1f", $1 / 1e9}'; }

for ((round = 0; round < ROUNDS; ++round)); do
  for variant in "${VARIANTS[@]}"; do
    dir=$WORK/$variant
    rm -rf "$dir"
    # shellcheck disable=SC2046
    cmake -S "$ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo $(flagsOf "$variant") >/dev/null
    start=$(date +%s%N)
    cmake --build "$dir" -j"$(nproc)" --target globe globe-tiler >"$WORK/log" 2>&1 ||
      { tail -30 "$WORK/log" >&2; echo "$variant: the build failed" >&2; exit 1; }
    first=$(seconds "$start")
    start=$(date +%s%N)
    cmake --build "$dir" -j"$(nproc)" >"$WORK/log" 2>&1 ||
      { tail -30 "$WORK/log" >&2; echo "$variant: the build failed" >&2; exit 1; }
    rest=$(seconds "$start")
    echo "$variant $first $rest" >>"$WORK/times"
    echo "round $((round + 1)): $variant: globe + globe-tiler ${first} s, the rest ${rest} s" >&2
    rm -rf "$dir"
  done
done

median() { sort -g | awk '{v[NR]=$1} END {if (NR % 2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }
basefirst=$(awk '$1 == "plain" {print $2}' "$WORK/times" | median)
baserest=$(awk '$1 == "plain" {print $3}' "$WORK/times" | median)
{
  echo "# Build time"
  echo
  echo "Cold builds (empty build directory, ccache off, RelWithDebInfo, \`-j$(nproc)\`): first"
  echo "\`globe\` + \`globe-tiler\` (what \`tools/setup.sh\` builds), then everything else in the same"
  echo "directory (what \`tools/run-tests.sh\` adds: tests, benchmarks, tools). Median wall time of"
  echo "$ROUNDS interleaved round(s) per variant, and the ratio to the plain build of the same run."
  echo "Made by \`tools/bench/build_time.sh\` on $(date -u +%Y-%m-%d)."
  echo
  echo "| variant | cmake flags | globe + globe-tiler, s | vs plain | the rest, s | vs plain | total, s |"
  echo "|---|---|---|---|---|---|---|"
  for variant in "${VARIANTS[@]}"; do
    f=$(awk -v v="$variant" '$1 == v {print $2}' "$WORK/times" | median)
    r=$(awk -v v="$variant" '$1 == v {print $3}' "$WORK/times" | median)
    flag=$(flagsOf "$variant")
    awk -v v="$variant" -v flag="${flag:-–}" -v f="$f" -v r="$r" -v bf="$basefirst" -v br="$baserest" \
      'BEGIN {printf "| %s | `%s` | %.0f | %.2f | %.0f | %.2f | %.0f |\n", v, flag, f, (bf > 0 ? f / bf : 0), r, (br > 0 ? r / br : 0), f + r}'
  done
  echo
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- . ':!docs' || echo ' + uncommitted changes')"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; $(g++ --version | head -1)"
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
