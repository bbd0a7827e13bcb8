#!/usr/bin/env bash
# What the bundled water mask costs per frame where it shows: the bundled pyramid with the mask as
# its only layer (no imagery: the terrain's own colours, whose land and sea it decides), against
# the same views without it, interleaved in one globe-bench-drape process (5 rounds of 3 frames).
# "Same tiles" compares frames of the same tile set (the shader's cost); "as the viewer runs"
# includes the terrain refining near coasts for the mask. Writes
# docs/performance/water-mask-frame-time.md.
#
#   tools/bench_drape/water_mask_cost.sh [BUILD]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-bench-drape >/dev/null  # tools/run-tests.sh builds only the tests
TILER=$BUILD/apps/globe-tiler/globe-tiler
BENCH=$BUILD/tools/bench_drape/globe-bench-drape
for exe in "$TILER" "$BENCH"; do [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }; done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$ROOT/tools/bench/tile_bundled.sh" "$TILER" "$WORK"
"$TILER" water-mask -q -o "$WORK/coast" "$ROOT/data/coast/gshhg-l-land.fgb" \
  "$ROOT"/data/coast/gshhg-f-*.fgb > /dev/null
"$BENCH" --pyramid "$WORK/pyramid" --layer "$WORK/coast" \
  --view fuji_oblique=138.60,35.20,6000,30,-15,0 --view suruga_bay=138.62,34.85,9000,10,-25,0 \
  --view wash=0.3,52.9,60000 --view europe=2,54,2500000 --view globe=138,30,20000000 \
  --rounds 5 --frames 3 --out "$WORK/table.md" > /dev/null
{
  echo "# What the water mask costs per frame"
  echo
  echo "Steady frames (update + draw + glFinish, 1280×720, OSMesa llvmpipe) of the bundled pyramid"
  echo "with the bundled water mask (data/coast) as its only layer, against the same views without"
  echo "it, interleaved in one \`globe-bench-drape\` process (5 rounds of 3 frames; medians)."
  echo "\"Ratio, same tiles\": the shader's cost on the same tile set; \"as the viewer runs\": with the"
  echo "terrain refined near coasts for the mask. Under an opaque world layer (the Blue Marble) the"
  echo "mask is neither loaded nor drawn: docs/performance/imagery-versus-baseline.md."
  echo
  echo "| view | without ms | with the mask ms | ratio as the viewer runs | ratio, same tiles | triangles without → with |"
  echo "|---|---|---|---|---|---|"
  awk -F'|' 'NR > 2 { gsub(/ /, "", $2); printf "| %s | %s | %s | %s | %s | %s → %s |\n", $2, $4, $6, $7, $8, $9, $10 }' "$WORK/table.md" | sed 's/  */ /g'
  echo
  echo "Made by \`tools/bench_drape/water_mask_cost.sh BUILD\` on $(date -u +%Y-%m-%d), commit $(git -C "$ROOT" log -1 --format=%h)$(git -C "$ROOT" diff --quiet -- src shaders || echo " + uncommitted changes")."
  echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores."
} > "$ROOT/docs/performance/water-mask-frame-time.md"
cat "$ROOT/docs/performance/water-mask-frame-time.md"
