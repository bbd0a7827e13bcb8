#!/usr/bin/env bash
# One-command set-up: installs the Debian packages, builds globe, tiles the bundled real data
# (whole-globe ETOPO20 + a GTOPO30 crop of eastern England + the Mount Fuji SRTM3 tile + Zion
# National Park's SRTM 3") into ./pyramid and the bundled imagery (the 5400x2700 Blue Marble and
# the Landsat 8 scene over Zion) into two imagery layers in ./layers and the bundled GSHHG land
# polygons into a water mask (./layers/coast: true coasts over the coarse grid), prints what they hold,
# renders views headless into out/, queries the height of Mount Fuji's summit and plays the
# bundled demo flight over Zion with both layers into out/play (frames, log, video when ffmpeg is
# installed; in a window as well when a display exists).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh --no-video
# The demo's video encoder (ffmpeg and its 115 packages) downloads and installs while globe builds:
# apt works mostly on the network and the disk, the compiler on the cores. Waited for before the
# flight; without it the flight still writes its frames.
mkdir -p out
bash tools/install-deps.sh --video >out/video-install.log 2>&1 &
VIDEO_INSTALL=$!
# Only the two programs the main job runs, without the tests (their packages come with
# tools/run-tests.sh, which builds the rest in the same directory with the same flags).
bash tools/configure.sh build -DGLOBE_BUILD_TESTS=OFF
cmake --build build -j"$(nproc)" --target globe globe-tiler
./build/apps/globe-tiler/globe-tiler -o pyramid data/dem/ETOPO20.DEM data/dem/W002N52.DEM \
  data/dem/E138N35_FUJI.DEM data/dem/zion-srtm3.tif
./build/apps/globe-tiler/globe-tiler imagery -o layers/blue-marble --bounds -180,-90,180,90 \
  data/imagery/world.topo.bathy.200412.3x5400x2700.jpg
./build/apps/globe-tiler/globe-tiler imagery -o layers/zion data/imagery/zion-landsat8-rgb.tif
./build/apps/globe-tiler/globe-tiler water-mask -o layers/coast data/coast/gshhg-l-land.fgb \
  data/coast/gshhg-f-*.fgb
./build/apps/globe/globe info pyramid
LAYERS=(--layer layers/blue-marble --layer layers/zion)
./build/apps/globe/globe snapshot pyramid --camera 138,30,20000000 "${LAYERS[@]}" -o out/globe.png
./build/apps/globe/globe snapshot pyramid --camera -112.93,37.16,4500,330,-20,0 "${LAYERS[@]}" -o out/zion.png
./build/apps/globe/globe snapshot pyramid --camera 138.60,35.20,6000,30,-15,0 --layer layers/coast -o out/fuji_oblique.png
./build/apps/globe/globe snapshot pyramid --camera 0.3,52.9,60000 --layer layers/coast -o out/wash.png
echo "138.7275,35.3606" | ./build/apps/globe/globe query pyramid
if wait "$VIDEO_INSTALL"; then rm -f out/video-install.log; else
  echo "ffmpeg did not install (out/video-install.log says why): the flight writes frames, no video"
fi
echo "Images in out/. Interactive: ./build/apps/globe/globe view pyramid ${LAYERS[*]} (needs a display)"
# 15 frames a second (481 frames) show the flight and the glide as well as 30 do, in half the
# time (a set-up within 6 minutes: docs/performance/ci-time.md); --fps 30 for a smoother video.
PLAY=(./build/apps/globe/globe play pyramid data/paths/zion-demo.json "${LAYERS[@]}" --out out/play --size 640x360 --fps 15)
if command -v ffmpeg >/dev/null 2>&1; then PLAY+=(--video out/play/zion.mp4); fi
# In a window when a display works; headless (OSMesa) otherwise. Same frames either way.
if [ -n "${DISPLAY:-}" ] && "${PLAY[@]}" --window; then :; else "${PLAY[@]}"; fi
echo "Demo flight: frames in out/play/frames/, per-frame log out/play/log.csv, summary out/play/summary.txt"
if [ -f out/play/zion.mp4 ]; then echo "Video: out/play/zion.mp4"; fi
