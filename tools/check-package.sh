#!/usr/bin/env bash
# Builds the Debian package from a built build directory (cpack -G DEB) and checks what it holds:
# the two programs and their man pages, and the runtime dependencies dpkg-shlibdeps found.
#
#   tools/check-package.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:?build directory}
OUT="$BUILD/package"
rm -rf "$OUT"
(cd "$BUILD" && cpack -G DEB -B "$PWD/package" >/dev/null)
DEB=$(ls "$OUT"/globe_*.deb)
echo "$DEB"
dpkg-deb -c "$DEB" | awk '{print $6}' | tee "$OUT/contents.txt"
for path in ./usr/bin/globe ./usr/bin/globe-tiler ./usr/share/man/man1/globe.1.gz; do
  grep -qx "$path" "$OUT/contents.txt" || { echo "missing from the package: $path" >&2; exit 1; }
done
DEPENDS=$(dpkg-deb -f "$DEB" Depends)
echo "Depends: $DEPENDS"
for library in libosmesa6 libglfw3 libgdal32; do
  case "$DEPENDS" in *"$library"*) ;; *) echo "Depends lacks $library" >&2; exit 1 ;; esac
done
