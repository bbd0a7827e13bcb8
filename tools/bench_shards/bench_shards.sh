#!/usr/bin/env bash
# Sharded tiling against the one-machine run, in one run: the CPU time (user + system) of the
# shards plus the merge against that of `globe-tiler -o OUT INPUT...`, every process on one thread
# (-j 1), median of REPS repetitions, each checked byte-identical (diff -r). Also the peak memory
# of a shard and the rate and output size the GLO-30 plan in docs/scale-out-glo30.md uses.
# Inputs: four real 3″ SRTM tiles (Fuji, the Taunus pair, the Kattegat coast): one resolution, 1°
# tiles, as Copernicus GLO-30 is laid out.
# Usage: tools/bench_shards/bench_shards.sh [BUILD_DIR] [SHARDS] [REPS]  (defaults: build, 4, 5).
# Writes docs/performance/sharded-tiling.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
SHARDS=${2:-4}
REPS=${3:-5}
cmake --build "$BUILD" --target globe-tiler -j"$(nproc)" >/dev/null
TILER=$BUILD/apps/globe-tiler/globe-tiler
D=tests/data/dem/gtopo30
INPUTS=("$D/E138N35_FUJI.DEM" "$D/N50E008.DEM" "$D/N50E009.DEM" "$D/N57E011.DEM")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# CPU seconds (user + system) and peak KiB of one run, appended to $1.
timed() {
  local log=$1
  shift
  /usr/bin/time -f "%U %S %M" -o "$WORK/time" "$@" >/dev/null
  awk '{printf "%.3f %d\n", $1 + $2, $3}' "$WORK/time" >>"$log"
}
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

for rep in $(seq "$REPS"); do
  rm -rf "$WORK/whole" "$WORK/sharded"
  : >"$WORK/shards-$rep"
  timed "$WORK/whole.log" "$TILER" -q -j 1 -o "$WORK/whole" "${INPUTS[@]}"
  for k in $(seq 0 $((SHARDS - 1))); do
    timed "$WORK/shards-$rep" "$TILER" -q -j 1 --shard "$k/$SHARDS" -o "$WORK/sharded" "${INPUTS[@]}"
  done
  timed "$WORK/merge.log" "$TILER" merge -q -j 1 -o "$WORK/sharded" "${INPUTS[@]}"
  diff -r "$WORK/whole" "$WORK/sharded" >/dev/null || { echo "rep $rep: not identical" >&2; exit 1; }
  awk '{s += $1} END {printf "%.3f\n", s}' "$WORK/shards-$rep" >>"$WORK/shards-total.log"
  awk '{if ($1 > m) m = $1} END {printf "%.3f\n", m}' "$WORK/shards-$rep" >>"$WORK/shards-slowest.log"
  cat "$WORK/shards-$rep" >>"$WORK/shards-all.log"
done

WHOLE=$(cut -d' ' -f1 "$WORK/whole.log" | median)
SHARDS_TOTAL=$(median <"$WORK/shards-total.log")
SLOWEST=$(median <"$WORK/shards-slowest.log")
MERGE=$(cut -d' ' -f1 "$WORK/merge.log" | median)
WHOLE_KIB=$(cut -d' ' -f2 "$WORK/whole.log" | median)
SHARD_KIB=$(cut -d' ' -f2 "$WORK/shards-all.log" | sort -n | tail -1)
MERGE_KIB=$(cut -d' ' -f2 "$WORK/merge.log" | median)
TILES=$(python3 -c "import json; m = json.load(open('$WORK/whole/manifest.json')); print(sum(l['tiles'] for l in m['levels']))")
PACK_BYTES=$(find "$WORK/whole" -name '*.pack' -printf '%s\n' | awk '{s += $1} END {print s}')
PLAN=$("$TILER" plan --shards "$SHARDS" "${INPUTS[@]}")
CPU=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')

ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
percent() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.1f", 100 * a / b}'; }
RATE=$(awk -v t="$TILES" -v s="$WHOLE" 'BEGIN {printf "%.0f", t / s}')
# GLO-30 arithmetic: 26,000 1° sources, level 16 deepest, shard level 13, 1,000 shards.
GLO_TILES_PER_SOURCE=$(awk 'BEGIN {printf "%.0f", (65536 / 180) ^ 2}')
GLO_TILES_RAW=$(awk -v p="$GLO_TILES_PER_SOURCE" 'BEGIN {printf "%.0f", 26000 * p * 4 / 3}')
GLO_TILES=$(awk -v t="$GLO_TILES_RAW" 'BEGIN {printf "%.1f billion", t / 1e9}')
GLO_UNITS=$(awk 'BEGIN {printf "%.0f", 26000 / (64 * 180 / 8192) ^ 2}')
GLO_UNITS_PER_SHARD=$(awk -v u="$GLO_UNITS" 'BEGIN {printf "%.0f", u / 1000}')
GLO_CORE_HOURS=$(awk -v t="$GLO_TILES_RAW" -v r="$RATE" 'BEGIN {printf "%.0f", t / r / 3600}')
GLO_SHARD_MINUTES=$(awk -v t="$GLO_TILES_RAW" -v r="$RATE" 'BEGIN {printf "%.0f", t / 1000 / r / 60}')
GLO_MERGE_MINUTES=$(awk -v t="$GLO_TILES_RAW" -v r="$RATE" -v m="$MERGE" -v w="$WHOLE" \
  'BEGIN {printf "%.0f", t / r * m / w / 60}')
