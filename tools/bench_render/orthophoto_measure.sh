#!/usr/bin/env bash
# An orthophoto over terrain with no fine DEM, against the source at the same view: the bundled
# NAIP scene (5 m, North Dakota) over the 20' world grid alone, photographed straight down from
# 3,000 m above the terrain with the lighting off and no sky, and the source warped by gdalwarp
# to the same frame (an azimuthal equidistant projection centred under the camera: a nadir
# pinhole over flat ground is a uniform scale). Two measures per build, in one run:
#   - sharpness: the mean luminance gradient (globe-image-gradient) of the view / the source's;
#   - mismatch: the fraction of pixels that match nothing within 2 px (globe-image-error).
# With BASELINE_BUILD (a build of an earlier commit) its row comes first. Writes
# docs/performance/orthophoto.md.
#
#   tools/bench_render/orthophoto_measure.sh [BUILD_DIR] [BASELINE_BUILD]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-image-error globe-image-gradient >/dev/null  # tools/run-tests.sh builds only the tests
BASELINE=${2:-}
OUT_MD=$ROOT/docs/performance/orthophoto.md
GRADIENT=$BUILD/tools/bench_render/globe-image-gradient
ERROR=$BUILD/tools/bench_render/globe-image-error
for exe in "$BUILD/apps/globe-tiler/globe-tiler" "$BUILD/apps/globe/globe" "$GRADIENT" "$ERROR" \
  ${BASELINE:+"$BASELINE/apps/globe/globe" "$BASELINE/apps/globe-tiler/globe-tiler"}; do
  [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
LON=-99.155 LAT=47.020 ABOVE=3000 W=640 H=480
# Half the frame on the ground: tan(22.5°) of the height (45° vertical field of view).
HALF_H=$(awk -v h=$ABOVE 'BEGIN { printf "%.3f", h * sin(3.14159265358979/8) / cos(3.14159265358979/8) }')
HALF_W=$(awk -v a=$HALF_H -v w=$W -v h=$H 'BEGIN { printf "%.3f", a * w / h }')
gdalwarp -q -t_srs "+proj=aeqd +lat_0=$LAT +lon_0=$LON +datum=WGS84 +units=m" \
  -te "-$HALF_W" "-$HALF_H" "$HALF_W" "$HALF_H" -ts $W $H -r bilinear \
  "$ROOT/data/imagery/naip-north-dakota-rgb.tif" "$WORK/source.tif"
gdal_translate -q -of PNG "$WORK/source.tif" "$WORK/source.png"
source_gradient=$("$GRADIENT" "$WORK/source.png")

row() {  # build label dir: the terrain and the layer made by the build's own tiler
  local build=$1 label=$2 dir=$WORK/$3
  mkdir -p "$dir"
  "$build/apps/globe-tiler/globe-tiler" -q -o "$dir/pyramid" "$ROOT/data/dem/ETOPO20.DEM" > /dev/null
  "$build/apps/globe-tiler/globe-tiler" imagery -q -o "$dir/naip" \
    "$ROOT/data/imagery/naip-north-dakota-rgb.tif" > /dev/null
  "$build/apps/globe/globe" snapshot "$dir/pyramid" --layer "$dir/naip" --lighting off --no-sky \
    --camera "$LON,$LAT,$ABOVE,0,-90,0" --above-terrain --size "${W}x$H" -o "$dir/view.png" \
    > /dev/null
  local gradient mismatch
  gradient=$("$GRADIENT" "$dir/view.png")
  mismatch=$("$ERROR" "$dir/view.png" "$WORK/source.png" | cut -f1)
  awk -v l="$label" -v g="$gradient" -v s="$source_gradient" -v m="$mismatch" \
    'BEGIN { printf "| %s | %.3f | %.2f | %.3f |\n", l, g, g / s, m }'
}
{
  echo "| build | view gradient | ÷ source's ($source_gradient) | pixels matching nothing within 2 px |"
  echo "|---|---|---|---|"
  if [ -n "$BASELINE" ]; then
    row "$BASELINE" "$(git -C "$BASELINE/.." log -1 --format=%h 2>/dev/null || echo baseline)" base
  fi
  row "$BUILD" "$(git -C "$ROOT" log -1 --format=%h)" new
} > "$WORK/table.md"
{
  echo "# An orthophoto over terrain with no fine DEM"
  echo
  echo "The bundled NAIP scene (5 m, North Dakota) over the 20′ world grid (ETOPO20) alone, straight"
  echo "down from ${ABOVE} m above the terrain, ${W}×${H}, \`--lighting off --no-sky\`, against the"
  echo "source warped by gdalwarp to the same frame. Sharpness: the view's mean luminance gradient"
  echo "over the source's; mismatch: the fraction of pixels matching nothing within 2 px (±24 of 255)."
  echo
  cat "$WORK/table.md"
  echo
  echo "Made by \`tools/bench_render/orthophoto_measure.sh BUILD [BASELINE_BUILD]\` on $(date -u +%Y-%m-%d)."
} > "$OUT_MD"
cat "$WORK/table.md"
