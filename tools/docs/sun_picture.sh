#!/usr/bin/env bash
# Renders docs/viewer.md's picture of the Sun at four times (docs/images/sun-times.png) from what
# tools/setup.sh made (pyramid/): Fuji from the south-east at 06:00, 12:00, 17:30 and 19:15 JST on
# the June solstice (--time), and the globe at 12:00 UTC; put together and labelled. Run from the
# checkout's root after setup.
set -euo pipefail
cd "$(dirname "$0")/../.."
GLOBE=${GLOBE:-./build/apps/globe/globe}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
n=0
for time in 06:00 12:00 17:30 19:15; do
  n=$((n + 1))
  "$GLOBE" snapshot pyramid --size 640x360 --camera 138.95,35.10,26000,315,-30,0 \
    --time "2024-06-21T$time+09:00" -o "$TMP/$n.png"
  convert "$TMP/$n.png" -fill white -undercolor '#00000080' -pointsize 20 -gravity northwest \
    -font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf -annotate +8+8 "$time JST" "$TMP/$n.png"
done
montage -mode concatenate -tile 2x "$TMP"/1.png "$TMP"/2.png "$TMP"/3.png "$TMP"/4.png \
  docs/images/sun-times.png
"$GLOBE" snapshot pyramid --size 480x480 --camera 60,20,20000000,0,-90,0 \
  --time 2024-06-21T12:00Z -o docs/images/sun-globe.png
echo "wrote docs/images/sun-times.png and docs/images/sun-globe.png"
