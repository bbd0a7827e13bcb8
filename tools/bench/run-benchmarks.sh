#!/usr/bin/env bash
# Runs globe-bench (the Fig. 7 timings and the accuracy mode) pinned to one core and writes
# docs/performance/performance-collision.md, tools/bench/*.png and tools/bench/results/. About 2 minutes.
#
# Environment: BUILD_DIR (default build-bench; configured RelWithDebInfo if missing),
# REPETITIONS (9), MIN_TIME (0.2 s per repetition), QUERIES_PER_REGION (40000, three regions),
# BENCH_CPU (the core to pin to; default the last one), FILTER (a --benchmark_filter). The
# repetitions are interleaved at random, so a slow spell of the machine falls on every benchmark
# alike and the ratios between them stay fair.
set -euo pipefail

REPO=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${BUILD_DIR:-$REPO/build-bench}
REPETITIONS=${REPETITIONS:-9}
MIN_TIME=${MIN_TIME:-0.2}
QUERIES=${QUERIES_PER_REGION:-40000}
FILTER=${FILTER:-.}
RESULTS=$REPO/tools/bench/results
PYTHON=/usr/bin/python3
[[ -x $PYTHON ]] || PYTHON=python3

if [[ ! -f $BUILD/CMakeCache.txt ]]; then
  cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
cmake --build "$BUILD" -j2 --target globe-bench
BENCH=$BUILD/tools/bench/globe-bench

PIN=()
if command -v taskset >/dev/null; then
  CPU=${BENCH_CPU:-$(($(nproc) - 1))}
  PIN=(taskset -c "$CPU")
fi
mkdir -p "$RESULTS"
# The commit measured, and whether the sources differ from it (before the outputs change).
COMMIT=$(git -C "$REPO" rev-parse --short HEAD 2>/dev/null || echo unknown)
DIRTY=$(git -C "$REPO" status --porcelain --untracked-files=no -- src tools/bench/*.cpp \
  tools/bench/*.hpp CMakeLists.txt 2>/dev/null | head -c1)
LOAD_BEFORE=$(cut -d' ' -f1-3 /proc/loadavg)
STARTED=$(date -u +%Y-%m-%dT%H:%M:%SZ)

echo "== timings (${REPETITIONS} repetitions of >= ${MIN_TIME} s, pinned: ${PIN[*]:-no})"
"${PIN[@]}" "$BENCH" --benchmark_filter="$FILTER" --benchmark_enable_random_interleaving=true \
  --benchmark_repetitions="$REPETITIONS" --benchmark_min_time="$MIN_TIME" \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$RESULTS/benchmarks.json" --benchmark_out_format=json

echo "== accuracy (3 x ${QUERIES} queries)"
"${PIN[@]}" "$BENCH" --accuracy --queries-per-region "$QUERIES" --out "$RESULTS" |
  tee "$RESULTS/accuracy.txt"

LOAD_AFTER=$(cut -d' ' -f1-3 /proc/loadavg)
export STARTED LOAD_BEFORE LOAD_AFTER REPETITIONS MIN_TIME
export PINNED="${PIN[*]:-}"
export COMMIT DIRTY
MPLBACKEND=Agg "$PYTHON" "$REPO/tools/bench/make_report.py" --results "$RESULTS" \
  --doc "$REPO/docs/performance/performance-collision.md" --plots "$REPO/tools/bench" --readme "$REPO/README.md"
