#!/usr/bin/env bash
# CI's sanitizer pass: the whole test suite under ASan+UBSan+LSan (build-asan); the loader tests,
# the HTTP client and the disk cache under TSan (build-tsan). Halts on the first report. See
# docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=$(nproc)
SUPP="$PWD/tools/sanitizers/lsan-mesa.supp"
# Line tables only (-g1): enough for the reports' stack traces, and instrumented code with full
# debug info takes a third longer to compile (the ASan build is the longest step of CI).
LINE_TABLES=(-DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG"
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG")
. tools/lib/seed-ctest-costs.sh

echo "== ASan+UBSan: every test"
# In unity batches, as the other builds; the TSan build below compiles its files one by one, so a
# source that compiles only thanks to a file batched before it still fails in CI.
bash tools/configure.sh build-asan -DGLOBE_WERROR=ON -DGLOBE_SANITIZE=ON "${LINE_TABLES[@]}"
cmake --build build-asan -j"$JOBS"
# The longest tests first (tools/run-tests.sh explains), from the committed times.
seed_ctest_costs build-asan
# The GLFW window tests (Xvfb) leak 112 bytes inside a GL/X driver module that is dlclose'd before
# LeakSanitizer reports, so the "<unknown module>" cannot be suppressed by name: they run with
# ASan+UBSan but without leak detection. Every other test runs with LeakSanitizer on.
WINDOW_TESTS='GlobeViewWindow\.|GlobePlay\.AWindow'
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1 \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$SUPP:print_suppressions=0" \
  ctest --test-dir build-asan -j"$JOBS" -E "$WINDOW_TESTS" --output-on-failure --timeout 1800
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=0:strict_string_checks=1 \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  ctest --test-dir build-asan -j"$JOBS" -R "$WINDOW_TESTS" --output-on-failure --timeout 1800

echo "== TSan: the loader and its task runners, the HTTP client and the disk cache"
# File by file (no unity batches): see above.
bash tools/configure.sh build-tsan -DGLOBE_WERROR=ON -DGLOBE_SANITIZE_THREAD=ON \
  -DGLOBE_UNITY_BUILD=OFF "${LINE_TABLES[@]}"
cmake --build build-tsan -j"$JOBS" --target globe_loader_tests globe_task_runner_tests \
  globe_http_tests globe_disk_cache_tests
TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
  ctest --test-dir build-tsan -j"$JOBS" -R '^(globe_loader_tests|globe_task_runner_tests|globe_http_tests|globe_disk_cache_tests)\.' \
  --output-on-failure --timeout 1800
