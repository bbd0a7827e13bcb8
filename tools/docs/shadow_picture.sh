#!/usr/bin/env bash
# Renders docs/viewer.md's pictures of shadows and anti-aliasing from what tools/setup.sh made
# (pyramid/, layers/): Zion Canyon straight down from 12 km at 19:30 MDT on the June solstice
# without and with shadows (docs/images/shadows-zion.png), and a ridge line over Zion against the
# sky with 1 and 4 samples a pixel, enlarged 3× (docs/images/samples.png). Run from the
# checkout's root after setup.
set -euo pipefail
cd "$(dirname "$0")/../.."
GLOBE=${GLOBE:-./build/apps/globe/globe}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
label() {
  convert "$1" -fill white -undercolor '#00000080' -pointsize 18 -gravity northwest \
    -font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf -annotate +8+8 "$2" "$1"
}
for shadows in "--no-shadows" ""; do
  name=${shadows:-shadows}
  "$GLOBE" snapshot pyramid --size 480x480 --camera -112.95,37.25,12000,0,-90,0 \
    --time 2024-06-21T19:30-06:00 $shadows -o "$TMP/$name.png"
  label "$TMP/$name.png" "$([ -n "$shadows" ] && echo "no shadows" || echo shadows)"
done
montage -mode concatenate -tile 2x "$TMP/--no-shadows.png" "$TMP/shadows.png" \
  docs/images/shadows-zion.png
for samples in 1 4; do
  "$GLOBE" snapshot pyramid --size 1280x720 --camera -112.93,37.16,4500,330,-20,0 \
    --layer layers/zion --samples "$samples" -o "$TMP/s$samples.png"
  convert "$TMP/s$samples.png" -crop 320x180+700+150 +repage -filter point -resize 300% "$TMP/s$samples.png"
  label "$TMP/s$samples.png" "$samples sample$([ "$samples" = 1 ] || echo s) a pixel"
done
montage -mode concatenate -tile 2x "$TMP/s1.png" "$TMP/s4.png" docs/images/samples.png
echo "wrote docs/images/shadows-zion.png and docs/images/samples.png"
