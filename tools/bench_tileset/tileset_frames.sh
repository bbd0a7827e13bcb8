#!/usr/bin/env bash
# Frame time with a 3D Tiles tileset against the same views without it, and the longest frame of
# a flight towards it while its contents arrive (issue 55), for two tilesets:
#   buildings: `globe-tiler buildings` of tests/data/buildings's footprints (--tile-buildings 3,
#              as tests/web/cesium_buildings.mjs) on the bundled pyramid;
#   dragon:    CesiumGS's TilesetWithDiscreteLOD (tests/data/interop/3dtiles) on the flat pyramid
#              the golden tests draw it on (tests/render/test_golden_images.cpp).
# Each case runs twice (runs 1 and 2, one globe-bench-tileset-frames process each), so the
# document shows how much two runs on this machine differ. Writes
# docs/performance/tileset-frame-time.md; PNGs of every view and of the flights' frames go to
# PNG_DIR (default: a temporary folder, removed).
#
#   tools/bench_tileset/tileset_frames.sh [BUILD [PNG_DIR]]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-tiler globe-bench-tileset-frames >/dev/null
TILER=$BUILD/apps/globe-tiler/globe-tiler
BENCH=$BUILD/tools/bench_tileset/globe-bench-tileset-frames
for exe in "$TILER" "$BENCH"; do [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }; done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
PNG=${2:-$WORK/png}
mkdir -p "$PNG"
D=$ROOT/data/dem
T=$ROOT/tests/data
# The bundled pyramid (tools/bench/tile_bundled.sh's, without its imagery layers) and the flat one.
"$TILER" -q -o "$WORK/pyramid" "$D/ETOPO20.DEM" "$D/W002N52.DEM" "$D/E138N35_FUJI.DEM" \
  "$D/zion-srtm3.tif" >/dev/null
"$TILER" -q -o "$WORK/flat-pyramid" "$T/dem/gtopo30/ETOPO20.DEM" \
  "$T/dem/synthetic/flat-philadelphia.tif" >/dev/null
"$TILER" buildings -o "$WORK/buildings" "$T/buildings/fuji_footprints.geojson" \
  --pyramid "$WORK/pyramid" --tile-buildings 3 >/dev/null

ROUNDS=7 FRAMES=5 FLIGHT_FRAMES=200 FLIGHT_ROUNDS=5
run_case() {  # NAME RUN PYRAMID TILESET FLIGHT_FROM VIEW...
  local name=$1 run=$2 pyramid=$3 tileset=$4 from=$5
  shift 5
  local views=() png=()
  for v in "$@"; do views+=(--view "$v"); done
  [ "$run" = 1 ] && png=(--png "$PNG/$name")
  "$BENCH" --case "$name" --label "$run" --pyramid "$pyramid" --tileset "$tileset" "${views[@]}" \
    --flight-from "$from" --flight-frames $FLIGHT_FRAMES --flight-rounds $FLIGHT_ROUNDS \
    --rounds $ROUNDS --frames $FRAMES "${png[@]}" --out "$WORK/$name-$run.md" >/dev/null
}
LOAD_BEFORE=$(cut -d' ' -f1 /proc/loadavg)
for run in 1 2; do
  # Low south-west of the Fujiyoshida footprints (A-D), looking north-east, 12° down (the camera
  # of tests/web/cesium_buildings.mjs); the flight from 20 km behind it, 12 km up.
  run_case buildings "$run" "$WORK/pyramid" "$WORK/buildings" 138.629,35.361,12000,50,-35,0 \
    fujiyoshida=138.7988,35.4772,880,50,-12,0
  # The golden tests' two dragon views; the flight from 25 km south, 10 km up, to the nearer.
  run_case dragon "$run" "$WORK/flat-pyramid" "$T/interop/3dtiles/TilesetWithDiscreteLOD" \
    -75.6121,39.811,10000,0,-30,0 dragon=-75.612,40.01,900,0,-5,0 \
    dragon_near=-75.6121,40.0360,450,0,-3,0
done
LOAD_AFTER=$(cut -d' ' -f1 /proc/loadavg)
rows() {  # SECTION: that section's rows of every case and run, case by case
  for name in buildings dragon; do
    for run in 1 2; do
      awk -v s="$1" '/^(STEADY|FLIGHT)$/ { on = ($0 == s); next } on' "$WORK/$name-$run.md"
    done
  done | sort -t'|' -k2,2 -k3,3 -s
}
DOC=$ROOT/docs/performance/tileset-frame-time.md
if git -C "$ROOT" rev-parse --git-dir >/dev/null 2>&1; then
  COMMIT=$(git -C "$ROOT" log -1 --format=%h)$(git -C "$ROOT" diff --quiet -- src shaders apps || echo " + uncommitted changes")
