#!/usr/bin/env bash
# Builds globe's tests in the same build directory and with the same flags as tools/setup.sh (so
# nothing is rebuilt that setup built) and runs the whole suite with CTest. Without a display
# the suite runs under xvfb-run, so the GLFW window tests run too. Any skipped test is listed at
# the end, loudly. BUILD_DIR (default build) changes the directory; GLOBE_WERROR=ON (CI) fails
# the run when the compiler warned (tools/lib/build-checked.sh: the flags stay the same).
# --save-costs afterwards copies the measured test times to tests/ctest-costs.txt, which a build
# directory without its own gets before CTest runs. Each step prints its time (CI-time lines).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
. tools/lib/build-checked.sh
. tools/lib/stage-time.sh
. tools/lib/test-tmpdir.sh
# The packages the tests need beyond the set-up's (apt; quick where they are installed).
stage "test packages (apt)" bash tools/install-deps.sh --tests
# Scratch files on tmpfs where there is one (before configuring: the shared fixtures' folder is
# set there); tools/lib/test-tmpdir.sh says why.
use_test_tmpdir
echo "test scratch files in ${TMPDIR:-/tmp}"
bash tools/configure.sh "$BUILD" -DGLOBE_BUILD_TESTS=ON
# Chromium, node and npm (apt, where missing) and tools/web's pinned npm packages: the web
# clients (CesiumJS, MapLibre) that tests/web shows the exports in. Slurm, munge, GNU parallel and
# python3-yaml (apt, where missing): what tests/cluster runs. Fetched while the tests compile
# (the network and the disk, not the cores: 37 s off a fresh machine's test command).
INSTALL_LOG=$BUILD/test-installs.log
mkdir -p "$BUILD"
test_installs() { bash tools/web/install.sh && bash tools/cluster/install.sh; }
test_installs >"$INSTALL_LOG" 2>&1 &
installs=$!
# The tests and the programs they run (target globe_tests); the benchmarks and tools build when
# their scripts run them (CI builds everything: .ci/run).
build_status=0
stage "build ($BUILD)" build_checked "$BUILD" --target globe_tests || build_status=$?
wait_installs() {
  local status=0
  wait "$installs" || status=$?
  cat "$INSTALL_LOG"
  return $status
}
stage "test installs (beside build)" wait_installs
[ $build_status -eq 0 ] || exit $build_status
# CTest starts the longest tests first when it knows their times; a new build directory does not,
# so it gets the committed ones (without them the long tests may start last and the suite waits).
. tools/lib/seed-ctest-costs.sh
seed_ctest_costs "$BUILD"
COSTS=$BUILD/Testing/Temporary/CTestCostData.txt
CTEST=(ctest --test-dir "$BUILD" -j"$(nproc)" --output-on-failure --timeout 900)
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null 2>&1; then
  CTEST=(xvfb-run -a -s "-screen 0 1280x1024x24" "${CTEST[@]}")
fi
status=0
# CTest runs each test program once per GoogleTest suite (cmake/GlobeTestGroupsScript.cmake says
# why); the programs' reports, counted after the run, say how many tests that was.
. tools/lib/gtest-results.sh
rm -rf "$BUILD/Testing/gtest"
suite() { "${CTEST[@]}" 2>&1 | tee "$BUILD/ctest-output.txt"; }
stage "suite" suite || status=$?
gtest_results "$BUILD/Testing/gtest" | tee "$BUILD/gtest-results.txt" || status=1
skipped=$( (grep -E '\(Skipped\)$' "$BUILD/ctest-output.txt"; grep '^  skipped: ' "$BUILD/gtest-results.txt") || true)
if [ -n "$skipped" ]; then
  echo
  echo "!!! $(echo "$skipped" | wc -l) test(s) SKIPPED: they did not run here. Their reasons are in"
  echo "!!! $BUILD/Testing/Temporary/LastTest.log; README.md, 'Tests that need more', says what each needs."
  echo "$skipped" | sed 's/^/!!!   /'
fi
if [ "${1:-}" = "--save-costs" ] && [ $status -eq 0 ]; then
  { grep '^#' tests/ctest-costs.txt
    # Only the tests there are now (CTest keeps the times of tests since renamed or grouped).
    ctest --test-dir "$BUILD" -N | sed -n 's/^ *Test *#[0-9]*: //p' |
      awk 'NR == FNR {known[$1]; next}
           NF == 3 && $3 >= 0.3 && ($1 in known) {printf "%s %.2f\n", $1, $3}' - "$COSTS" |
      sort -k2 -rn
  } >tests/ctest-costs.txt.tmp
  mv tests/ctest-costs.txt.tmp tests/ctest-costs.txt
fi
exit $status
