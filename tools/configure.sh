#!/usr/bin/env bash
# Configures a build directory the way tools/setup.sh and tools/run-tests.sh share it:
# RelWithDebInfo, ccache when installed (its objects shared between checkouts in different
# folders), Ninja when installed. Extra arguments go to cmake (the sanitizer builds add theirs).
#
#   tools/configure.sh BUILD_DIR [CMAKE_ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:?build directory}
shift
LAUNCHER=()
if command -v ccache >/dev/null 2>&1; then
  # Paths under the checkout hashed as relative ones and the working directory left out of the
  # hash (the objects hold no absolute path: -ffile-prefix-map in CMakeLists.txt), so a clone in
  # another folder gets this one's objects from the cache (docs/performance/ci-time.md).
  CCACHE="env;CCACHE_BASEDIR=$PWD;CCACHE_NOHASHDIR=1;ccache"
  LAUNCHER=(-DCMAKE_C_COMPILER_LAUNCHER="$CCACHE" -DCMAKE_CXX_COMPILER_LAUNCHER="$CCACHE")
fi
# Ninja schedules compiles across targets (Make waits for each library before its users' objects):
# a cold build of globe and globe-tiler on 2 cores in 162 s instead of 186 s. A directory that
# was made with another generator keeps it (CMake refuses to switch one).
GENERATOR=()
if command -v ninja >/dev/null 2>&1 && ! grep -qs '^CMAKE_GENERATOR:INTERNAL=' "$BUILD/CMakeCache.txt"; then
  GENERATOR=(-G Ninja)
fi
cmake -S . -B "$BUILD" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${LAUNCHER[@]}" "$@" >/dev/null