else  # a copy of a commit (git archive): GLOBE_COMMIT names it
  COMMIT="${GLOBE_COMMIT:-unknown} (an exported copy of it)"
fi
{
  echo "# Frame time with a 3D Tiles tileset, and the longest frame while its tiles arrive"
  echo
  echo "Issue 55: the frame time a tileset costs, and no frame waiting on its contents (decoding"
  echo "and the collision height grids are made on the scene's loader threads, tiles3d/tileset_stream.hpp;"
  echo "a frame only uploads what arrived). \`globe-bench-tileset-frames\` (tools/bench_tileset/main.cpp)"
  echo "in one process and one OSMesa context, 1280×720, llvmpipe; each frame is"
  echo "\`TerrainScene::update\` + the terrain's draw + the contents' draw (\`app::ModelDrawing\`, as"
  echo "\`globe view\` and \`snapshot\` draw them) + glFinish. Two cases:"
  echo
  echo "- **buildings**: \`globe-tiler buildings --tile-buildings 3\` of the 13 synthetic footprints of"
  echo "  tests/data/buildings on the bundled pyramid (6 GLB tiles, ADD refinement);"
  echo "- **dragon**: CesiumGS's TilesetWithDiscreteLOD (the Stanford dragon in three REPLACE levels,"
  echo "  the finest absent as in the collection) on the flat pyramid of the golden tests, at their"
  echo "  two cameras (\`dragon\`, \`dragon_near\`)."
  echo
  echo "Every case was run twice (runs 1 and 2: two processes, one after the other); both runs are"
  echo "shown, so their difference is this machine's noise."
  echo
  echo "## Steady frames"
  echo
  echo "The view complete (terrain and contents loaded and uploaded), then $ROUNDS rounds of $FRAMES frames"
  echo "a side, the sides interleaved; medians. Triangles: the terrain's (skirts included) and the"
  echo "contents' drawn."
  echo
  echo "| case | view | run | frames a side | without ms | with the tileset ms | ratio | triangles without | triangles with: terrain + contents | contents drawn |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  rows STEADY
  echo
  echo "## A flight towards the tileset"
  echo
  echo "$FLIGHT_FRAMES frames from far (buildings: 20 km behind the view, 12 km up; dragon: 25 km south,"
  echo "10 km up) to the case's last view, the height eased geometrically, each frame one update +"
  echo "draw + glFinish that never waits for a load, as \`globe view\` runs (hysteresis, 8 morph"
  echo "frames, 4 shadow tiles a frame); a fresh scene and renderer each flight, $FLIGHT_ROUNDS flights a side"
  echo "alternated. Per flight: the median frame, the 99th percentile, the longest; the table gives"
  echo "each figure's median over the flights (the longest also its range). \"Contents arrived\":"
  echo "frames that drew a content the frame before did not (its GL upload in that frame, its"
  echo "decoding and height grid done before on the loader threads), listed for the first flight"
  echo "with the tileset. \"Over its neighbours\": such a frame's time less the median of the 4"
  echo "frames before and the 4 after it (what the arrival added, the view's own cost at that point"
  echo "of the path set aside), the largest of a flight; beside it the same for the same frames"
  echo "(the same poses) of the flight without the tileset flown in the same round: a frame's noise"
  echo "there. Medians over the flights."
  echo
  echo "| case | run | flights × frames | median ms without, with | p99 ms without, with | longest ms without (range), with (range) | longest: with / without | frames contents arrived in | longest of those ms | the most one took over its neighbours ms: with, the same frames without | longest of the other frames with the tileset ms | contents, triangles at the end |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  rows FLIGHT
  echo
  echo "## Collision"
  echo
  echo "What a tileset costs a collision query (the probe the camera controller runs, the surface"
  echo "height) is measured by \`globe-bench-tileset-query\`: [tileset-query.md](tileset-query.md)."
  echo "Its height grids are made on the loader threads with the content, so the frames above"
  echo "include none of that work."
  echo
  echo "Made by \`tools/bench_tileset/tileset_frames.sh BUILD\` on $(date -u +%Y-%m-%d), commit $COMMIT."
  echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, llvmpipe; load average $LOAD_BEFORE before, $LOAD_AFTER after."
} >"$DOC"
cat "$DOC"
