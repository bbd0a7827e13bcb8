#!/usr/bin/env bash
# Level of detail against image error: per view, the triangles drawn, the image error against a
# 0.5 px reference (the fraction of pixels that match nothing within a 2 px shift,
# globe-image-error) and the steady frame time, for a baseline build, a new build, and the new
# build with --nominal-lod, run interleaved in one run. Each build tiles its own pyramid from the same inputs (the bundled
# data/dem, plus the Taunus and Kattegat SRTM tiles from ../shared when present). Each build's
# images are compared with its own 0.5 px reference (--sse 0.5; the new build's with
# --nominal-lod, the most refined), so a change of the picture itself (a sky the baseline did
# not draw) does not count as level-of-detail error. Frame time: a held pose played with `globe play --no-frames`, the
# median total of the second half of its frames (the view is complete by then).
#
#   tools/bench_render/bench_lod.sh BASE_BUILD NEW_BUILD [ROUNDS] [OUT_MD]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BASE=${1:?baseline build directory}
NEW=${2:?new build directory}
ROUNDS=${3:-3}
OUT_MD=${4:-$ROOT/docs/performance/performance-lod.md}
IMAGE_ERROR=$NEW/tools/bench_render/globe-image-error
# A program of build $1 named $2: apps/ since the redesign, src/app and tools/tiler before it.
program() {
  for p in "$1/apps/$2/$2" "$1/src/app/$2" "$1/tools/tiler/$2"; do
    [ -x "$p" ] && { echo "$p"; return; }
  done
  echo "build it first: $1/apps/$2/$2" >&2
  exit 1
}
BASE_GLOBE=$(program "$BASE" globe); BASE_TILER=$(program "$BASE" globe-tiler)
NEW_GLOBE=$(program "$NEW" globe); NEW_TILER=$(program "$NEW" globe-tiler)
[ -x "$IMAGE_ERROR" ] || { echo "build it first: $IMAGE_ERROR" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
SHARED=$ROOT/../shared/data/dem/gtopo30
INPUTS=("$ROOT/data/dem/ETOPO20.DEM" "$ROOT/data/dem/W002N52.DEM" "$ROOT/data/dem/E138N35_FUJI.DEM"
        "$ROOT/data/dem/zion-srtm3.tif")
for f in N50E008 N50E009 N57E011; do [ -f "$SHARED/$f.DEM" ] && INPUTS+=("$SHARED/$f.DEM"); done
"$BASE_TILER" -q -o "$WORK/base-pyramid" "${INPUTS[@]}"
"$NEW_TILER" -q -o "$WORK/new-pyramid" "${INPUTS[@]}"

# name=camera (LON,LAT,HEIGHT,HEADING,PITCH,ROLL)
VIEWS=(fuji_oblique=138.60,35.20,6000,30,-15,0
       zion_oblique=-112.93,37.16,4500,330,-20,0
       east_england_low=-1.00,52.60,600,80,-8,0
       globe=138,30,20000000,0,-90,0)
[ -f "$SHARED/N50E008.DEM" ] && VIEWS+=(taunus_oblique=8.40,50.15,2500,30,-12,0)
[ -f "$SHARED/N57E011.DEM" ] && VIEWS+=(kattegat_coast=11.55,57.35,1500,20,-10,0)
SIZE=1280x720

median() { sort -g | awk '{v[NR]=$1} END {if (NR == 0) print "nan"; else if (NR % 2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }

steadyFrameMs() {  # build pyramid camera [flags] → median total_ms of the second half of 60 frames
  local lon lat h hd p r
  IFS=, read -r lon lat h hd p r <<<"$3"
  cat >"$WORK/hold.json" <<JSON
{"interpolation": "linear", "keyframes": [
 {"t": 0, "lon": $lon, "lat": $lat, "height": $h, "heading": $hd, "pitch": $p, "roll": $r},
 {"t": 2, "lon": $lon, "lat": $lat, "height": $h, "heading": $hd, "pitch": $p, "roll": $r}]}
JSON
  rm -rf "$WORK/play"
  "$(program "$1" globe)" play "$2" "$WORK/hold.json" --out "$WORK/play" --no-frames --size $SIZE \
    ${4:-} >/dev/null
  tail -n +2 "$WORK/play/timing.csv" | awk -F, '{print $7 - $6}' | tail -n 30 | median
}

printf '| view | side | triangles | vs base | image error | frame ms | vs base |\n' >"$WORK/table.md"
printf '|---|---|---|---|---|---|---|\n' >>"$WORK/table.md"
for view in "${VIEWS[@]}"; do
  name=${view%%=*}
  camera=${view#*=}
  "$BASE_GLOBE" snapshot "$WORK/base-pyramid" --camera "$camera" --size $SIZE --sse 0.5 \
    -o "$WORK/$name.base.reference.png" >/dev/null
  "$NEW_GLOBE" snapshot "$WORK/new-pyramid" --camera "$camera" --size $SIZE --sse 0.5 \
    --nominal-lod -o "$WORK/$name.new.reference.png" >/dev/null
  SIDES=(base nominal new)
  for side in "${SIDES[@]}"; do : >"$WORK/$name.$side.ms"; done
  for ((round = 0; round < ROUNDS; ++round)); do
    for side in "${SIDES[@]}"; do
      build=$NEW; pyramid=$WORK/new-pyramid; flags=
      [ $side = base ] && build=$BASE pyramid=$WORK/base-pyramid
      [ $side = nominal ] && flags=--nominal-lod
      out=$("$(program "$build" globe)" snapshot "$pyramid" --camera "$camera" --size $SIZE $flags \
        -o "$WORK/$name.$side.png")
      echo "$out" | sed -E 's/.* ([0-9]+) triangles.*/\1/' >"$WORK/$name.$side.triangles"
      steadyFrameMs "$build" "$pyramid" "$camera" $flags >>"$WORK/$name.$side.ms"
    done
  done
  tb=$(cat "$WORK/$name.base.triangles")
  mb=$(median <"$WORK/$name.base.ms")
  for side in "${SIDES[@]}"; do
    t=$(cat "$WORK/$name.$side.triangles")
    reference=$WORK/$name.new.reference.png
    [ $side = base ] && reference=$WORK/$name.base.reference.png
    e=$("$IMAGE_ERROR" "$WORK/$name.$side.png" "$reference" | cut -f1)
    m=$(median <"$WORK/$name.$side.ms")
    awk -v n="$name" -v s="$side" -v t="$t" -v tb="$tb" -v e="$e" -v m="$m" -v mb="$mb" \
      'BEGIN {printf "| %s | %s | %d | %.2f | %.3f %% | %.1f | %.2f |\n", n, s, t, t / tb, 100 * e, m, m / mb}' \
      >>"$WORK/table.md"
  done
done
{
  echo "# Level of detail: triangles, image error and frame time"
  echo
  echo "Per view (1280x720, OSMesa llvmpipe, default 2 px screen-space error): the triangles drawn,"
  echo "the image error against a 0.5 px rendering by the same build (the new build's with"
  echo "\`--nominal-lod\`: the most refined; the fraction of pixels that match no pixel within a"
  echo "2 px shift, every channel within 24 of 255; the larger of both ways), and"
  echo "the median steady frame time of a held pose (\`globe play --no-frames\`, second half of 60"
  echo "frames, $ROUNDS interleaved rounds per side). Sides: base (the baseline build and its"
  echo "pyramid), nominal (this build and its pyramid with \`--nominal-lod\`), new (this build)."
  echo "Made by \`tools/bench_render/bench_lod.sh\` on $(date -u +%Y-%m-%d)."
  echo
  cat "$WORK/table.md"
  echo
  echo "- base: $(git -C "$BASE/.." rev-parse --short HEAD 2>/dev/null || echo "$BASE"); new: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet || echo ' + uncommitted changes')"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; GL: llvmpipe"
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
