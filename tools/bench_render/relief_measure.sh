#!/usr/bin/env bash
# How much relief the Blue Marble layer leaves visible: the mean luminance gradient magnitude
# (globe-image-gradient) of a snapshot with the layer over the same view without any layer, on
# Mount Fuji and on Zion, for --lighting off, auto and on. 7 km Blue Marble texels carry no relief
# of their own, so a ratio well under 1 means the layer flattens the mountains. Tiles the bundled
# data into a scratch directory first. Writes docs/performance/relief.md.
#
#   tools/bench_render/relief_measure.sh [BUILD_DIR]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-image-gradient >/dev/null  # tools/run-tests.sh builds only the tests
TILER=$BUILD/apps/globe-tiler/globe-tiler
GLOBE=$BUILD/apps/globe/globe
GRADIENT=$BUILD/tools/bench_render/globe-image-gradient
OUT_MD=$ROOT/docs/performance/relief.md
for exe in "$TILER" "$GLOBE" "$GRADIENT"; do
  [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$ROOT/tools/bench/tile_bundled.sh" "$TILER" "$WORK"
# The first-run views (tools/setup.sh, the golden tests).
VIEWS=("Mount Fuji oblique=138.60,35.20,6000,30,-15,0" "Zion oblique=-112.93,37.16,4500,330,-20,0")
MODES=(off auto on)
gradient() { "$GRADIENT" "$1"; }
shot() { "$GLOBE" snapshot "$WORK/pyramid" --camera "$1" -o "$2" "${@:3}" >/dev/null; }
{
  echo "| view | no layer | $(printf 'Blue Marble, --lighting %s | ' "${MODES[@]}")"
  echo "|---|---|$(printf -- '---|%.0s' "${MODES[@]}")"
  for view in "${VIEWS[@]}"; do
    name=${view%%=*} camera=${view#*=}
    shot "$camera" "$WORK/bare.png"
    bare=$(gradient "$WORK/bare.png")
    row="| $name | $bare |"
    for mode in "${MODES[@]}"; do
      shot "$camera" "$WORK/$mode.png" --layer "$WORK/blue-marble" --lighting "$mode"
      value=$(gradient "$WORK/$mode.png")
      row+=" $value ($(awk -v a="$value" -v b="$bare" 'BEGIN { printf "%.2f", a / b }')) |"
    done
    echo "$row"
  done
} > "$WORK/table.md"
{
  echo "# Relief under coarse imagery"
  echo
  echo "Mean luminance gradient magnitude (Rec. 709 luma of 255, central differences: how much"
  echo "relief a picture shows) of 1280x720 snapshots (OSMesa llvmpipe) of two first-run views with"
  echo "the Blue Marble layer (7 km texels) and without any layer (the hypsometric ramp, fully"
  echo "hill-shaded), and in brackets the ratio of the two. \`--lighting off\` is how imagery was"
  echo "drawn before: its own shading only, which Blue Marble does not have at this scale; \`auto\`"
  echo "(the default) shades each layer by how much coarser its texel is than the terrain's samples"
  echo "(docs/viewer.md): fully here; \`on\` always fully. Lit slopes brighten at most to the"
  echo "photo's own colour, and the dark Blue Marble is drawn with its automatic exposure"
  echo "(\`--exposure auto\`, k = 2.42)."
  echo "Made by \`tools/bench_render/relief_measure.sh\` on $(date -u +%Y-%m-%d)."
  echo
  cat "$WORK/table.md"
  echo
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- src shaders tools apps || echo " + uncommitted changes")"
  echo "- binaries: $BUILD"
} > "$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
