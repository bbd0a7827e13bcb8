#!/usr/bin/env bash
# Renders the README's overlays picture (docs/images/overlays.png) from what tools/setup.sh made
# (pyramid/, layers/): four 960x540 snapshots with overlays over the bundled terrain and imagery,
# put together 2x2 and reduced to 1280x720. Run from the checkout's root after setup.
set -euo pipefail
cd "$(dirname "$0")/../.."
GLOBE=${GLOBE:-./build/apps/globe/globe}
OVERLAYS=tests/data/interop/overlays
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
"$GLOBE" snapshot pyramid --size 960x540 --camera 138.80,35.25,9000,315,-25,0 \
  --layer layers/coast --overlay data/overlays/fuji-demo.kml -o "$TMP/1.png"
"$GLOBE" snapshot pyramid --size 960x540 --camera 10,30,12000000 --layer layers/blue-marble \
  --overlay "$OVERLAYS/ne_110m_admin_0_countries.geojson" \
  --overlay "$OVERLAYS/ne_110m_rivers_lake_centerlines.geojson" \
  --overlay "$OVERLAYS/ne_110m_populated_places_simple.geojson" -o "$TMP/2.png"
"$GLOBE" snapshot pyramid --size 960x540 --camera -112.93,37.16,4500,330,-20,0 \
  --layer layers/blue-marble --layer layers/zion --overlay data/overlays/zion-peaks.kml -o "$TMP/3.png"
"$GLOBE" snapshot pyramid --size 960x540 --camera -2.24,53.36,14000,0,-55,0 --layer layers/coast \
  --overlay "$OVERLAYS/tfgm-Metrolink_Lines_Functional.kml" \
  --overlay "$OVERLAYS/tfgm-Metrolink_Stops_Functional.kml" -o "$TMP/4.png"
montage -mode concatenate -tile 2x "$TMP"/1.png "$TMP"/2.png "$TMP"/3.png "$TMP"/4.png \
  "$TMP/all.png"
convert "$TMP/all.png" -resize 1280x720 docs/images/overlays.png
echo "wrote docs/images/overlays.png"
