#!/usr/bin/env bash
# Installs the Debian packages globe needs to build and run (needs root or sudo); with --tests,
# those its test suite needs as well (tools/run-tests.sh asks for them): GoogleTest, Google
# Benchmark, nginx, Xvfb and xdotool, ImageMagick, gnuplot and matplotlib, help2man, gdal-bin.
# The set-up command installs only the first set, so a new machine downloads ~110 packages fewer
# before it shows anything; and it installs the video encoder (ffmpeg: 115 packages, 64 MB, used
# only for the demo's video) while the build runs, not before it:
#
#   tools/install-deps.sh [--tests]   everything the build, the programs (and the tests) need
#   tools/install-deps.sh --no-video  the same without ffmpeg
#   tools/install-deps.sh --video     ffmpeg alone, without refreshing the package lists
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
PACKAGES=(
  build-essential cmake pkg-config git ca-certificates
  libosmesa6-dev libgl-dev libgl1-mesa-dri libegl-dev libglfw3-dev libglew-dev libglm-dev
  libstb-dev libfreetype-dev libharfbuzz-dev fonts-dejavu-core libgdal-dev libjpeg-dev
  libdeflate-dev zlib1g-dev libwebp-dev libavif-dev libtomlplusplus-dev libgeographiclib-dev nlohmann-json3-dev
  libtinygltf-dev libdraco-dev libmeshoptimizer-dev
  libcli11-dev libfmt-dev libtinyxml2-dev libcairo2-dev libcurl4-openssl-dev ccache lld
  ninja-build python3-glad
)
VIDEO_PACKAGES=(ffmpeg)
TEST_PACKAGES=(
  libgtest-dev libgmock-dev libbenchmark-dev help2man time xvfb xdotool x11-apps imagemagick
  gnuplot-nox python3-matplotlib mesa-utils nginx-light openssl gdal-bin libxml2-utils
)
case "${1:-}" in
  "") PACKAGES+=("${VIDEO_PACKAGES[@]}") ;;
  --tests) PACKAGES+=("${VIDEO_PACKAGES[@]}" "${TEST_PACKAGES[@]}") ;;
  --no-video) ;;
  --video) PACKAGES=("${VIDEO_PACKAGES[@]}") ;;
  *) echo "install-deps.sh: unknown option '$1' (--tests, --no-video or --video)" >&2; exit 2 ;;
esac
# --video follows a --no-video run of a moment ago: its package lists are fresh.
if [ "${1:-}" != --video ]; then $SUDO apt-get update -qq; fi
HAD_NGINX=0
if dpkg -s nginx-light >/dev/null 2>&1 || dpkg -s nginx >/dev/null 2>&1; then HAD_NGINX=1; fi
$SUDO apt-get install -y -qq --no-install-recommends "${PACKAGES[@]}" >/dev/null
# nginx-light is for the HTTP tests, which start their own on 127.0.0.1 and stop it; the
# distribution's service (port 80 on every address) is not wanted where we installed it.
if [ "$HAD_NGINX" = 0 ] && command -v systemctl >/dev/null 2>&1; then
  $SUDO systemctl disable --now nginx >/dev/null 2>&1 || true
fi
# Optional: clang with libFuzzer for the fuzz targets (tests/fuzz, -DGLOBE_FUZZ=ON). CI does not
# need it: the corpora replay under g++ and the sanitizer builds use g++'s libasan/libtsan.
if [ "${GLOBE_INSTALL_FUZZ:-0}" = 1 ]; then
  $SUDO apt-get install -y -qq --no-install-recommends clang libclang-rt-14-dev >/dev/null
fi
