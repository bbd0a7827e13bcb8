#!/usr/bin/env bash
# Seams with imagery: nadir snapshots (north up) with the bundled Blue Marble and Zion layers,
# each centred on a tile edge (the antimeridian, an ordinary Blue Marble tile edge, 0° in England
# where W002N52 ends too, a Landsat tile edge over Zion), and per view the mean luma step across
# it against its neighbouring columns' (globe-image-seams --column). With
# BASELINE_BUILD (an earlier commit's build) its columns come first, with the pyramid and layers
# its own tiler makes (the layers' pixel grid is part of what changed). Writes
# docs/performance/imagery-seams.md.
#
#   tools/bench_render/seam_measure.sh BUILD [BASELINE_BUILD]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:?BUILD}
cmake --build "$BUILD" -j"$(nproc)" --target globe-image-seams >/dev/null  # tools/run-tests.sh builds only the tests
BASELINE=${2:-}
OUT_MD=$ROOT/docs/performance/imagery-seams.md
SEAMS=$BUILD/tools/bench_render/globe-image-seams
for exe in "$BUILD/apps/globe-tiler/globe-tiler" "$BUILD/apps/globe/globe" "$SEAMS" \
  ${BASELINE:+"$BASELINE/apps/globe/globe" "$BASELINE/apps/globe-tiler/globe-tiler"}; do
  [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
# Each build's own tiler: the layers' pixel grid is part of what is measured.
"$ROOT/tools/bench/tile_bundled.sh" "$BUILD/apps/globe-tiler/globe-tiler" "$WORK/new"
if [ -n "$BASELINE" ]; then
  "$ROOT/tools/bench/tile_bundled.sh" "$BASELINE/apps/globe-tiler/globe-tiler" "$WORK/base"
fi
# Views whose centre column (319 | 320 of 640) lies on a tile edge.
VIEWS=(
  "Blue Marble tile edge at ±180° (Fiji), 150 km=180.0,-16.5,150000"
  "Blue Marble tile edge at 168.75° W (open sea), 150 km=-168.75,-16.5,150000"
  "England along 0° (a tile edge and W002N52's east edge), 20 km=0.0,52.9,20000"
  "Landsat tile edge at 112.9834° W (Zion), 8 km=-112.98339844,37.25,8000"
)
score() {  # build side image camera
  "$1/apps/globe/globe" snapshot "$WORK/$2/pyramid" --layer "$WORK/$2/blue-marble" \
    --layer "$WORK/$2/zion" --camera "$4" --size 640x480 -o "$3" > /dev/null
  "$SEAMS" --column 319 "$3" | awk -F'\t' '{ printf "%.2f (%.2f)", $3, $4 }'
}
{
  label=$(git -C "$ROOT" log -1 --format=%h)
  if [ -n "$BASELINE" ]; then
    base=$(git -C "$BASELINE/.." log -1 --format=%h 2>/dev/null || echo baseline)
    echo "| view | $base: step (neighbours') | $label: step (neighbours') |"
    echo "|---|---|---|"
  else
    echo "| view | $label: step (neighbours') |"
    echo "|---|---|"
  fi
  n=0
  for view in "${VIEWS[@]}"; do
    name=${view%%=*} camera=${view#*=}
    n=$((n + 1))
    row="| $name |"
    if [ -n "$BASELINE" ]; then
      row="$row $(score "$BASELINE" base "$WORK/base-$n.png" "$camera") |"
    fi
    echo "$row $(score "$BUILD" new "$WORK/new-$n.png" "$camera") |"
  done
} > "$WORK/table.md"
{
  echo "# Seams with imagery"
  echo
  echo "Nadir snapshots (640×480, north up) with the bundled Blue Marble and Zion Landsat layers"
  echo "over the bundled pyramid, each centred on a tile edge, so that the edge runs between pixel"
  echo "columns 319 and 320. Per view: the mean luminance step across that edge, in levels of 255"
  echo "(\`globe-image-seams --column 319\`), and in brackets the median of the same step over the"
  echo "24 neighbouring columns: a seam is a step well above its neighbours'. Each build draws the"
  echo "pyramid and layers its own tiler made (the layers' pixel grid is part of what changed)."
  echo
  cat "$WORK/table.md"
  echo
  echo "Made by \`tools/bench_render/seam_measure.sh BUILD [BASELINE_BUILD]\` on $(date -u +%Y-%m-%d)."
} > "$OUT_MD"
cat "$WORK/table.md"
