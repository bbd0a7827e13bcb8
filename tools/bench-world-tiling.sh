#!/usr/bin/env bash
# Scale benchmark for globe-tiler: writes a synthetic world-sized GTOPO30 set (33 tiles, 43200×21600
# samples, 1.87 GB) and tiles it, reporting wall time, throughput, peak RSS, tiles and files.
# Usage: tools/bench-world-tiling.sh [WORK_DIR]   (needs ~9 GB free; build/ must be built)
set -euo pipefail
cd "$(dirname "$0")/.."
WORK=${1:-/tmp/globe-world-bench}
BUILD=${BUILD_DIR:-build}
mkdir -p "$WORK"
if [ ! -f "$WORK/world/W180S60.DEM" ]; then
  "$BUILD/tools/synth/globe-synth-gtopo30" -o "$WORK/world" >/dev/null
fi
rm -rf "$WORK/pyramid"
/usr/bin/time -v "$BUILD/tools/tiler/globe-tiler" -q -o "$WORK/pyramid" "$WORK"/world/*.DEM \
  >"$WORK/tiler.out" 2>"$WORK/tiler.time"
cat "$WORK/tiler.out"
grep -E "Elapsed|Maximum resident|Percent of CPU" "$WORK/tiler.time"
echo "files in pyramid: $(find "$WORK/pyramid" -type f | wc -l)"
echo "pyramid size: $(du -sh "$WORK/pyramid" | cut -f1)"
echo "cores: $(nproc)"
