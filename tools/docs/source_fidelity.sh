#!/usr/bin/env bash
# docs/performance/source-fidelity.md: how the tiler draws each source it is given
# (docs/conditioning.md), on real cases made from the repository's DEMs with GDAL's own tools: a
# summit at a crop's edge, a coastal tile half blanked, two adjacent SRTM tiles, a DEM warped to
# UTM, a no-data collar, and the bundled tiles over the 20′ world grid. Each case is tiled by
# this tree's globe-tiler and, when BASELINE_TILER names another (e.g. the previous commit's), by
# that one too; globe-source-fidelity measures each pyramid (tools/fidelity/source_fidelity.hpp).
#
#   tools/docs/source_fidelity.sh [BUILD_DIR] [BASELINE_TILER]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-source-fidelity >/dev/null  # tools/run-tests.sh builds only the tests
BASELINE=${2:-}
OUT_MD=${OUT_MD:-$ROOT/docs/performance/source-fidelity.md}
TILER=$BUILD/apps/globe-tiler/globe-tiler
MEASURE=$BUILD/tools/fidelity/globe-source-fidelity
for exe in "$TILER" "$MEASURE"; do [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }; done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
DEM=$ROOT/tests/data/dem
WORLD=$DEM/gtopo30/ETOPO20.DEM
FUJI_TIFF=$DEM/original/mt_fuji_90m.tif

# The cases' inputs.
gdal_translate -q -projwin 138.55 35.37 138.95 35.10 "$FUJI_TIFF" "$WORK/fuji-summit-at-edge.tif"
gdal_translate -q "$FUJI_TIFF" "$WORK/fuji-south-blanked.tif"
cat >"$WORK/south.geojson" <<'JSON'
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry":
 {"type": "Polygon", "coordinates": [[[137.9, 34.9], [139.1, 34.9], [139.1, 35.5], [137.9, 35.5], [137.9, 34.9]]]}}]}
JSON
gdal_rasterize -q -burn -32768 "$WORK/south.geojson" "$WORK/fuji-south-blanked.tif"
gdal_translate -q "$FUJI_TIFF" "$WORK/fuji-collar.tif"
cat >"$WORK/collar.geojson" <<'JSON'
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry":
 {"type": "Polygon", "coordinates": [[[137.9, 34.9], [139.1, 34.9], [139.1, 36.1], [137.9, 36.1], [137.9, 34.9]],
  [[138.0025, 35.0025], [138.9975, 35.0025], [138.9975, 35.9975], [138.0025, 35.9975], [138.0025, 35.0025]]]}}]}
JSON
gdal_rasterize -q -burn -32768 "$WORK/collar.geojson" "$WORK/fuji-collar.tif"
gdalwarp -q -t_srs EPSG:32654 -tr 90 90 -r bilinear -dstnodata -32768 "$FUJI_TIFF" "$WORK/fuji-utm54.tif"
CASES=(
  "Fuji SRTM3 tile|$ROOT/data/dem/E138N35_FUJI.DEM"
  "eastern England, GTOPO30|$ROOT/data/dem/W002N52.DEM"
  "Zion SRTM3 GeoTIFF|$ROOT/data/dem/zion-srtm3.tif"
  "Kattegat SRTM3 tile, mostly 0 m sea|$DEM/gtopo30/N57E011.DEM"
  "Fuji cropped, summit 0.01° from the north edge|$WORK/fuji-summit-at-edge.tif"
  "Fuji tile, south half blanked to no data|$WORK/fuji-south-blanked.tif"
  "two adjacent SRTM3 tiles|$DEM/gtopo30/N50E008.DEM $DEM/gtopo30/N50E009.DEM"
  "Fuji warped to UTM 54N (no-data wedges)|$WORK/fuji-utm54.tif"
  "Fuji with a no-data collar 3 samples wide|$WORK/fuji-collar.tif"
)

# Wall milliseconds of one tiling (two threads, as on a 2-core machine).
RUNS=${RUNS:-3}
tile_ms() {  # tiler, output dir, inputs...
  local tiler=$1 out=$2 start end
  shift 2
  rm -rf "$out"
  start=$(date +%s%N)
  "$tiler" -q -j2 -o "$out" "$WORLD" "$@" >/dev/null
  end=$(date +%s%N)
  echo $(((end - start) / 1000000))
}
median_seconds() { sort -n | awk '{a[NR] = $1} END {printf "%.2f", a[int((NR + 1) / 2)] / 1000}'; }

