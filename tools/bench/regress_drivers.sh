#!/usr/bin/env bash
# What moves in globe regress's figures when only the GL driver changes: the 40 views of
# tools/bench/regress_bench_suite.py, references drawn by the default driver (llvmpipe, one thread
# per core), then the same suite judged as drawn by llvmpipe again, llvmpipe on one thread,
# softpipe (Mesa's other software rasteriser), and, given MESA_LIB_DIR (another Mesa's libOSMesa,
# e.g. unpacked from a newer Debian package), that Mesa. Per driver: the views failing the default
# tolerance, the largest share of pixels over 16/255, the largest channel difference, the lowest
# mean and lowest window SSIM. Writes docs/performance/regress-drivers.md.
#
#   tools/bench/regress_drivers.sh BUILD_DIR [MESA_LIB_DIR [NAME]]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:?build directory}
MESA_DIR=${2:-}
MESA_NAME=${3:-another Mesa}
cmake --build "$BUILD" -j"$(nproc)" --target globe globe-tiler >/dev/null
GLOBE=$(realpath "$BUILD/apps/globe/globe")
WORK=$(mktemp -d /tmp/globe-regress-drivers.XXXXXX)
trap 'rm -rf "$WORK"' EXIT  # KEEP=DIR copies each driver's report.json there first
bash tools/bench/tile_bundled.sh "$BUILD/apps/globe-tiler/globe-tiler" "$WORK"
python3 tools/bench/regress_bench_suite.py "$WORK/suite.json"
"$GLOBE" regress "$WORK/suite.json" --out "$WORK/references" --update >/dev/null

# One row: the driver's name, then `env` assignments for the run.
row() {
  local name=$1 started=$EPOCHREALTIME
  shift
  env "$@" "$GLOBE" regress "$WORK/suite.json" --out "$WORK/out" >/dev/null 2>&1 || true
  if [ -n "${KEEP:-}" ]; then mkdir -p "$KEEP/$name" && cp -r "$WORK/out/." "$WORK/references/." "$KEEP/$name/"; fi
  python3 - "$WORK/out/report.json" "$name" "$started" "$EPOCHREALTIME" <<'PY'
import json, sys
views = json.load(open(sys.argv[1]))["views"]
judged = [v for v in views if v["differingFraction"] is not None]
fail = sum(v["status"] == "fail" for v in views)
err = sum(v["status"] == "error" for v in views)
def worst(key, pick):  # the figure and, where any view differs at all, the view it is of
    v = pick(judged, key=lambda v: v[key])
    return v[key], v["name"] if v["differingFraction"] > 0 or v["ssim"] < 1 else "all"
fraction, fraction_view = worst("differingFraction", max)
largest, largest_view = worst("largestChannelDifference", max)
ssim, ssim_view = worst("ssim", min)
window, window_view = worst("lowestWindowSsim", min)
print(f"| {sys.argv[2]} | {float(sys.argv[4]) - float(sys.argv[3]):.1f} | {fail} | {err} | "
      f"{100 * fraction:.3f} ({fraction_view}) | {largest} ({largest_view}) | "
      f"{ssim:.4f} ({ssim_view}) | {window:.4f} ({window_view}) |")
PY
}
OUT_MD=${OUT_MD:-docs/performance/regress-drivers.md}
{
  echo "# globe regress: what moves when only the driver changes"
  echo
  echo "The 40 views of \`tools/bench/regress_bench_suite.py\` (the bundled data at 480x270),"
  echo "references drawn by the default driver, judged with the default tolerance (16/255 per"
  echo "channel on at most 0.1 % of pixels, SSIM at least 0.99) as each driver draws them. One run"
  echo "of \`tools/bench/regress_drivers.sh\` ($(date -u +%Y-%m-%d), $(nproc) cores,"
  echo "$(git describe --always --dirty), Mesa $(dpkg-query -W -f '${Version}' libosmesa6 2>/dev/null || echo '?'))."
  echo
  echo "| driver | s | views failed | errors | most pixels over 16/255, % (view) | largest channel difference | lowest SSIM | lowest window SSIM |"
  echo "|---|---|---|---|---|---|---|---|"
  row "llvmpipe again (the references' driver)"
  row "llvmpipe, one thread" LP_NUM_THREADS=1
  row "softpipe" GALLIUM_DRIVER=softpipe
  if [ -n "$MESA_DIR" ]; then row "$MESA_NAME" LD_LIBRARY_PATH="$MESA_DIR"; fi
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
