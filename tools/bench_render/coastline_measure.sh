#!/usr/bin/env bash
# Coastline position with the 20' world grid (ETOPO20) alone, against GSHHG's full-resolution
# shoreline, at five coasts: each view straight down over a shoreline vertex, lighting off, no
# sky, the terrain's own colours (sea blue, land green), from 60 km, 4 km and 400 m. Rows: the grid's own
# sea flag; with the bundled world water mask (GSHHG low, data/coast/gshhg-l-land.fgb); with it and
# the bundled full-resolution boxes (data/coast/gshhg-f-*.fgb). The reference: the same
# full-resolution polygons rasterised by gdal_rasterize into the view's frame (an azimuthal
# equidistant projection centred under the camera: a nadir pinhole over flat ground is a uniform
# scale). Per view (tools/bench_render/coastline_error.py): the fraction of pixels of the wrong
# class, and the mean distance from the view's coast pixels to the reference's and back.
# Writes docs/performance/coastlines.md.
#
#   tools/bench_render/coastline_measure.sh [BUILD_DIR]     (KEEP=DIR keeps the views and references)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
OUT_MD=$ROOT/docs/performance/coastlines.md
TILER=$BUILD/apps/globe-tiler/globe-tiler
GLOBE=$BUILD/apps/globe/globe
ERROR=$ROOT/tools/bench_render/coastline_error.py
for exe in "$TILER" "$GLOBE"; do [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }; done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
W=480 H=360
"$TILER" -q -o "$WORK/pyramid" "$ROOT/data/dem/ETOPO20.DEM" > /dev/null
"$TILER" water-mask -q -o "$WORK/world" "$ROOT/data/coast/gshhg-l-land.fgb" > /dev/null
"$TILER" water-mask -q -o "$WORK/boxes" "$ROOT/data/coast/gshhg-l-land.fgb" \
  "$ROOT"/data/coast/gshhg-f-*.fgb > /dev/null
# name, a point near the coast, the box's file and its bounds (data/coast/SOURCES.md)
COASTS=("Suruga Bay,138.60,35.00,suruga-bay,138.3,34.55,139.2,35.2"
        "the Wash,0.30,52.90,the-wash,-0.5,52.5,1.8,53.3"
        "Chesapeake Bay mouth,-76.00,37.00,chesapeake-bay,-76.6,36.8,-75.6,37.6"
        "Strait of Gibraltar,-5.60,36.00,gibraltar,-6.2,35.7,-4.9,36.3"
        "San Francisco Bay,-122.40,37.80,san-francisco-bay,-122.7,37.4,-121.9,38.1")
{
  echo "| coast | view height | grid alone: wrong pixels | coast off by (m) | + world mask (GSHHG low) | coast off by (m) | + full-resolution boxes | coast off by (m) |"
  echo "|---|---|---|---|---|---|---|---|"
} > "$WORK/table.md"
for entry in "${COASTS[@]}"; do
  IFS=, read -r name lon lat box west south east north <<< "$entry"
  polygons=$ROOT/data/coast/gshhg-f-$box.fgb
  printf '{"type":"Polygon","coordinates":[[[%s,%s],[%s,%s],[%s,%s],[%s,%s],[%s,%s]]]}' \
    "$west" "$south" "$east" "$south" "$east" "$north" "$west" "$north" "$west" "$south" \
    > "$WORK/box.geojson"
  IFS=, read -r clon clat <<< "$(/usr/bin/python3 "$ERROR" nearest "$polygons" "$lon" "$lat")"
  for above in 60000 4000 400; do
    # Half the frame on the ground: tan(22.5°) of the height (45° vertical field of view).
    half_h=$(awk -v h=$above 'BEGIN { printf "%.3f", h * sin(3.14159265358979/8) / cos(3.14159265358979/8) }')
    half_w=$(awk -v a="$half_h" -v w=$W -v h=$H 'BEGIN { printf "%.3f", a * w / h }')
    metres=$(awk -v a="$half_h" -v h=$H 'BEGIN { printf "%.4f", 2 * a / h }')
    srs="+proj=aeqd +lat_0=$clat +lon_0=$clon +datum=WGS84 +units=m"
    rm -f "$WORK/ref.tif" "$WORK/land.gpkg" "$WORK/valid.tif" "$WORK/box.gpkg"
    ogr2ogr -q -t_srs "$srs" -f GPKG "$WORK/land.gpkg" "$polygons"
    # Densified first: the box's straight edges in longitude/latitude curve in the projection.
    ogr2ogr -q -segmentize 0.01 -s_srs EPSG:4326 -t_srs "$srs" -f GPKG "$WORK/box.gpkg" "$WORK/box.geojson"
    for what in land:ref box:valid; do
      gdal_rasterize -q -burn 1 -init 0 -ot Byte -te "-$half_w" "-$half_h" "$half_w" "$half_h" \
        -ts $W $H "$WORK/${what%%:*}.gpkg" "$WORK/${what#*:}.tif"
    done
    cells=()
    for mask in none world boxes; do
      layer=()
      [ "$mask" != none ] && layer=(--layer "$WORK/$mask")
      # 0 m above the ellipsoid is the water surface: the height is above it, not the terrain.
      "$GLOBE" snapshot "$WORK/pyramid" "${layer[@]}" --lighting off --no-sky \
        --camera "$clon,$clat,$above,0,-90,0" --size "${W}x$H" -o "$WORK/view.png" > /dev/null
      [ -n "${KEEP:-}" ] && cp "$WORK/view.png" "$KEEP/$box-$above-$mask.png" && cp "$WORK/ref.tif" "$KEEP/$box-$above-ref.tif"
      read -r wrong there _ back _ <<< "$(/usr/bin/python3 "$ERROR" compare "$WORK/view.png" "$WORK/ref.tif" "$WORK/valid.tif" "$metres")"
      off="$there / $back"
      [ "$there" = - ] && off="no coast drawn"
      cells+=("$(awk -v w="$wrong" 'BEGIN { printf "%.1f %%", 100 * w }')" "$off")
    done
    echo "| $name ($clon, $clat) | $(awk -v a=$above 'BEGIN { if (a >= 1000) printf "%.0f km", a / 1000; else printf "%.0f m", a }') | ${cells[0]} | ${cells[1]} | ${cells[2]} | ${cells[3]} | ${cells[4]} | ${cells[5]} |" >> "$WORK/table.md"
  done
done
{
  echo "# Coastlines with only the world grid"
  echo
  echo "The 20′ world grid (ETOPO20) alone, straight down over a shoreline vertex of GSHHG's"
  echo "full-resolution shoreline at each coast, from 60 km, 4 km and 400 m, ${W}×${H}, 45° field of view, \`--lighting off"
  echo "--no-sky\`, against those polygons rasterised into the same frame. Wrong pixels: land drawn"
  echo "as sea or sea as land. Coast off by: the mean distance from the view's coast pixels to the"
  echo "reference's nearest / from the reference's to the view's (a coast the view lacks counts in"
  echo "the second). Only the pixels inside the box the reference polygons cover count. World mask: \`globe-tiler water-mask data/coast/gshhg-l-land.fgb\` (GSHHG low,"
  echo "~5 km, levels 0-4); boxes: with the bundled full-resolution boxes as well"
  echo "(\`data/coast/gshhg-f-*.fgb\`)."
  echo
  cat "$WORK/table.md"
  echo
  echo "Made by \`tools/bench_render/coastline_measure.sh BUILD\` on $(date -u +%Y-%m-%d)."
} > "$OUT_MD"
cat "$WORK/table.md"
