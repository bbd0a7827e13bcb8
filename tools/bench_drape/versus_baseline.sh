#!/usr/bin/env bash
# Frame time with the bundled imagery layers (Blue Marble + Zion) of this build against a
# baseline build (an earlier commit built beside it), on the same data and views (each build's
# pyramid and layers made by its own tiler), and this build with the bundled water mask as well:
# RUNS alternating runs of each (5 rounds of 3 frames per run), then per view the median over
# the runs of each one's "with imagery" median, and the ratios to the baseline's.
# Writes docs/performance/imagery-versus-baseline.md.
#
#   tools/bench_drape/versus_baseline.sh BUILD BASELINE_BUILD [RUNS]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:?BUILD}
BASELINE=${2:?BASELINE_BUILD}
RUNS=${3:-5}
TILER=$BUILD/apps/globe-tiler/globe-tiler
for exe in "$TILER" "$BASELINE/apps/globe-tiler/globe-tiler" \
  "$BUILD/tools/bench_drape/globe-bench-drape" "$BASELINE/tools/bench_drape/globe-bench-drape"; do
  [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
# Each build's own tiler: a layer's format is part of what may have changed.
"$ROOT/tools/bench/tile_bundled.sh" "$BASELINE/apps/globe-tiler/globe-tiler" "$WORK/base"
"$ROOT/tools/bench/tile_bundled.sh" "$TILER" "$WORK/new"
VIEWS=(--view fuji_oblique=138.60,35.20,6000,30,-15,0 --view zion_oblique=-112.93,37.16,4500,330,-20,0
       --view zion_nadir=-112.98,37.27,9000 --view globe=138,30,20000000
       --view wash=0.3,52.9,60000 --view suruga_bay=138.62,34.85,9000,10,-25,0
       --rounds 5 --frames 3)
"$TILER" water-mask -q -o "$WORK/new/coast" "$ROOT/data/coast/gshhg-l-land.fgb" \
  "$ROOT"/data/coast/gshhg-f-*.fgb > /dev/null
for run in $(seq "$RUNS"); do
  for side in base new mask; do
    build=$BUILD dir=$WORK/$side extra=()
    [ "$side" = base ] && build=$BASELINE
    [ "$side" = mask ] && dir=$WORK/new extra=(--layer "$WORK/new/coast")
    "$build/tools/bench_drape/globe-bench-drape" --pyramid "$dir/pyramid" \
      --layer "$dir/blue-marble" --layer "$dir/zion" "${extra[@]}" "${VIEWS[@]}" \
      --out "$WORK/$side-$run.md" > /dev/null
    # view, with-imagery median ms, triangles with
    awk -F'|' 'NR > 2 { gsub(/ /, "", $2); print $2, $6, $10 }' "$WORK/$side-$run.md" \
      >> "$WORK/$side.txt"
  done
done
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
{
  echo "# Frame time with imagery against an earlier commit"
  echo
  echo "Steady frames (update + draw + glFinish, 1280×720, OSMesa llvmpipe) of four views with the"
  echo "bundled Blue Marble and Zion layers, this build against a baseline build of an earlier commit"
  echo "beside it, each over the pyramid and layers its own tiler made, and this build with the"
  echo "bundled water mask (data/coast) as a third layer: $RUNS alternating runs of each"
  echo "\`globe-bench-drape\` (5 rounds of 3 frames), per view the median of the runs' medians. Made by \`tools/bench_drape/versus_baseline.sh BUILD BASELINE_BUILD $RUNS\` on $(date -u +%Y-%m-%d)."
  echo
  echo "| view | baseline ms | this build ms | ratio | + water mask ms | ratio | triangles (baseline → this → + mask) |"
  echo "|---|---|---|---|---|---|---|"
  for view in $(awk '{ print $1 }' "$WORK/new.txt" | sort -u); do
    b=$(awk -v v="$view" '$1 == v { print $2 }' "$WORK/base.txt" | median)
    n=$(awk -v v="$view" '$1 == v { print $2 }' "$WORK/new.txt" | median)
    m=$(awk -v v="$view" '$1 == v { print $2 }' "$WORK/mask.txt" | median)
    tb=$(awk -v v="$view" '$1 == v { print $3 }' "$WORK/base.txt" | head -1)
    tn=$(awk -v v="$view" '$1 == v { print $3 }' "$WORK/new.txt" | head -1)
    tm=$(awk -v v="$view" '$1 == v { print $3 }' "$WORK/mask.txt" | head -1)
    awk -v v="$view" -v b="$b" -v n="$n" -v m="$m" -v tb="$tb" -v tn="$tn" -v tm="$tm" \
      'BEGIN { printf "| %s | %.1f | %.1f | %.2f | %.1f | %.2f | %s → %s → %s |\n", v, b, n, n / b, m, m / b, tb, tn, tm }'
  done
  echo
  echo "- baseline $(git -C "$BASELINE/.." log -1 --format=%h 2>/dev/null || echo "$BASELINE"), this build $(git -C "$ROOT" log -1 --format=%h)$(git -C "$ROOT" diff --quiet -- src shaders || echo " + uncommitted changes")"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; GL: llvmpipe"
} > "$ROOT/docs/performance/imagery-versus-baseline.md"
cat "$ROOT/docs/performance/imagery-versus-baseline.md"
