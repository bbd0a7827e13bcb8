# Sourced: build_checked BUILD_DIR [cmake --build arguments...] builds and, when GLOBE_WERROR=ON,
# fails if the compiler warned. The warnings are read from the build's output rather than made
# errors with -Werror: the flags then stay those of the README's build, so CI's clone gets the
# objects a developer's `tools/run-tests.sh` compiled from the compiler cache (which replays a
# cached compile's warnings too). docs/performance/ci-time.md.
build_checked() {
  local build=$1
  shift
  local log=$build/build-output.txt
  mkdir -p "$build"
  local status=0
  cmake --build "$build" -j"$(nproc)" "$@" 2>&1 | tee "$log" || status=$?
  if [ "$status" != 0 ]; then return "$status"; fi
  if [ "${GLOBE_WERROR:-OFF}" = ON ] && grep -qE '(^|: )warning: ' "$log"; then
    echo "!!! the build warned (GLOBE_WERROR=ON): $(grep -cE '(^|: )warning: ' "$log") warning(s), in $log:"
    grep -E '(^|: )warning: ' "$log" | sort -u | head -50
    return 1
  fi
}
