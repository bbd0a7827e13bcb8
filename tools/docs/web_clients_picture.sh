#!/usr/bin/env bash
# Renders docs/images/cesium-fuji.png and docs/images/maplibre-fuji.png: the bundled pyramid's
# Fuji square exported by globe-tiler (quantized-mesh, Terrarium) and drawn by CesiumJS and by
# MapLibre GL JS in headless Chromium, as the web-client tests draw them (tests/web: the pictures
# are theirs; a picture whose test failed is written all the same, and this exits 1). 960x540. Needs tools/web/install.sh and a
# build (GLOBE_EXE, GLOBE_TILER_EXE; default build/apps/...). Run from anywhere in the checkout.
set -euo pipefail
cd "$(dirname "$0")/../.."
export GLOBE_EXE=${GLOBE_EXE:-$PWD/build/apps/globe/globe}
export GLOBE_TILER_EXE=${GLOBE_TILER_EXE:-$PWD/build/apps/globe-tiler/globe-tiler}
mkdir -p docs/images
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
export GLOBE_WEB_OUT=$TMP
status=0
for test in cesium_terrain.mjs maplibre_terrain.mjs; do
  picture=${test%_terrain.mjs}-fuji.png
  if sh tests/web/run_web_test.sh "$test" >"$TMP/$test.log" 2>&1; then
    cp "$TMP/$picture" docs/images/ && echo "wrote docs/images/$picture"
  else
    status=1
    cat "$TMP/$test.log"
    # The picture still, where the test drew it: its failing check is printed above.
    if [ -f "$TMP/$picture" ]; then
      cp "$TMP/$picture" docs/images/ && echo "wrote docs/images/$picture, but tests/web/$test FAILED" >&2
    else
      echo "tests/web/$test FAILED before drawing: docs/images/$picture not written" >&2
    fi
  fi
done
exit $status
