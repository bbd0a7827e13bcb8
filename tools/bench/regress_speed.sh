#!/usr/bin/env bash
# globe regress's speed: a suite of 40 views of the bundled data at 480x270 (the globe, Fuji,
# Zion, the poles, the Blue Marble and Landsat layers), run at --jobs 1 and 2, against the same
# views as single `globe snapshot` runs one after another (the sum of their wall times). The
# issue's goal: a run at N jobs within 1.2x of that sum divided by N. Medians of RUNS runs, in one
# run of this script. Writes docs/performance/regress-speed.md.
#
#   tools/bench/regress_speed.sh BUILD_DIR [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:?build directory}
RUNS=${2:-3}
cmake --build "$BUILD" -j"$(nproc)" --target globe globe-tiler >/dev/null
GLOBE=$(realpath "$BUILD/apps/globe/globe")
WORK=$(mktemp -d /tmp/globe-regress-speed.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
bash tools/bench/tile_bundled.sh "$BUILD/apps/globe-tiler/globe-tiler" "$WORK"

python3 tools/bench/regress_bench_suite.py "$WORK/suite.json"  # 40 views at 480x270
"$GLOBE" regress "$WORK/suite.json" --out "$WORK/out" --update >/dev/null

median() { sort -n | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
seconds() { local s=$EPOCHREALTIME; "$@" >/dev/null 2>&1; awk -v a="$s" -v b="$EPOCHREALTIME" 'BEGIN {printf "%.3f\n", b - a}'; }
singles() {  # every view as its own globe snapshot, one after another: the sum of their times
  python3 -c 'import json,sys; [print("\t".join(v["snapshot"])) for v in json.load(open(sys.argv[1]))["views"]]' \
    "$WORK/suite.json" | (cd "$WORK" && while IFS=$'\t' read -r -a args; do
      "$GLOBE" snapshot "${args[@]}" -o "$WORK/single.png" 2>/dev/null
    done) >"$WORK/singles.out"
}
# What the singles' own lines say they took ("..., 0.41 s": from opening the pyramid to the PNG
# written, the process's start and exit left out), summed over the 40.
own_seconds() { awk '/ tiles drawn, / {s += $(NF - 1)} END {printf "%.3f\n", s}' "$WORK/singles.out"; }
: >"$WORK/t-single" >"$WORK/t-own" >"$WORK/t-j1" >"$WORK/t-j2"
for _ in $(seq "$RUNS"); do
  seconds singles >>"$WORK/t-single"
  own_seconds >>"$WORK/t-own"
  seconds "$GLOBE" regress "$WORK/suite.json" --out "$WORK/out" --jobs 1 >>"$WORK/t-j1"
  seconds "$GLOBE" regress "$WORK/suite.json" --out "$WORK/out" --jobs 2 >>"$WORK/t-j2"
done
"$GLOBE" regress "$WORK/suite.json" --out "$WORK/out" --jobs 2 >/dev/null  # exit 0: all passed
S=$(median <"$WORK/t-single")
OWN=$(median <"$WORK/t-own")
J1=$(median <"$WORK/t-j1")
J2=$(median <"$WORK/t-j2")
OUT_MD=${OUT_MD:-docs/performance/regress-speed.md}
{
  echo "# globe regress: speed"
  echo
  echo "A suite of 40 views of the bundled data at 480x270 (8 places x terrain, lit, Blue Marble,"
  echo "Blue Marble + Landsat, SSE 8), every view compared with its reference (all pass). Medians"
  echo "of $RUNS runs in one run of \`tools/bench/regress_speed.sh\` ($(date -u +%Y-%m-%d),"
  echo "$(nproc) cores, $(git describe --always --dirty)). The single snapshots: the same 40 views,"
  echo "each \`globe snapshot\` run alone, one after another."
  echo
  echo "The own times: the sum of what each single snapshot says it took (from opening the"
  echo "pyramid to the PNG written; the process's start and exit left out)."
  echo
  echo "| run | wall s | views/s | vs single snapshots / jobs | vs their own times / jobs |"
  echo "|---|---|---|---|---|"
  awk -v s="$S" -v o="$OWN" 'BEGIN {printf "| 40 single snapshots | %.2f | %.2f | 1.00 | %.2f |\n", s, 40 / s, s / o}'
  awk -v o="$OWN" 'BEGIN {printf "| their own times, summed | %.2f | %.2f | | 1.00 |\n", o, 40 / o}'
  awk -v s="$S" -v o="$OWN" -v t="$J1" 'BEGIN {printf "| regress --jobs 1 | %.2f | %.2f | %.2f | %.2f |\n", t, 40 / t, t / s, t / o}'
  awk -v s="$S" -v o="$OWN" -v t="$J2" 'BEGIN {printf "| regress --jobs 2 | %.2f | %.2f | %.2f | %.2f |\n", t, 40 / t, t / (s / 2), t / (o / 2)}'
  echo
  echo "Goal (issue 51): at most 1.20 in the last two columns."
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
