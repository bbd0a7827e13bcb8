#!/usr/bin/env bash
# Renders docs/viewer.md's picture of the physically based sky (docs/images/sky-physical.png)
# from what tools/setup.sh made (pyramid/): from 2 km east of Mount Fuji looking west at 10:00
# and 18:50 JST on the June solstice (the Sun setting behind the ridges), and from 20 km up at
# 19:15 JST (dusk, the Earth's shadow rising in the east); labelled. Run from the checkout's root
# after setup.
set -euo pipefail
cd "$(dirname "$0")/../.."
GLOBE=${GLOBE:-./build/apps/globe/globe}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
n=0
for shot in "10:00 138.80,35.25,2000,290,5,0 west, 2 km" "18:50 138.80,35.25,2000,290,5,0 west, 2 km" \
  "19:15 138.80,35.25,20000,110,-5,0 east, 20 km" "19:15 138.80,35.25,20000,290,-5,0 west, 20 km"; do
  set -- $shot
  n=$((n + 1))
  "$GLOBE" snapshot pyramid --size 640x360 --camera "$2" --time "2024-06-21T$1+09:00" \
    -o "$TMP/$n.png"
  convert "$TMP/$n.png" -fill white -undercolor '#00000080' -pointsize 18 -gravity northwest \
    -font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf -annotate +8+8 "$1 JST, $3 $4 $5" "$TMP/$n.png"
done
montage -mode concatenate -tile 2x "$TMP"/1.png "$TMP"/2.png "$TMP"/3.png "$TMP"/4.png \
  docs/images/sky-physical.png
echo "wrote docs/images/sky-physical.png"
