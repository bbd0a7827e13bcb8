#!/usr/bin/env bash
# Configures a build directory the way tools/setup.sh and tools/run-tests.sh share it:
# RelWithDebInfo, ccache when installed. Extra arguments go to cmake (CI adds -DGLOBE_WERROR=ON
# in its own directory).
#
#   tools/configure.sh BUILD_DIR [CMAKE_ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:?build directory}
shift
LAUNCHER=()
if command -v ccache >/dev/null 2>&1; then
  LAUNCHER=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${LAUNCHER[@]}" "$@" >/dev/null
