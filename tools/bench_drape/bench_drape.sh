#!/usr/bin/env bash
# Frame time of steady views with the bundled imagery layers (Blue Marble + Zion) against the same
# views without, measured in one process with interleaved rounds (globe-bench-drape). Tiles the
# bundled data into a scratch directory first. Writes docs/performance/imagery-frame-time.md.
#
#   tools/bench_drape/bench_drape.sh [BUILD_DIR]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-bench-drape >/dev/null  # tools/run-tests.sh builds only the tests
TILER=$BUILD/apps/globe-tiler/globe-tiler
BENCH=$BUILD/tools/bench_drape/globe-bench-drape
OUT_MD=$ROOT/docs/performance/imagery-frame-time.md
for exe in "$TILER" "$BENCH"; do [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }; done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$ROOT/tools/bench/tile_bundled.sh" "$TILER" "$WORK"
ARGS=(--pyramid "$WORK/pyramid" --layer "$WORK/blue-marble" --layer "$WORK/zion"
      --view fuji_oblique=138.60,35.20,6000,30,-15,0 --view zion_oblique=-112.93,37.16,4500,330,-20,0
      --view zion_nadir=-112.98,37.27,9000 --view globe=138,30,20000000 --rounds 25 --frames 3)
"$BENCH" "${ARGS[@]}" --out "$WORK/table.md"
{
  echo "# Frame time with imagery layers"
  echo
  echo "Steady frames (update + draw + glFinish, 1280x720, OSMesa llvmpipe) of four views with the"
  echo "bundled Blue Marble and Zion layers against the same views without imagery, in one process"
  echo "and one GL context, 25 interleaved rounds of 3 frames per side: medians and their ratios."
  echo "Two sides without imagery: as the viewer draws it, and the imagery side's own scene (its"
  echo "tiles: under a layer the terrain refines as far as that sharpens the imagery,"
  echo "docs/viewer.md) drawn without the imagery. The first ratio is what turning imagery on costs in"
  echo "the viewer; the second the imagery's own cost on the same triangles. The last two columns"
  echo "are the baseline of the bilinear sampler where imagery is magnified over a whole tile"
  echo "(render/terrain_renderer.hpp): the same imagery sampled trilinearly everywhere, as before."
  echo "Made by \`tools/bench_drape/bench_drape.sh\` on $(date -u +%Y-%m-%d)."
  echo
  cat "$WORK/table.md"
  echo
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- src shaders tools || echo " + uncommitted changes")"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores; GL: llvmpipe"
  echo "- drapes: (terrain tile, layer) pairs drawn with a texture; imagery textures: on the GPU, mip chains included"
  echo "- goal (issue 12): with imagery at most 1.3x the frame without"
} > "$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
