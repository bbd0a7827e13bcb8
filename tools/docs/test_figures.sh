#!/usr/bin/env bash
# The figures the docs quote from tests (void fills, collision audits, stress maxima): runs
# those tests from a built tree and writes what each prints, verbatim, to
# docs/performance/test-figures.md, with the commit and machine, so the docs cite a generated
# document instead of numbers copied by hand (tools/docs/check_numbers.py checks that they agree).
#
#   tools/docs/test_figures.sh [BUILD_DIR]      (default: build)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:-$ROOT/build}
OUT_MD=${OUT_MD:-$ROOT/docs/performance/test-figures.md}
# test program (under BUILD/tests) and GoogleTest filter
RUNS=(
  "tiling/globe_tiler_tests TilerConditioning.*"
  "collision/globe_response_tests FujiDrive.*:WallDrive.*:WallGlide.*:RidgeSlide.*"
  "collision/globe_collision_tests RealPyramid.*:StressQotcd.*"
  "geo/globe_geo_tests StressGeodesy.*"
  "render/globe_render_tests PlanetScalePrecision.*"
)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
{
  echo "# Figures the tests print"
  echo
  echo "What the tests below print when they pass (their assertions are the pass criteria; these"
  echo "are the measured values), run one after another from \`$(basename "$BUILD")\`. Made by"
  echo "\`tools/docs/test_figures.sh\` on $(date -u +%Y-%m-%d); do not edit by hand."
  echo
  echo "- commit: $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet -- src tests tools || echo " + uncommitted changes")"
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
  for run in "${RUNS[@]}"; do
    read -r program filter <<<"$run"
    exe=$BUILD/tests/$program
    [ -x "$exe" ] || { echo "build it first: $exe" >&2; exit 1; }
    if ! (cd "$BUILD/tests/$(dirname "$program")" && "$exe" --gtest_filter="$filter" \
      --gtest_color=no) >"$WORK/log" 2>&1; then
      tail -30 "$WORK/log" >&2
      echo "$program --gtest_filter='$filter' failed: no figures from a failing test" >&2
      exit 1
    fi
    echo
    echo "## \`$(basename "$program") --gtest_filter='$filter'\`"
    echo
    echo '```'
    # The tests' own lines: everything but GoogleTest's progress markers.
    grep -v -E '^\[[ =A-Z-]+\]|^Note: Google Test filter|^Running main\(\) from|^$' "$WORK/log" || true
    echo '```'
  done
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
echo "wrote $OUT_MD"
