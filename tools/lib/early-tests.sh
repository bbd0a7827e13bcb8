# Sourced: the tests labelled `early` (tests/web, tests/cluster) run nothing but globe and
# globe-tiler, so tools/run-tests.sh starts them as soon as those two are built, in the background,
# while the test programs compile; the suite then runs the rest (`ctest -LE early`). They spend
# half their time waiting (Chromium's software WebGL between frames, Slurm's daemons), which the
# compiler fills; beside the suite's heaviest tests the CesiumJS one took 91-151 s instead of
# 28-37 s (docs/performance/ci-time.md). CTest runs them from $BUILD/tests, whose Testing/ folder is
# not the suite's, so the two runs keep separate logs and costs.
#   start_early_tests BUILD_DIR   then, after the suite:   finish_early_tests
start_early_tests() {
  EARLY_BUILD=$1
  EARLY_OUT=$EARLY_BUILD/early-tests-output.txt
  ctest --test-dir "$EARLY_BUILD/tests" -L early --output-on-failure --timeout 900 \
    >"$EARLY_OUT" 2>&1 &
  EARLY_PID=$!
  echo "early tests (web clients, cluster engines) started: their output in $EARLY_OUT"
}

# Waits for them, prints their output and returns their exit status.
finish_early_tests() {
  local status=0
  wait "$EARLY_PID" || status=$?
  cat "$EARLY_OUT"
  return "$status"
}
