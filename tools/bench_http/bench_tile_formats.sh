#!/usr/bin/env bash
# The same terrain as three tile formats over HTTP, measured in one run and written to
# docs/performance/tile-formats.md: the pack pyramid the tiler makes from the bundled DEMs, and
# that pyramid exported (globe-tiler export) as a quantized-mesh tree and a Terrarium PNG tree
# (the world to level 6 / zoom 3, the Fuji DEM's square to its finest). Each is served by nginx
# behind a proxy adding a 50 ms round trip (globe-delay-proxy) and drawn by `globe snapshot` of
# the same camera: cold (an empty disk cache) and warm (the same cache again): requests, bytes and
# whole-process seconds. nginx and the proxy listen on 127.0.0.1 only and stop by themselves.
#
#   tools/bench_http/bench_tile_formats.sh BUILD_DIR [RTT_MS] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:?build directory}
cmake --build "$BUILD" -j"$(nproc)" --target globe-delay-proxy >/dev/null  # tools/run-tests.sh builds only the tests
RTT=${2:-50}
RUNS=${3:-3}
GLOBE=$BUILD/apps/globe/globe
TILER=$BUILD/apps/globe-tiler/globe-tiler
PROXY=$BUILD/tools/bench_http/globe-delay-proxy
OUT=docs/performance/tile-formats.md
WORK=$(mktemp -d /tmp/globe-bench-formats.XXXXXX)
cleanup() {
  kill "${NGINX_PID:-}" "${PROXY_PID:-}" 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
NGINX_PORT=$(free_port)
PROXY_PORT=$(free_port)

FUJI=138,35,139.5,36
"$TILER" -q -o "$WORK/www/pyramid" data/dem/ETOPO20.DEM data/dem/W002N52.DEM \
  data/dem/E138N35_FUJI.DEM data/dem/zion-srtm3.tif
export_log() { "$TILER" export "$@" | sed "s|$WORK/||; s/^/    /" >> "$WORK/export.log"; }
export_log --format quantized-mesh -o "$WORK/www/qm" --levels 0-4 "$WORK/www/pyramid"
export_log --format quantized-mesh -o "$WORK/www/qm" --levels 5-12 --bounds $FUJI "$WORK/www/pyramid"
export_log --format terrarium -o "$WORK/www/terrarium" --levels 0-3 "$WORK/www/pyramid"
export_log --format terrarium -o "$WORK/www/terrarium" --levels 4-11 --bounds $FUJI "$WORK/www/pyramid"

mkdir -p "$WORK/nginx/tmp"
cat > "$WORK/nginx/nginx.conf" <<CONF
daemon off; master_process off; worker_processes 1;
pid $WORK/nginx/nginx.pid; error_log $WORK/nginx/error.log warn;
events { worker_connections 512; }
http {
  log_format bench '\$request_method \$uri \$status "\$http_range" \$bytes_sent';
  access_log $WORK/nginx/access.log bench;
  client_body_temp_path $WORK/nginx/tmp/b; proxy_temp_path $WORK/nginx/tmp/p;
  fastcgi_temp_path $WORK/nginx/tmp/f; uwsgi_temp_path $WORK/nginx/tmp/u; scgi_temp_path $WORK/nginx/tmp/s;
  types { application/json json; image/png png; } default_type application/octet-stream;
  keepalive_requests 100000;
  server {
    listen 127.0.0.1:$NGINX_PORT; root $WORK/www;
    # Cesium terrain as ctb and CesiumJS's servers publish it: gzip stored, said so.
    location /qm/ { location ~ \.terrain\$ { add_header Content-Encoding gzip; } }
  }
}
CONF
timeout 1800 /usr/sbin/nginx -p "$WORK/nginx" -c "$WORK/nginx/nginx.conf" -e "$WORK/nginx/error.log" &
NGINX_PID=$!
timeout 1800 "$PROXY" "$PROXY_PORT" "$NGINX_PORT" "$RTT" 1800 &
PROXY_PID=$!
sleep 0.5

FAR=http://127.0.0.1:$PROXY_PORT
SOURCES=("pack pyramid=$FAR/pyramid"
         "quantized-mesh=quantized-mesh:$FAR/qm/layer.json"
         "Terrarium PNG=terrarium:$FAR/terrarium/{z}/{x}/{y}.png?maxzoom=11")
CAMERA=138.60,35.20,6000,30,-15,0
median() { python3 -c 'import sys,statistics; print(f"{statistics.median(map(float,sys.argv[1:])):.2f}")' "$@"; }
log_lines() { wc -l < "$WORK/nginx/access.log"; }
log_stats() {  # requests and bytes sent since line $1 of the access log
  tail -n +"$(($1 + 1))" "$WORK/nginx/access.log" | awk '{n++; b+=$NF} END {printf "%d %d\n", n, b}'
}
timed() {  # wall seconds of a command; its stdout to $WORK/last.out
  local start end
  start=$(date +%s.%N)
  "$@" > "$WORK/last.out"
  end=$(date +%s.%N)
  python3 -c "print(f'{$end - $start:.3f}')"
}

ROWS=""
for entry in "${SOURCES[@]}"; do
  name=${entry%%=*}
  source=${entry#*=}
  snap() { "$GLOBE" snapshot "$source" --camera "$CAMERA" --size 1280x720 --no-attribution \
             -o "$WORK/$(echo "$name" | tr ' ' _).png" --cache-dir "$WORK/cache"; }
  cold=() warm=()
  for run in $(seq "$RUNS"); do
    rm -rf "$WORK/cache"
    before=$(log_lines)
    cold+=("$(timed snap)")
    read -r coldRequests coldBytes <<< "$(log_stats "$before")"
    drawn=$(grep -o '[0-9]* tiles drawn, [0-9]* triangles' "$WORK/last.out")
    before=$(log_lines)
    warm+=("$(timed snap)")
    read -r warmRequests _ <<< "$(log_stats "$before")"
  done
  ROWS+="| $name | $coldRequests | $((coldBytes / 1024)) | $(median "${cold[@]}") | $warmRequests | $(median "${warm[@]}") | $drawn |
"
done

COMMIT=$(git rev-parse --short HEAD)
DIRTY=$(git diff --quiet HEAD -- src tools apps && echo "" || echo " with uncommitted changes")
CPU=$(grep -m1 "model name" /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
cat > "$OUT.tmp" <<DOC
# The same terrain as three tile formats

Generated by \`tools/bench_http/bench_tile_formats.sh $BUILD $RTT $RUNS\` on commit $COMMIT$DIRTY,
$(nproc) cores ($CPU), $(date -u +%Y-%m-%d). Medians of $RUNS runs, whole-process wall seconds of
\`globe snapshot --size 1280x720\` of the oblique Fuji view (camera $CAMERA), each format served
by nginx on 127.0.0.1 through globe-delay-proxy adding a ${RTT} ms round trip.

The three hold the same terrain: the pack pyramid \`globe-tiler\` makes from the bundled DEMs
(the world from ETOPO20, Fuji's 1° square at 3″), and that pyramid exported by
\`globe-tiler export\`:

$(cat "$WORK/export.log")

| format | cold requests | cold KiB | cold s | warm requests | warm s | drawn |
|---|---|---|---|---|---|---|
$ROWS
* **pack pyramid**: the manifest, each pack's header and index by one range request, then the
  blocks, neighbours (a tile's children, stored together) by one range request.
* **quantized-mesh**: \`layer.json\`, then one GET per tile (gzip, 17×17 grid TINs); globe samples
  each onto a 65-vertex block, so it draws more triangles for the same surface.
* **Terrarium PNG**: one GET per 256×256 Web-Mercator tile, resampled into geographic blocks as
  it loads; zooms 4–11 exist only over Fuji's square (404 elsewhere: the parent is drawn).
* **warm**: the same disk cache again. The pack pyramid revalidates its manifest (one 304) and
  trusts its cached packs; the quantized-mesh tree revalidates \`layer.json\`, and its tiles'
  URLs carry the tree's version (\`{version}\`), so cached tiles are used without asking; an XYZ
  template names no version, so each Terrarium tile is revalidated (a 304 each).
DOC
mv "$OUT.tmp" "$OUT"
cat "$OUT"
