#!/usr/bin/env bash
# The bundled data as the benchmark scripts draw it, tiled by the given globe-tiler: OUT/pyramid
# (ETOPO20, W002N52, Mount Fuji's and Zion's SRTM), the layers OUT/blue-marble (whole globe) and
# OUT/zion (Landsat 8). Quiet; exits non-zero if the tiler does.
#
#   tools/bench/tile_bundled.sh GLOBE_TILER OUT_DIR
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TILER=${1:?GLOBE_TILER}
OUT=${2:?OUT_DIR}
D=$ROOT/data
"$TILER" -q -o "$OUT/pyramid" "$D/dem/ETOPO20.DEM" "$D/dem/W002N52.DEM" "$D/dem/E138N35_FUJI.DEM" \
  "$D/dem/zion-srtm3.tif" > /dev/null
"$TILER" imagery -q -o "$OUT/blue-marble" --bounds -180,-90,180,90 \
  "$D/imagery/world.topo.bathy.200412.3x5400x2700.jpg" > /dev/null
"$TILER" imagery -q -o "$OUT/zion" "$D/imagery/zion-landsat8-rgb.tif" > /dev/null
