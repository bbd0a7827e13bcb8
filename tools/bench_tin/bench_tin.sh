#!/usr/bin/env bash
# The quantized-mesh exporter's TINs against @mapbox/martini and delatin on the same real tiles
# at the same maximum errors (one run: triangles, the error each really has, time), and the
# export itself (tiles/s, bytes per tile) against the whole grid and the pyramid's own packs.
# Usage: tools/bench_tin/bench_tin.sh [BUILD_DIR] [PYRAMID]  (defaults: build, pyramid/ of
# tools/setup.sh). Needs tools/web's node packages (tools/web/install.sh). Writes
# docs/performance/tin-simplification.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
PYRAMID=${2:-pyramid}
cmake --build "$BUILD" --target globe-bench-tin globe-tiler -j"$(nproc)" >/dev/null
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
BENCH=$BUILD/tools/bench_tin/globe-bench-tin
TILER=$BUILD/apps/globe-tiler/globe-tiler
# Fuji's volcano (3″ SRTM), Zion's canyons (3″ SRTM), and Wales (30″ GTOPO30), two levels above
# their finest so each sample is a pyramid vertex.
"$BENCH" "$PYRAMID" -o "$WORK/fuji" --level 10 --bounds 138.3,35.1,139,35.7 --errors 1,5,20 >/dev/null
"$BENCH" "$PYRAMID" -o "$WORK/zion" --level 10 --bounds -113.2,37.1,-112.8,37.4 --errors 1,5,20 >/dev/null
"$BENCH" "$PYRAMID" -o "$WORK/wales" --level 9 --bounds -2,52,-1,53 --errors 1,5,20 >/dev/null
TABLE=$(node tools/bench_tin/compare.mjs "$WORK/fuji" "$WORK/zion" "$WORK/wales")

# The export: the whole pyramid, TINs (the default) and the whole grid (--mesh-error 0).
export_row() {
  local label=$1; shift
  local start end tiles bytes
  start=$(date +%s.%N)
  local dir="$WORK/export-${label//[^a-z0-9]/_}"
  "$TILER" export --format quantized-mesh -o "$dir" "$@" "$PYRAMID" >/dev/null
  end=$(date +%s.%N)
  tiles=$(find "$dir" -name '*.terrain' | wc -l)
  bytes=$(find "$dir" -name '*.terrain' -printf '%s\n' | awk '{s += $1} END {print s}')
  awk -v l="$label" -v t="$tiles" -v b="$bytes" -v s="$(echo "$end - $start" | bc)" \
    'BEGIN {printf "| %s | %d | %.1f | %.0f | %.2f |\n", l, t, s, t / s, b / t / 1024}'
}
PACK_BYTES=$(find "$PYRAMID" -name '*.pack' -printf '%s\n' | awk '{s += $1} END {print s}')
PACK_TILES=$(python3 -c "import json,sys; m=json.load(open('$PYRAMID/manifest.json')); print(sum(l.get('tiles', 0) for l in m['levels']))" 2>/dev/null || echo 0)
CORES=$(nproc)
EXPORTS=$(export_row "tin, 1 thread" -j 1; export_row "tin, $CORES threads" -j "$CORES"
  export_row "whole grid, 1 thread" --mesh-error 0 -j 1)

{
  echo "# TIN simplification of the quantized-mesh export"
  echo
  echo "Made by \`tools/bench_tin/bench_tin.sh\` on $(date -u +%Y-%m-%d) ($(nproc) cores, $(uname -m))."
  echo "Each tile's 65×65 grid of the pyramid's exact surface (tools/setup.sh's pyramid), simplified"
  echo "by globe (\`publish/tin_simplifier\`), \`@mapbox/martini\` $(node -p "require('./tools/web/node_modules/@mapbox/martini/package.json').version") (RTIN) and"
  echo "\`delatin\` $(node -p "require('./tools/web/node_modules/delatin/package.json').version") (greedy Delaunay insertion) at the same maximum error. The error"
  echo "each really has is measured by one evaluator over every sample (\`compare.mjs\`); martini's"
  echo "parameter is an approximation and its meshes exceed it, so at an equal real error it would"
  echo "need more triangles than shown. Times: globe in C++, the others in node."
  echo
  echo "$TABLE"
  echo
  echo "## The export"
  echo
  echo "\`globe-tiler export --format quantized-mesh\` of the whole pyramid: each tile's TIN within"
  echo "its geometric error (the default) and the whole 65×65 grid (\`--mesh-error 0\`), each with"
  echo "normals, water mask and metadata. The packs: the pyramid the tiler wrote (every level)."
  echo
  echo "| tree | tiles | s | tiles/s | KiB/tile (gzip) |"
  echo "|---|---|---|---|---|"
  echo "$EXPORTS"
  if [ "$PACK_TILES" -gt 0 ]; then
    awk -v b="$PACK_BYTES" -v t="$PACK_TILES" 'BEGIN {printf "| the pyramid'"'"'s packs (17×17 blocks) | %d | | | %.2f |\n", t, b / t / 1024}'
  fi
} > docs/performance/tin-simplification.md
cat docs/performance/tin-simplification.md
