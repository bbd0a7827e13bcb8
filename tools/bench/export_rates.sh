#!/usr/bin/env bash
# Tiles per second of `globe-tiler export`, per format and thread count, on the same pyramid and
# region: the bundled pyramid (tools/bench/tile_bundled.sh) over Fuji's 1° square, every level
# the pyramid holds there (quantized-mesh and heightmap: levels; terrarium and terrain-rgb: the
# Web-Mercator zooms down to the pyramid's finest level). Each run into an empty directory;
# medians of RUNS runs in one run of this script, so the ratios compare like with like. Also
# checks that -j 2 writes the same bytes as -j 1. Writes docs/performance/export-rates.md.
#
#   tools/bench/export_rates.sh BUILD_DIR [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:?build directory}
RUNS=${2:-3}
cmake --build "$BUILD" -j"$(nproc)" --target globe-tiler >/dev/null
TILER=$(realpath "$BUILD/apps/globe-tiler/globe-tiler")
WORK=$(mktemp -d /tmp/globe-export-rates.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
"$TILER" -q -o "$WORK/pyramid" data/dem/ETOPO20.DEM data/dem/E138N35_FUJI.DEM >/dev/null
BOUNDS=138,35,139,36
FORMATS=(quantized-mesh heightmap terrarium terrain-rgb)
median() { sort -n | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
run() {  # format threads dir -> "seconds tiles"
  rm -rf "$3"; mkdir -p "$(dirname "$3")"
  local s=$EPOCHREALTIME
  "$TILER" export -q --format "$1" -j "$2" --bounds "$BOUNDS" -o "$3" "$WORK/pyramid" >"$WORK/out"
  local tiles
  tiles=$(sed -n 's/.*: \([0-9]*\) .* tiles written.*/\1/p' "$WORK/out")
  awk -v a="$s" -v b="$EPOCHREALTIME" -v t="$tiles" 'BEGIN {printf "%.3f %d\n", b - a, t}'
}
declare -A TILES SECS
for _ in $(seq "$RUNS"); do
  for f in "${FORMATS[@]}"; do
    for j in 1 2; do
      read -r s t < <(run "$f" "$j" "$WORK/j$j/$f")
      echo "$s" >>"$WORK/t-$f-$j"
      TILES[$f]=$t
    done
  done
done
same=yes
for f in "${FORMATS[@]}"; do
  diff -r -q "$WORK/j1/$f" "$WORK/j2/$f" >/dev/null || same=no
  for j in 1 2; do SECS[$f-$j]=$(median <"$WORK/t-$f-$j"); done
done
QM1=$(awk -v t="${TILES[quantized-mesh]}" -v s="${SECS[quantized-mesh-1]}" 'BEGIN {print t / s}')
OUT_MD=${OUT_MD:-docs/performance/export-rates.md}
{
  echo "# globe-tiler export: tiles per second"
  echo
  echo "The bundled ETOPO20 + Fuji pyramid over Fuji's 1° square ($BOUNDS), every level the"
  echo "pyramid holds there; each run writes a whole tree into an empty directory (wall time of"
  echo "the process, reading the pyramid included). Medians of $RUNS runs in one run of"
  echo "\`tools/bench/export_rates.sh\` ($(date -u +%Y-%m-%d), $(nproc) cores,"
  echo "$(git describe --always --dirty)). -j 2 wrote the same bytes as -j 1: $same."
  echo
  echo "A quantized-mesh or heightmap tile is a 65×65 grid of exact-surface samples (4,225), a"
  echo "Terrarium or Terrain-RGB tile 256×256 (65,536): the samples/s column counts those."
  echo
  echo "| format | tiles | -j 1 s | -j 1 tiles/s | -j 2 s | -j 2 tiles/s | -j 2 vs -j 1 | -j 1 tiles/s vs quantized-mesh | -j 1 samples/s |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for f in "${FORMATS[@]}"; do
    case $f in terrarium | terrain-rgb) n=65536 ;; *) n=4225 ;; esac
    awk -v f="$f" -v t="${TILES[$f]}" -v a="${SECS[$f-1]}" -v b="${SECS[$f-2]}" -v q="$QM1" -v n="$n" \
      'BEGIN {printf "| %s | %d | %.2f | %.0f | %.2f | %.0f | %.2f× | %.2f× | %.2f M |\n", f, t, a, t / a, b, t / b, a / b, t / a / q, t * n / a / 1e6}'
  done
  echo
  echo "Terrarium and Terrain-RGB tiles hold 15.5× the samples of a quantized-mesh one; since the"
  echo "lattice sampler (src/surface/lattice_heights.hpp) they are made at least as fast per tile."
  echo "A tile's pixel centres are one longitude × latitude lattice: the nadir's sines and cosines"
  echo "are worked out per row and column, each pyramid block under the tile is looked up and its"
  echo "vertices built once, and the exact surface's plane step runs on them, giving the doubles"
  echo "PyramidSurface::heightMeters gives (the same pixels; any case it does not cover, such as a"
  echo "meeting point just outside its triangle, a pole or a TIN block, goes to the exact surface"
  echo "itself). The PNGs are RGB, Up-filtered, at deflate level 1 (9.2 MB for the 78 tiles, 9.9"
  echo "before). Before that (2026-12-07) they made 37 and 36 tiles/s at -j 1, 0.39× and 0.38×"
  echo "quantized-mesh, a third of their time the exact surface per pixel, a quarter the pixel's"
  echo "sines, cosines and block lookup. Heightmap's posts go through the same lattice (its time is"
  echo "mostly its water mask). The terrarium and terrain-rgb runs are short: some 0.1 s of each is"
  echo "the process starting, which also holds -j 2 back. Before the workers (issue 54) they ran"
  echo "on one thread, and without --levels walked the whole world at every zoom down to 22: the"
  echo "bundled world + Fuji pyramid never finished; now a zoom's tiles lie only where the pyramid"
  echo "has that level."
} >"$OUT_MD"
cat "$OUT_MD"
[ "$same" = yes ]
