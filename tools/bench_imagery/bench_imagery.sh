#!/usr/bin/env bash
# Speed of `globe-tiler imagery` against gdal2tiles.py -p geodetic --tmscompatible (the same
# quadtree) on the same inputs, the same levels and the same number of processes: median of 3
# runs each, tiles per second, the ratio. Writes docs/performance/imagery-tiler-speed.md.
#
#   tools/bench_imagery/bench_imagery.sh [BUILD_DIR] [PROCESSES]
#
# BUILD_DIR defaults to ./build (globe-tiler must be built there); PROCESSES to 2. The inputs are
# the team's shared imagery (GLOBE_IMAGERY_DATA, default ../shared/data/imagery): the Zion
# Landsat RGB (UTM 12N, 30 m) and the 5400x2700 Blue Marble (no georeference: --bounds for us,
# a VRT with the same bounds for gdal2tiles).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
PROCESSES=${2:-2}
TILER=$BUILD/apps/globe-tiler/globe-tiler
DATA=${GLOBE_IMAGERY_DATA:-$ROOT/../shared/data/imagery}
GDAL2TILES=${GDAL2TILES:-$(command -v gdal2tiles.py || echo /usr/bin/gdal2tiles.py)}
OUT_MD=$ROOT/docs/performance/imagery-tiler-speed.md
[ -x "$TILER" ] || { echo "build globe-tiler first: $TILER" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
seconds() { local start=$1; echo "$(date +%s.%N) - $start" | bc -l; }

ROWS=""
COMMANDS=""
# bench NAME GDAL2TILES_INPUT TILER_ARGS...
bench() {
  local name=$1 g2tInput=$2
  shift 2
  local ours=() theirs=() tiles=0 g2tTiles=0 maxLevel=0
  for run in 1 2 3; do
    rm -rf "$WORK/ours"
    local start
    start=$(date +%s.%N)
    "$TILER" imagery -q -j "$PROCESSES" -o "$WORK/ours" "$@" > /dev/null
    ours+=("$(seconds "$start")")
  done
  tiles=$(python3 -c "import json,sys; m=json.load(open(sys.argv[1])); print(sum(l['tileCount'] for l in m['levels']))" "$WORK/ours/layer.json")
  maxLevel=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['maxLevel'])" "$WORK/ours/layer.json")
  for run in 1 2 3; do
    rm -rf "$WORK/g2t"
    local start
    start=$(date +%s.%N)
    "$GDAL2TILES" -q -p geodetic --tmscompatible -w none --processes="$PROCESSES" \
      -z "0-$maxLevel" "$g2tInput" "$WORK/g2t" > /dev/null 2>&1
    theirs+=("$(seconds "$start")")
  done
  g2tTiles=$(find "$WORK/g2t" -type f -name '*.png' | wc -l)
  local oursMedian theirsMedian oursRate theirsRate ratio
  oursMedian=$(printf '%s\n' "${ours[@]}" | median)
  theirsMedian=$(printf '%s\n' "${theirs[@]}" | median)
  oursRate=$(echo "$tiles / $oursMedian" | bc -l)
  theirsRate=$(echo "$g2tTiles / $theirsMedian" | bc -l)
  ratio=$(echo "$oursRate / $theirsRate" | bc -l)
  printf '%-12s globe-tiler %5d tiles %6.2f s %7.1f tiles/s | gdal2tiles %5d tiles %6.2f s %7.1f tiles/s | %.1fx\n' \
    "$name" "$tiles" "$oursMedian" "$oursRate" "$g2tTiles" "$theirsMedian" "$theirsRate" "$ratio"
  ROWS+=$(printf '| %s | 0-%s | %d | %.2f | %.1f | %d | %.2f | %.1f | **%.1f×** |' "$name" \
    "$maxLevel" "$tiles" "$oursMedian" "$oursRate" "$g2tTiles" "$theirsMedian" "$theirsRate" "$ratio")$'\n'
  COMMANDS+="globe-tiler imagery -q -j $PROCESSES -o OUT $*"$'\n'
  COMMANDS+="gdal2tiles.py -q -p geodetic --tmscompatible -w none --processes=$PROCESSES -z 0-$maxLevel ${g2tInput#"$WORK"/} OUT"$'\n'
}

ZION=$DATA/zion/zion_landsat8_rgb_8bit_DERIVED.tif
MARBLE=$DATA/global/world.topo.bathy.200412.3x5400x2700.jpg
gdal_translate -q -of VRT -a_srs EPSG:4326 -a_ullr -180 90 180 -90 "$MARBLE" "$WORK/marble.vrt"
COMMANDS="gdal_translate -of VRT -a_srs EPSG:4326 -a_ullr -180 90 180 -90 $MARBLE marble.vrt"$'\n'
bench "Zion RGB" "$ZION" "$ZION"
bench "Blue Marble" "$WORK/marble.vrt" --bounds -180,-90,180,90 "$MARBLE"

COMMIT=$(git -C "$ROOT" rev-parse --short HEAD)
if [ -n "$(git -C "$ROOT" status --porcelain -- src tools)" ]; then COMMIT="$COMMIT + uncommitted changes"; fi
CPU=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
cat > "$OUT_MD" <<MD
# Imagery tiler speed

\`globe-tiler imagery\` against \`gdal2tiles.py -p geodetic --tmscompatible\` (GDAL $(gdal-config --version 2>/dev/null || gdalinfo --version | cut -d' ' -f2 | tr -d ,)), which
cuts the same quadtree (level 0 = two 180° tiles, 256-pixel tiles), on the same input, the same
levels (0 to the level globe-tiler chose: the first whose texel is no larger than the source
pixel) and the same number of processes ($PROCESSES). Median of 3 runs each, wall clock, tiles per second.
Made by \`tools/bench_imagery/bench_imagery.sh\` on $(date -u +%Y-%m-%d).

| input | levels | globe-tiler tiles | s | tiles/s | gdal2tiles tiles | s | tiles/s | ratio |
|---|---|---|---|---|---|---|---|---|
$ROWS
- commit: $COMMIT
- machine: $CPU, $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GB; other builds may have been running on it
- globe-tiler writes JPEG tiles (quality 85) where every pixel is opaque and PNG elsewhere, into
  packs; gdal2tiles writes one PNG file per tile (its default; its average resampling reads 4×
  larger windows). The tile counts differ where gdal2tiles writes tiles that globe-tiler leaves
  out because no pixel is covered, or the reverse at the footprint's edge.

Commands:

\`\`\`
$COMMANDS\`\`\`
MD
echo "wrote $OUT_MD"
