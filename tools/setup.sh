#!/usr/bin/env bash
# One-command set-up: installs the Debian packages, builds globe, tiles the bundled real data
# (whole-globe ETOPO20 + a GTOPO30 crop of eastern England + the Mount Fuji SRTM3 tile) into
# ./pyramid and prints what it holds.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)"
./build/tools/tiler/globe-tiler -o pyramid data/dem/ETOPO20.DEM data/dem/W002N52.DEM data/dem/E138N35_FUJI.DEM
./build/src/app/globe info pyramid
