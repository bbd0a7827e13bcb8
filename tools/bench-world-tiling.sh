#!/usr/bin/env bash
# Scale benchmark for globe-tiler: writes a synthetic world-sized GTOPO30 set (33 tiles, 43200×21600
# samples, 1.87 GB) with globe-synth-gtopo30 and tiles it ROUNDS times, reporting per round the
# wall time, CPU use and peak RSS, and the pyramid's tiles, files and size; writes
# docs/performance/world-tiling.md (naming the commit, the machine and the date).
#
#   tools/bench-world-tiling.sh [ROUNDS] [WORK_DIR]   (needs ~9 GB free; BUILD_DIR, default build)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
ROUNDS=${1:-2}
WORK=${2:-/tmp/globe-world-bench}
BUILD=${BUILD_DIR:-build}
cmake --build "$BUILD" -j"$(nproc)" --target globe-synth-gtopo30 globe-tiler >/dev/null  # tools/run-tests.sh builds only the tests
OUT_MD=${OUT_MD:-$ROOT/docs/performance/world-tiling.md}
for exe in "$BUILD/tools/synth/globe-synth-gtopo30" "$BUILD/apps/globe-tiler/globe-tiler"; do
  [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
done
mkdir -p "$WORK"
if [ ! -f "$WORK/world/W180S60.DEM" ]; then
  "$BUILD/tools/synth/globe-synth-gtopo30" -o "$WORK/world" >/dev/null
fi
SOURCE_MB=$(du -cm "$WORK"/world/*.DEM | tail -1 | cut -f1)
: >"$WORK/rounds.md"
for ((round = 1; round <= ROUNDS; ++round)); do
  rm -rf "$WORK/pyramid"
  /usr/bin/time -v "$BUILD/apps/globe-tiler/globe-tiler" -q -o "$WORK/pyramid" "$WORK"/world/*.DEM \
    >"$WORK/tiler.out" 2>"$WORK/tiler.time"
  cat "$WORK/tiler.out"
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$WORK/tiler.time")
  seconds=$(echo "$wall" | awk -F: '{s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s}')
  cpu=$(awk -F': ' '/Percent of CPU/ {print $2}' "$WORK/tiler.time")
  rssMb=$(awk -F': ' '/Maximum resident/ {printf "%.0f", $2 / 1024}' "$WORK/tiler.time")
  tiles=$(grep -Eo '[0-9]+ tiles' "$WORK/tiler.out" | head -1 | cut -d' ' -f1)
  files=$(find "$WORK/pyramid" -type f | wc -l)
  size=$(du -sh "$WORK/pyramid" | cut -f1)
  echo "| $round | $seconds | $cpu | $rssMb | $tiles | $files | $size |" >>"$WORK/rounds.md"
done
{
  echo "# Tiling the whole GTOPO30 world"
  echo
  echo "\`globe-tiler\` on a synthetic world-sized GTOPO30 set in the product's own layout (33 tiles:"
  echo "27 of 40°×50° and 6 Antarctic tiles of 60°×30°, 43200×21600 samples, $SOURCE_MB MiB, written by"
  echo "\`globe-synth-gtopo30\`), levels 0..11, every core; \`/usr/bin/time -v\` per round."
  echo "Made by \`tools/bench-world-tiling.sh\` on $(date -u +%Y-%m-%d)."
  echo
  echo "| round | wall s | CPU | peak RSS MB | tiles | files | pyramid |"
  echo "|---|---|---|---|---|---|---|"
  cat "$WORK/rounds.md"
  echo
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- . ':!docs' || echo ' + uncommitted changes')"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)"
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
