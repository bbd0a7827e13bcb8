#!/usr/bin/env bash
# Installs the Debian packages globe needs to build and run (needs root or sudo); with --tests,
# those its test suite needs as well (tools/run-tests.sh asks for them): GoogleTest, Google
# Benchmark, nginx, Xvfb and xdotool, ImageMagick, gnuplot and matplotlib, help2man. The set-up
# command installs only the first set, so a new machine downloads ~110 packages fewer before it
# shows anything.
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
PACKAGES=(
  build-essential cmake pkg-config git ca-certificates
  libosmesa6-dev libgl-dev libgl1-mesa-dri libegl-dev libglfw3-dev libglew-dev libglm-dev
  libstb-dev libfreetype-dev libharfbuzz-dev fonts-dejavu-core libgdal-dev gdal-bin libjpeg-dev
  libdeflate-dev libwebp-dev libtomlplusplus-dev libgeographiclib-dev nlohmann-json3-dev
  libcli11-dev libfmt-dev libtinyxml2-dev libcairo2-dev libcurl4-openssl-dev ffmpeg ccache lld
  python3-glad
)
TEST_PACKAGES=(
  libgtest-dev libgmock-dev libbenchmark-dev help2man time xvfb xdotool x11-apps imagemagick
  gnuplot-nox python3-matplotlib mesa-utils nginx-light openssl
)
if [ "${1:-}" = "--tests" ]; then PACKAGES+=("${TEST_PACKAGES[@]}"); fi
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
