#!/usr/bin/env bash
# Seams with imagery: nadir snapshots (north up, so tile edges and meridians are columns and
# parallels rows) with the bundled Blue Marble and Zion layers, scored by globe-image-seams: the
# worst column's or row's step over its neighbours' median (natural ground 1.2-1.6; a straight
# step stands out above 2) and that step's excess in luma levels (of 255; for views with little
# texture). Views over tile edges of several levels, a source boundary (0° in England: W002N52's
# east edge), the antimeridian, and the Landsat footprint's edge over the Blue Marble. With
# BASELINE_BUILD (an earlier commit's build) its columns come first; the same pyramid and layers,
# tiled by BUILD. Writes docs/performance/imagery-seams.md.
#
#   tools/bench_render/seam_measure.sh BUILD [BASELINE_BUILD]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:?BUILD}
BASELINE=${2:-}
OUT_MD=$ROOT/docs/performance/imagery-seams.md
SEAMS=$BUILD/tools/bench_render/globe-image-seams
for exe in "$BUILD/apps/globe-tiler/globe-tiler" "$BUILD/apps/globe/globe" "$SEAMS" \
  ${BASELINE:+"$BASELINE/apps/globe/globe"}; do
  [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
D=$ROOT/data
TILER=$BUILD/apps/globe-tiler/globe-tiler
"$TILER" -q -o "$WORK/pyramid" "$D/dem/ETOPO20.DEM" "$D/dem/W002N52.DEM" "$D/dem/E138N35_FUJI.DEM" \
  "$D/dem/zion-srtm3.tif" > /dev/null
"$TILER" imagery -q -o "$WORK/blue-marble" --bounds -180,-90,180,90 \
  "$D/imagery/world.topo.bathy.200412.3x5400x2700.jpg" > /dev/null
"$TILER" imagery -q -o "$WORK/zion" "$D/imagery/zion-landsat8-rgb.tif" > /dev/null
VIEWS=(
  "Zion, 20 km=-113.05,37.32,20000"
  "Zion, 60 km=-113.00,37.30,60000"
  "Landsat footprint's west edge, 30 km=-113.27,37.30,30000"
  "Mount Fuji, 20 km=138.73,35.36,20000"
  "England across 0°, 60 km=0.0,52.5,60000"
  "England across 0°, 20 km=0.0,52.9,20000"
  "Fiji across ±180°, 150 km=180.0,-16.5,150000"
)
score() {  # globe image
  "$1" snapshot "$WORK/pyramid" --layer "$WORK/blue-marble" --layer "$WORK/zion" \
    --camera "$3" --size 640x480 -o "$2" > /dev/null
  "$SEAMS" "$2" | awk -F'\t' '{ printf "%.2f (%.2f levels)", $1, $2 }'
}
{
  label=$(git -C "$ROOT" log -1 --format=%h)
  if [ -n "$BASELINE" ]; then
    base=$(git -C "$BASELINE/.." log -1 --format=%h 2>/dev/null || echo baseline)
    echo "| view | $base: score (excess step) | $label: score (excess step) |"
    echo "|---|---|---|"
  else
    echo "| view | $label: score (excess step) |"
    echo "|---|---|"
  fi
  n=0
  for view in "${VIEWS[@]}"; do
    name=${view%%=*} camera=${view#*=}
    n=$((n + 1))
    row="| $name |"
    if [ -n "$BASELINE" ]; then
      row="$row $(score "$BASELINE/apps/globe/globe" "$WORK/base-$n.png" "$camera") |"
    fi
    echo "$row $(score "$BUILD/apps/globe/globe" "$WORK/new-$n.png" "$camera") |"
  done
} > "$WORK/table.md"
{
  echo "# Seams with imagery"
  echo
  echo "Nadir snapshots (640×480, north up) with the bundled Blue Marble and Zion Landsat layers"
  echo "over the bundled pyramid, scored by \`globe-image-seams\`: the worst pixel column's or row's"
  echo "mean luminance step over the median of its 24 neighbours' (natural ground scores 1.2-1.6;"
  echo "a straight step along a tile edge or a boundary stands out above 2), and in brackets that"
  echo "step's excess over its neighbours' in luma levels of 255 (the ratio means little where the"
  echo "picture has almost no texture: 7 km Blue Marble texels seen from 20 km)."
  echo
  cat "$WORK/table.md"
  echo
  echo "Made by \`tools/bench_render/seam_measure.sh BUILD [BASELINE_BUILD]\` on $(date -u +%Y-%m-%d)."
} > "$OUT_MD"
cat "$WORK/table.md"
