#!/usr/bin/env bash
# `cmake --install` into a temporary prefix gives a globe that runs with nothing from the checkout
# (and bash completion for both programs):
# with the source tree's shaders/ hidden (an empty tmpfs mounted over it in a private mount
# namespace) the installed program renders the same image, byte for byte, as the build tree's.
#
#   test_install.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
SOURCE=${1:?source directory}
BUILD=${2:?build directory}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cmake --install "$BUILD" --prefix "$WORK/prefix" >"$WORK/install.log"
for f in bin/globe bin/globe-tiler share/man/man1/globe.1.gz share/man/man1/globe-tiler.1.gz \
  share/globe/places.tsv.gz share/globe/places-SOURCES.md; do
  [ -e "$WORK/prefix/$f" ] || { echo "not installed: $f" >&2; cat "$WORK/install.log" >&2; exit 1; }
done
"$WORK/prefix/bin/globe" --version | grep -q '^globe [0-9]' || { echo "globe --version" >&2; exit 1; }
"$WORK/prefix/bin/globe-tiler" --version | grep -q '^globe-tiler [0-9]'

# Bash completion, installed under both names, completes from the installed programs' --help.
COMPLETIONS="$WORK/prefix/share/bash-completion/completions"
[ -e "$COMPLETIONS/globe" ] && [ -e "$COMPLETIONS/globe-tiler" ] ||
  { echo "bash completion not installed" >&2; exit 1; }
complete_line() {  # words of a command line being typed -> what TAB offers
  PATH="$WORK/prefix/bin:$PATH" bash -c 'source "$1"; shift; COMP_WORDS=("$@");
    COMP_CWORD=$(($# - 1)); _globe_complete "$1"; echo "${COMPREPLY[*]}"' _ \
    "$COMPLETIONS/globe" "$@"
}
for check in "globe sn=snapshot" "globe snapshot --cam=--camera" "globe snapshot --off=--offline" "globe view --lay=--layer" \
  "globe-tiler imagery --sc=--scale" "globe --=--help --version" \
  "globe-tiler --z=--z-scale --z-units" "globe-tiler imagery --ba=--bands" \
  "globe su=sun" "globe re=regress" "globe-tiler wa=water-mask" "globe-tiler me=merge" \
  "globe-tiler export-i=export-imagery"; do
  words=${check%%=*} wanted=${check#*=}
  # shellcheck disable=SC2086
  got=$(complete_line $words)
  [ "$got" = "$wanted" ] || { echo "completing '$words': '$got', wanted '$wanted'" >&2; exit 1; }
done
# The help's footers list rules as "  - ..." lines: no bare "-" is offered.
for program in globe-tiler "globe-tiler imagery"; do
  # shellcheck disable=SC2086
  got=$(complete_line $program -)
  case " $got " in *" - "*) echo "completing '$program -' offers a bare '-': '$got'" >&2; exit 1 ;; esac
done

# A small real pyramid: the whole globe at 20' and Mount Fuji's SRTM tile.
"$WORK/prefix/bin/globe-tiler" -q -o "$WORK/pyramid" "$SOURCE/data/dem/ETOPO20.DEM" \
  "$SOURCE/data/dem/E138N35_FUJI.DEM"
VIEW=(--camera 138.60,35.20,6000,30,-15,0 --size 320x180)
"$BUILD/apps/globe/globe" snapshot "$WORK/pyramid" "${VIEW[@]}" -o "$WORK/build-tree.png" >/dev/null

if ! unshare -m true 2>/dev/null; then
  echo "SKIP: cannot make a private mount namespace here (unshare -m needs root)" >&2
  exit 77
fi
cp "$WORK/prefix/bin/globe" "$WORK/globe-copy"  # a copied binary works too
unshare -m bash -c "
  set -e
  mount -t tmpfs none '$SOURCE/shaders'
  test -z \"\$(ls -A '$SOURCE/shaders')\"
  cd /
  env -u GLOBE_SHADER_DIR '$WORK/globe-copy' snapshot '$WORK/pyramid' ${VIEW[*]} \
    -o '$WORK/installed.png' >/dev/null
  # The installed gazetteer, with the checkout's hidden too.
  mount -t tmpfs none '$SOURCE/data/places'
  env -u GLOBE_PLACES '$WORK/prefix/bin/globe' search Fuji --limit 1 > '$WORK/search.csv'
"
grep -q '^"Mount Fuji, JP",' "$WORK/search.csv" ||
  { echo "installed globe search: $(cat "$WORK/search.csv")" >&2; exit 1; }
cmp "$WORK/build-tree.png" "$WORK/installed.png"
echo "installed globe renders byte-identical images with the checkout's shaders hidden, and searches its installed gazetteer"
