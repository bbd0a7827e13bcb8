#!/usr/bin/env bash
# CI's sanitizer pass: the whole test suite under ASan+UBSan+LSan (build-asan); the loader tests,
# the HTTP client and the disk cache under TSan (build-tsan). Halts on the first report. See
# docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=$(nproc)
SUPP="$PWD/tools/sanitizers/lsan-mesa.supp"

echo "== ASan+UBSan: every test"
# File by file (no unity batches): a source that compiles only thanks to a file batched before
# it fails here.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLOBE_WERROR=ON \
  -DGLOBE_SANITIZE=ON -DGLOBE_UNITY_BUILD=OFF >/dev/null
cmake --build build-asan -j"$JOBS"
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
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLOBE_WERROR=ON \
  -DGLOBE_SANITIZE_THREAD=ON >/dev/null
cmake --build build-tsan -j"$JOBS" --target globe_loader_tests globe_task_runner_tests \
  globe_http_tests globe_disk_cache_tests
TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
  ctest --test-dir build-tsan -j"$JOBS" -R '^(globe_loader_tests|globe_task_runner_tests|globe_http_tests|globe_disk_cache_tests)\.' \
  --output-on-failure --timeout 1800