GLO_OUTPUT_TB=$(awk -v t="$GLO_TILES_RAW" -v b="$PACK_BYTES" -v n="$TILES" 'BEGIN {printf "%.2f", t * b / n / 1e12}')
TOTAL=$(awk -v a="$SHARDS_TOTAL" -v b="$MERGE" 'BEGIN {printf "%.3f", a + b}')
cat >docs/performance/sharded-tiling.md <<DOC
# Sharded tiling: shards + merge against one machine

\`tools/bench_shards/bench_shards.sh $BUILD $SHARDS $REPS\` on $(nproc) cores ($CPU), $(date -u +%Y-%m-%d).
Inputs: four real 3″ SRTM tiles in tests/data/dem (Fuji, N50E008, N50E009, N57E011): one
resolution in 1° tiles, as Copernicus GLO-30 is laid out; default options (17×17 blocks, 64×64
tiles a pack, shard level three above the deepest). Every process on one thread (\`-j 1\`); CPU
time is user + system from \`/usr/bin/time\`; medians of $REPS repetitions in this one run, each
sharded pyramid checked byte-identical to the one-machine pyramid (\`diff -r\`).

| run | CPU s (median) | against one machine |
|---|---|---|
| one machine: \`globe-tiler -o OUT\` | $WHOLE | 1.00 |
| $SHARDS shards, all together | $SHARDS_TOTAL | $(ratio "$SHARDS_TOTAL" "$WHOLE") |
| the slowest shard (the wall time with $SHARDS machines) | $SLOWEST | $(ratio "$SLOWEST" "$WHOLE") |
| merge | $MERGE | $(percent "$MERGE" "$WHOLE") % |
| **shards + merge** | **$TOTAL** | **$(ratio "$TOTAL" "$WHOLE")** |

Peak memory: one machine $((WHOLE_KIB / 1024)) MiB, the largest shard $((SHARD_KIB / 1024)) MiB,
the merge $((MERGE_KIB / 1024)) MiB.

Tiling rate of one process on one core: $TILES tiles in $WHOLE s, $(awk -v t="$TILES" -v s="$WHOLE" 'BEGIN {printf "%.0f", t / s}') tiles/s (with the conditioning);
output $(awk -v b="$PACK_BYTES" -v t="$TILES" 'BEGIN {printf "%.2f", b / t / 1024}') KiB a tile in packs.

What a shard does beyond its share: it opens every input's header to plan (all shards make the
same plan), conditions whole every source its units and their apron reach (a source across a
shard border is conditioned by each shard it crosses), and reads the heights of the coarser tiles
that fall inside its units for the merge. The merge reads the shard-level packs and builds the
levels above them.

## Copernicus GLO-30 on paper, from these measurements

GLO-30 is about 26,000 sources of 1°×1° at 1″ (30 m; 3600×3600 samples up to 50° of latitude,
fewer columns nearer the poles). 1″ makes level 16 the deepest (vertex spacing 0.62″ with 17×17
blocks), so one source holds (2^16/180)² = $GLO_TILES_PER_SOURCE tiles of level 16 and the pyramid, with
the levels above (a third more), about $GLO_TILES tiles. The shard level is 13: a unit is a
pack of 64×64 level-13 tiles, 1.41° square; the world's land (about 26,000 square degrees of
sources) makes at least $GLO_UNITS units.

| | from | GLO-30 |
|---|---|---|
| CPU | $GLO_TILES tiles at $RATE tiles/s a core (measured above, conditioning included) | $GLO_CORE_HOURS core-hours |
| shards | 1,000 (about $GLO_UNITS_PER_SHARD units each) | $GLO_SHARD_MINUTES min each on one core, plus the shards' overhead ($(ratio "$SHARDS_TOTAL" "$WHOLE")× here) |
| merge | 1/192 of the tiles, plus reading the level-13 packs | $GLO_MERGE_MINUTES min on one core (measured ratio $(percent "$MERGE" "$WHOLE") % × the whole) |
| output | $(awk -v b="$PACK_BYTES" -v t="$TILES" 'BEGIN {printf "%.2f", b / t / 1024}') KiB a tile (measured above) | $GLO_OUTPUT_TB TB |

The plan (\`globe-tiler plan --shards $SHARDS\`):

\`\`\`
$PLAN
\`\`\`
DOC
echo "wrote docs/performance/sharded-tiling.md: shards + merge $(ratio "$TOTAL" "$WHOLE")x, merge $(percent "$MERGE" "$WHOLE") %"