measure() {  # tiler -> table rows
  local tiler=$1 n=0
  for case in "${CASES[@]}"; do
    local name=${case%%|*} inputs
    read -r -a inputs <<<"${case#*|}"
    n=$((n + 1))
    "$tiler" -q -o "$WORK/pyramid-$n" "$WORLD" "${inputs[@]}" >/dev/null
    "$MEASURE" "$WORK/pyramid-$n" "$WORLD" "${inputs[@]}" | tail -n +3 | sed "s/^| /| $name: /"
    rm -rf "$WORK/pyramid-$n"
  done
}

HEADER='| case: source | level | inside: p95 / max \|drawn − source\| (m) | 0.1° edge band: p95 / max (m) | steps across its edge: worst (m) / source p99.9 (m) | over 1.5× the local step | vertices over no data drawn as sea over land |'
{
  echo "# Source fidelity: how the tiler draws the sources it is given"
  echo
  echo "Made by \`tools/docs/source_fidelity.sh\` on $(date -u +%Y-%m-%d); do not edit by hand."
  echo "Every case is tiled over the 20′ world grid (ETOPO20) and measured at the source's finest"
  echo "level by \`globe-source-fidelity\` (tools/fidelity/source_fidelity.hpp):"
  echo
  echo "- **|drawn − source|**: at the pyramid's vertices whose four nearest source samples are all"
  echo "  land (above 0 m), the drawn height against the source's bilinear value there; inside, and"
  echo "  within 0.1° of the source's edges. 0.5 m is the heights' rounding to the metre."
  echo "- **steps across its edge**: between neighbouring vertices, one on the source's footprint and"
  echo "  one off it (beyond its rectangle, or over its no data reaching its border), where no equally"
  echo "  fine source goes on; a step counts as a wall when it exceeds 1.5× the largest step between"
  echo "  the source's own neighbouring samples within 5 samples of it (and 1 m)."
  echo "- **no data drawn as sea over land**: vertices whose nearest source sample is no data (and no"
  echo "  measured sample at or below 0 m among the four), drawn as water although the coarser"
  echo "  source's surface is above 0 m at all four sample positions. Must be 0."
  echo
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- src tests tools || echo " + uncommitted changes")"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
  echo
  echo "## This tree"
  echo
  echo "$HEADER"
  echo "|---|---|---|---|---|---|---|"
  measure "$TILER"
  if [ -n "$BASELINE" ]; then
    echo
    echo "## Baseline: $("$BASELINE" --version 2>/dev/null || echo "$BASELINE")"
    echo
    echo "$HEADER"
    echo "|---|---|---|---|---|---|---|"
    measure "$BASELINE"
  fi
  echo
  echo "## Tiling time"
  echo
  echo -n "Wall seconds of the whole tiling over the 20′ grid (\`-j2\`), median of $RUNS runs"
  if [ -n "$BASELINE" ]; then
    echo ", this tree and the baseline in turn on the same machine."
    echo
    echo "| case | this tree (s) | baseline (s) | ratio |"
    echo "|---|---|---|---|"
  else
    echo "."
    echo
    echo "| case | this tree (s) |"
    echo "|---|---|"
  fi
  for case in "${CASES[@]}"; do
    read -r -a inputs <<<"${case#*|}"
    : >"$WORK/new.ms"
    : >"$WORK/old.ms"
    for _ in $(seq "$RUNS"); do
      tile_ms "$TILER" "$WORK/timed" "${inputs[@]}" >>"$WORK/new.ms"
      if [ -n "$BASELINE" ]; then tile_ms "$BASELINE" "$WORK/timed" "${inputs[@]}" >>"$WORK/old.ms"; fi
    done
    new=$(median_seconds <"$WORK/new.ms")
    if [ -n "$BASELINE" ]; then
      old=$(median_seconds <"$WORK/old.ms")
      echo "| ${case%%|*} | $new | $old | $(awk -v a="$new" -v b="$old" 'BEGIN {printf "%.2f", a / b}') |"
    else
      echo "| ${case%%|*} | $new |"
    fi
  done
  rm -rf "$WORK/timed"
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
echo "wrote $OUT_MD"
