#!/usr/bin/env bash
# Times the README's first command on a truly new machine: a minimal Debian 12 made by
# `debootstrap --variant=minbase bookworm` in a temporary directory (nothing installed beyond the
# base), a fresh clone of HEAD in it, then `bash tools/setup.sh` as root inside it under
# /usr/bin/time: apt-get update, the download and install of every package, the build, tiling,
# rendering and the demo flight. Needs root and Debian's package mirror (not run by CI: it
# downloads ~420 MB of packages). Writes docs/performance/first-run-fresh-debian.md.
#
#   sudo tools/bench/first_run_fresh_debian.sh
set -euo pipefail
REPO=$(cd "$(dirname "$0")/../.." && pwd)
OUT_MD=${OUT_MD:-$REPO/docs/performance/first-run-fresh-debian.md}
COMMIT=$(git -C "$REPO" rev-parse --short HEAD)
# shellcheck source=SCRIPTDIR/../fresh-debian-root.sh
source "$REPO/tools/fresh-debian-root.sh"
makeFreshDebian globe-first-run
# A clone as a user makes it (git is not in the minimal system; the clone is not timed).
git clone -q "$REPO" "$ROOT/root/globe"
echo "== bash tools/setup.sh inside it (timed)"
if ! /usr/bin/time -f %e -o "$ROOT/setup.time" chroot "$ROOT" bash -c \
  "cd /root/globe && bash tools/setup.sh" >"$ROOT/setup.log" 2>&1; then
  tail -40 "$ROOT/setup.log" >&2
  echo "tools/setup.sh failed on the fresh system" >&2
  exit 1
fi
seconds=$(tail -1 "$ROOT/setup.time")
# apt's own record of its two runs (update, then install), start to end.
aptSeconds=$(awk '/^Start-Date:/ {s = $2 " " $3} /^End-Date:/ && s {cmd = "date -d \"" s "\" +%s"; cmd | getline a; close(cmd); cmd = "date -d \"" $2 " " $3 "\" +%s"; cmd | getline b; close(cmd); total += b - a; s = ""} END {print total + 0}' "$ROOT/var/log/apt/history.log")
packages=$(chroot "$ROOT" dpkg-query -f '.\n' -W | wc -l)
downloaded=$(du -sm "$ROOT/var/cache/apt/archives" | cut -f1)
for made in out/globe.png out/zion.png out/play/summary.txt out/play/zion.mp4; do
  [ -s "$ROOT/root/globe/$made" ] || { echo "setup.sh finished without $made" >&2; exit 1; }
done
{
  echo "# The first command on a new Debian 12, timed"
  echo
  echo "A minimal Debian 12 (\`debootstrap --variant=minbase bookworm\`, nothing beyond the base),"
  echo "a fresh clone of $COMMIT in it, and \`bash tools/setup.sh\` run as root inside it under"
  echo "\`/usr/bin/time\`: from the first \`apt-get update\` to the demo flight's frames, packages"
  echo "downloaded from $MIRROR. On $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"
  echo "$(nproc) cores. Made by \`tools/bench/first_run_fresh_debian.sh\` on $(date -u +%Y-%m-%d)."
  echo
  echo "| command | wall s | wall | of which apt-get (its own log), s | packages installed | apt's package cache afterwards, MB |"
  echo "|---|---|---|---|---|---|"
  echo "| \`bash tools/setup.sh\` | $seconds | $(awk -v s="$seconds" 'BEGIN {printf "%d min %02d s", s / 60, s % 60}') | $aptSeconds | $packages | $downloaded |"
  echo
  echo "- goal (issue 16): at most 6 min on a fresh 2-core machine, apt-get included"
} >"$OUT_MD.tmp"
mv "$OUT_MD.tmp" "$OUT_MD"
cat "$OUT_MD"
