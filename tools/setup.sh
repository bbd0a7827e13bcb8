#!/usr/bin/env bash
# One-command set-up: installs the Debian packages, builds globe, tiles the bundled real data
# (whole-globe ETOPO20 + a GTOPO30 crop of eastern England + the Mount Fuji SRTM3 tile) into
# ./pyramid, prints what it holds, renders two views headless into out/ and queries the
# height of Mount Fuji's summit.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)"
./build/tools/tiler/globe-tiler -o pyramid data/dem/ETOPO20.DEM data/dem/W002N52.DEM data/dem/E138N35_FUJI.DEM
./build/src/app/globe info pyramid
mkdir -p out
./build/src/app/globe snapshot pyramid --camera 138.60,35.20,6000,30,-15,0 -o out/fuji_oblique.png
./build/src/app/globe snapshot pyramid --camera 138,30,20000000 -o out/globe.png
echo "138.7275,35.3606" | ./build/src/app/globe query pyramid
echo "Images in out/. Interactive: ./build/src/app/globe view pyramid (needs a display)"
