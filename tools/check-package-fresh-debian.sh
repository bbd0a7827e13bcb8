#!/usr/bin/env bash
# Installs the Debian package on a fresh Debian 12 (a minimal bookworm root made with debootstrap
# in a temporary directory, nothing else in it) with apt, which must find every runtime
# dependency the package declares; then tiles the bundled Fuji data and renders a headless
# snapshot there with the installed programs, and compares it byte for byte with the build tree's
# own. Needs root and Debian's package mirror (not run by CI: it downloads the packages). Writes the
# times to docs/performance/package-fresh-debian.md.
#
#   sudo tools/check-package-fresh-debian.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:?build directory (built, with globe and globe-tiler)}
OUT_MD=${OUT_MD:-$PWD/docs/performance/package-fresh-debian.md}
START_ALL=$(date +%s)
# shellcheck source=SCRIPTDIR/fresh-debian-root.sh
source tools/fresh-debian-root.sh
bash tools/check-package.sh "$BUILD" >/dev/null
DEB=$(ls "$BUILD"/package/globe_*.deb)
makeFreshDebian globe-fresh-debian
mkdir -p "$ROOT/tmp/data"
cp "$DEB" "$ROOT/tmp/"
cp data/dem/ETOPO20.DEM data/dem/ETOPO20.HDR data/dem/E138N35_FUJI.DEM data/dem/E138N35_FUJI.HDR \
  "$ROOT/tmp/data/"
echo "== apt-get install ./$(basename "$DEB") (its declared dependencies from the mirror)"
START=$(date +%s)
if ! chroot "$ROOT" bash -c "apt-get update -q && DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -q /tmp/$(basename "$DEB")" >"$ROOT/tmp/apt.log" 2>&1; then
  cat "$ROOT/tmp/apt.log" >&2
  exit 1
fi
INSTALL_SECONDS=$(($(date +%s) - START))
echo "installed in $INSTALL_SECONDS s"
chroot "$ROOT" globe --version
# shellcheck disable=SC2054  # the commas are inside one argument
VIEW=(--camera 138.60,35.20,6000,30,-15,0 --size 640x360)
chroot "$ROOT" bash -c "cd /tmp && globe-tiler -q -o pyramid data/ETOPO20.DEM data/E138N35_FUJI.DEM \
  >/dev/null && globe snapshot pyramid ${VIEW[*]} -o fresh.png >/dev/null"
HOST=$(mktemp -d)
"$BUILD/apps/globe-tiler/globe-tiler" -q -o "$HOST/pyramid" "$ROOT/tmp/data/ETOPO20.DEM" \
  "$ROOT/tmp/data/E138N35_FUJI.DEM" >/dev/null
"$BUILD/apps/globe/globe" snapshot "$HOST/pyramid" "${VIEW[@]}" -o "$HOST/build.png" >/dev/null
if cmp -s "$HOST/build.png" "$ROOT/tmp/fresh.png"; then
  echo "the installed package renders the same image as the build tree (byte for byte)"
  rm -rf "$HOST"
  {
    echo "# The Debian package on a fresh Debian 12"
    echo
    echo "\`tools/check-package-fresh-debian.sh\` on $(date -u +%Y-%m-%d), commit"
    echo "$(git rev-parse --short HEAD), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores:"
    echo "a minimal bookworm root (\`debootstrap --variant=minbase\`), \`apt-get install\` of"
    echo "$(basename "$DEB") with the dependencies it declares from $MIRROR, then the bundled"
    echo "Fuji data tiled and rendered with the installed programs."
    echo
    echo "| step | s |"
    echo "|---|---|"
    echo "| apt-get update + install of the package and its dependencies | $INSTALL_SECONDS |"
    echo "| the whole check (debootstrap, install, tile, render, compare) | $(($(date +%s) - START_ALL)) |"
    echo
    echo "- image: byte-identical to the build tree's"
    echo "- apt's package cache afterwards: $(du -sm "$ROOT/var/cache/apt/archives" | cut -f1) MB"
  } >"$OUT_MD.tmp"
  mv "$OUT_MD.tmp" "$OUT_MD"
else
  echo "the installed package's image differs from the build tree's: $HOST/build.png" >&2
  cp "$ROOT/tmp/fresh.png" "$HOST/fresh.png"
  exit 1
fi
