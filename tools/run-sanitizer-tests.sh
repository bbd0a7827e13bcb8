#!/usr/bin/env bash
# CI's sanitizer passes (docs/robustness.md): ASan+UBSan+LSan over every test that feeds the
# program bytes from outside (tools/sanitizers/asan-tests.txt), TSan over every test of code that
# runs on more than one thread (tools/sanitizers/tsan-tests.txt). Only those targets and what
# they link are built. Halts on the first report. GLOBE_WERROR=ON fails a build that warned.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=$(nproc)
SUPP="$PWD/tools/sanitizers/lsan-mesa.supp"
# TSan at -O1 with line tables only (-g1): what the sanitizers' documentation advises and the
# reports' stack traces need (instrumented code at -O2 -g took 2x as long to compile:
# docs/performance/ci-time.md). The ASan build sets its own (cmake/GlobeWarnings.cmake).
TSAN_FLAGS=(-DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG")
. tools/lib/seed-ctest-costs.sh
. tools/lib/test-tmpdir.sh
use_test_tmpdir  # scratch files on tmpfs where there is one (tools/lib/test-tmpdir.sh)
. tools/lib/build-checked.sh
. tools/lib/stage-time.sh
. tools/lib/gtest-results.sh  # the tests each pass ran, counted from GoogleTest's reports

# A list file's entries: the first word of each line that is not a comment, TARGET or
# TARGET:SuiteA,SuiteB.
entries() { grep -vE '^(#|\s*$)' "$1" | awk '{print $1}'; }
# The targets to build.
targets() { entries "$1" | cut -d: -f1; }
# A CTest regex for the tests of those entries (tests are named TARGET.Suite.Case, a
# parameterised suite Prefix/Suite). No groups: CMake's regular expressions allow only nine.
pattern() {
  entries "$1" | awk -F: '{ if ($2 == "") print "^" $1 "\\."; else {
    n = split($2, suites, ","); for (i = 1; i <= n; i++) print "^" $1 "\\.[^.]*" suites[i] "\\." } }' |
    paste -sd '|'
}

ASAN_TARGETS=$(targets tools/sanitizers/asan-tests.txt)
TSAN_TARGETS=$(targets tools/sanitizers/tsan-tests.txt)

echo "== ASan+UBSan: the tests that feed the program bytes (tools/sanitizers/asan-tests.txt)"
# The libraries and programs instrumented; the tests' own code compiled as in build-ci, so its
# objects come from the compiler cache (cmake/GlobeWarnings.cmake).
bash tools/configure.sh build-asan -DGLOBE_SANITIZE=ON
# shellcheck disable=SC2086 # one argument per target
stage "asan build" build_checked build-asan --target $ASAN_TARGETS
rm -rf build-asan/Testing/gtest
# The longest tests first (tools/run-tests.sh explains), from the committed times.
seed_ctest_costs build-asan
# The GLFW window tests (Xvfb) leak 112 bytes inside a GL/X driver module that is dlclose'd before
# LeakSanitizer reports, so the "<unknown module>" cannot be suppressed by name: they run with
# ASan+UBSan but without leak detection. Every other test runs with LeakSanitizer on.
WINDOW_TESTS='GlobeViewWindow\.|GlobePlay\.AWindow'
ASAN_TESTS=$(pattern tools/sanitizers/asan-tests.txt)
ASAN_RUN=(ctest --test-dir build-asan -j"$JOBS" --output-on-failure --timeout 1800)
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1 \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$SUPP:print_suppressions=0" \
  stage "asan suite" "${ASAN_RUN[@]}" -R "$ASAN_TESTS" -E "$WINDOW_TESTS"
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=0:strict_string_checks=1 \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  stage "asan window tests" "${ASAN_RUN[@]}" -R "$WINDOW_TESTS"
gtest_results build-asan/Testing/gtest

echo "== TSan: the tests of code that runs on several threads (tools/sanitizers/tsan-tests.txt)"
# Everything instrumented, the tests too: TSan reports false races where an uninstrumented
# reference count (a shared_ptr in a test's code) hands an object between threads.
bash tools/configure.sh build-tsan -DGLOBE_SANITIZE_THREAD=ON "${TSAN_FLAGS[@]}"
# shellcheck disable=SC2086
stage "tsan build" build_checked build-tsan --target $TSAN_TARGETS
rm -rf build-tsan/Testing/gtest
seed_ctest_costs build-tsan
# Mesa's llvmpipe draws on threads of its own, uninstrumented, whose hand-offs TSan cannot see:
# it draws on the calling thread here, and keeps no shader-cache thread.
LP_NUM_THREADS=0 MESA_SHADER_CACHE_DISABLE=true \
  TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tools/sanitizers/tsan-gdal.supp" \
  stage "tsan suite" ctest --test-dir build-tsan -j"$JOBS" \
  -R "$(pattern tools/sanitizers/tsan-tests.txt)" --output-on-failure --timeout 1800
gtest_results build-tsan/Testing/gtest
