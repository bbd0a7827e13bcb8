#!/usr/bin/env bash
# Frame times of the renderer as the viewer draws today (globe-bench-render: the whole globe, the
# Fuji oblique view near the ground, a jump between them), ROUNDS runs on the bundled data, and
# from them docs/performance/render-frame-time.md and the README's rendering bullet (between its
# render-summary markers), each naming the commit, the machine and the date.
#
#   tools/bench_render/bench_render.sh [BUILD_DIR] [ROUNDS]
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-bench-render >/dev/null  # tools/run-tests.sh builds only the tests
ROUNDS=${2:-3}
BENCH=$BUILD/tools/bench_render/globe-bench-render
[ -x "$BENCH" ] || { echo "build it first: $BENCH" >&2; exit 1; }
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$BUILD/apps/globe-tiler/globe-tiler" -q -o "$WORK/pyramid" "$ROOT/data/dem/ETOPO20.DEM" \
  "$ROOT/data/dem/W002N52.DEM" "$ROOT/data/dem/E138N35_FUJI.DEM" "$ROOT/data/dem/zion-srtm3.tif"
for round in $(seq 1 "$ROUNDS"); do
  echo "== round $round of $ROUNDS" >&2
  "$BENCH" --pyramid "$WORK/pyramid" --lp-threads 2 > "$WORK/round-$round.md"
done
COMMIT="$(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- src shaders || echo ' + uncommitted changes')"
MACHINE="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
python3 "$ROOT/tools/bench_render/render_report.py" --commit "$COMMIT" --machine "$MACHINE" \
  --doc "$ROOT/docs/performance/render-frame-time.md" --readme "$ROOT/README.md" "$WORK"/round-*.md
