#!/usr/bin/env bash
# Streaming over HTTP, measured in one run and written to docs/performance/http-streaming.md:
#   * cold: `globe snapshot` of a view from a pyramid served by nginx behind a proxy that adds a
#     50 ms round trip (globe-delay-proxy), with an empty disk cache: requests, bytes, seconds;
#   * the same blocks as one file per tile (the z/x/y layout) fetched by curl over the same proxy
#     with as many transfers at once: the transport's floor without a pack index (curl is told the
#     exact list up front, which no viewer knows; a z/x/y viewer would also learn which tiles
#     exist by asking for them);
#   * warm: the same snapshot again from the disk cache (one revalidation of the manifest), over
#     the 50 ms proxy and straight to nginx, against the local directory.
# nginx and the proxy listen on 127.0.0.1 only and stop by themselves (timeout) if this dies.
#
#   tools/bench_http/bench_http.sh BUILD_DIR [RTT_MS] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:?build directory}
cmake --build "$BUILD" -j"$(nproc)" --target globe-delay-proxy >/dev/null  # tools/run-tests.sh builds only the tests
RTT=${2:-50}
RUNS=${3:-3}
GLOBE=$BUILD/apps/globe/globe
TILER=$BUILD/apps/globe-tiler/globe-tiler
PROXY=$BUILD/tools/bench_http/globe-delay-proxy
OUT=docs/performance/http-streaming.md
WORK=$(mktemp -d /tmp/globe-bench-http.XXXXXX)
cleanup() {
  kill "${NGINX_PID:-}" "${PROXY_PID:-}" 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
NGINX_PORT=$(free_port)
PROXY_PORT=$(free_port)

"$TILER" -q -o "$WORK/www/pyramid" data/dem/ETOPO20.DEM data/dem/W002N52.DEM \
  data/dem/E138N35_FUJI.DEM data/dem/zion-srtm3.tif
ln -s pyramid "$WORK/www/fresh"
mkdir -p "$WORK/nginx/tmp"
cat > "$WORK/nginx/nginx.conf" <<EOF
daemon off; master_process off; worker_processes 1;
pid $WORK/nginx/nginx.pid; error_log $WORK/nginx/error.log warn;
events { worker_connections 512; }
http {
  log_format bench '\$request_method \$uri \$status "\$http_range" \$bytes_sent';
  access_log $WORK/nginx/access.log bench;
  client_body_temp_path $WORK/nginx/tmp/b; proxy_temp_path $WORK/nginx/tmp/p;
  fastcgi_temp_path $WORK/nginx/tmp/f; uwsgi_temp_path $WORK/nginx/tmp/u; scgi_temp_path $WORK/nginx/tmp/s;
  types { application/json json; } default_type application/octet-stream;
  keepalive_requests 100000;
  server {
    listen 127.0.0.1:$NGINX_PORT; root $WORK/www;
    # The same pyramid, its manifest fresh for 5 minutes (Cache-Control: max-age=300).
    location = /fresh/manifest.json { expires 5m; }
  }
}
EOF
timeout 1800 /usr/sbin/nginx -p "$WORK/nginx" -c "$WORK/nginx/nginx.conf" -e "$WORK/nginx/error.log" &
NGINX_PID=$!
timeout 1800 "$PROXY" "$PROXY_PORT" "$NGINX_PORT" "$RTT" 1800 &
PROXY_PID=$!
sleep 0.5

FAR=http://127.0.0.1:$PROXY_PORT
NEAR=http://127.0.0.1:$NGINX_PORT
# name = camera
VIEWS=("fuji_oblique=138.60,35.20,6000,30,-15,0" "zion_oblique=-112.93,37.16,4500,330,-20,0")

seconds() {  # wall seconds of a command
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  python3 -c "print(f'{$end - $start:.3f}')"
}
median() { python3 -c 'import sys,statistics; print(f"{statistics.median(map(float,sys.argv[1:])):.2f}")' "$@"; }
log_stats() {  # requests and bytes sent since line $1 of the access log
  tail -n +"$(($1 + 1))" "$WORK/nginx/access.log" | awk '{n++; b+=$NF} END {printf "%d %d\n", n, b}'
}
log_lines() { wc -l < "$WORK/nginx/access.log"; }

ROWS=""
for entry in "${VIEWS[@]}"; do
  name=${entry%%=*}
  camera=${entry#*=}
  snap() { "$GLOBE" snapshot "$1" --camera "$camera" --size 1280x720 -o "$WORK/$name.png" "${@:2}"; }
  cold=() warmFar=() warmNear=() warmFresh=() local_=()
  for run in $(seq "$RUNS"); do
    rm -rf "$WORK/cache"
    before=$(log_lines)
    start=$(date +%s.%N)
    snap "$FAR/pyramid" --cache-dir "$WORK/cache" > "$WORK/cold-$run.out"
    end=$(date +%s.%N)
    cold+=("$(python3 -c "print(f'{$end - $start:.3f}')")")
    loads=$(grep -o '[0-9]* tile loads' "$WORK/cold-$run.out" | cut -d' ' -f1)
    read -r coldRequests coldBytes <<< "$(log_stats "$before")"
    if [ "$run" = 1 ]; then
      # The blocks it fetched, as one file per tile, for the z/x/y comparison.
      tail -n +"$((before + 1))" "$WORK/nginx/access.log" > "$WORK/cold.log"
      coldLoads=$loads
    fi
    before=$(log_lines)
    warmFar+=("$(seconds snap "$FAR/pyramid" --cache-dir "$WORK/cache")")
    read -r warmRequests _ <<< "$(log_stats "$before")"
    # The cache is keyed by URL: the near URL's entries are filled once, untimed.
    snap "$NEAR/pyramid" --cache-dir "$WORK/cache" >/dev/null
    warmNear+=("$(seconds snap "$NEAR/pyramid" --cache-dir "$WORK/cache")")
    local_+=("$(seconds snap "$WORK/www/pyramid")")
  done
  rm -rf "$WORK/cache-fresh"
  snap "$FAR/fresh" --cache-dir "$WORK/cache-fresh" >/dev/null
  for run in $(seq "$RUNS"); do
    before=$(log_lines)
    warmFresh+=("$(seconds snap "$FAR/fresh" --cache-dir "$WORK/cache-fresh")")
    read -r freshRequests _ <<< "$(log_stats "$before")"
  done
  python3 tools/bench_http/zxy_from_log.py "$WORK/cold.log" "$WORK/www" "zxy-$name" \
    "$FAR" "$coldLoads" 2>/dev/null > "$WORK/curl-$name.cfg"
  zxy=()
  for run in $(seq "$RUNS"); do
    before=$(log_lines)
    zxy+=("$(seconds curl --parallel --parallel-max 24 --parallel-immediate -s -K "$WORK/curl-$name.cfg" 2>/dev/null)")
    read -r zxyRequests zxyBytes <<< "$(log_stats "$before")"
  done
  localMedian=$(median "${local_[@]}")
  ratio() { awk -v a="$1" -v b="$localMedian" 'BEGIN {printf "%.2f", (b > 0 ? a / b : 0)}'; }
  ROWS+="| $name | $coldRequests | $((coldBytes / 1024)) | $(median "${cold[@]}") | $zxyRequests | $((zxyBytes / 1024)) | $(median "${zxy[@]}") | $warmRequests | $(median "${warmFar[@]}") | $(median "${warmNear[@]}") | $freshRequests | $(median "${warmFresh[@]}") | $localMedian | $(ratio "$(median "${warmFar[@]}")") | $(ratio "$(median "${warmFresh[@]}")") |
"
done

COMMIT=$(git rev-parse --short HEAD)
DIRTY=$(git diff --quiet HEAD -- src tools && echo "" || echo " with uncommitted changes")
CPU=$(grep -m1 "model name" /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
cat > "$OUT.tmp" <<EOF
# Streaming over HTTP

Generated by \`tools/bench_http/bench_http.sh $BUILD $RTT $RUNS\` on commit $COMMIT$DIRTY,
$(nproc) cores ($CPU), $(date -u +%Y-%m-%d). Medians of $RUNS runs, whole-process wall seconds of
\`globe snapshot --size 1280x720\` (start, every load, render, PNG). nginx on 127.0.0.1; "far" is
through globe-delay-proxy adding a ${RTT} ms round trip (each chunk held ${RTT}/2 ms each way, and
one round trip per new connection).

| view | cold requests | cold KiB | cold s (far) | z/x/y requests | z/x/y KiB | z/x/y s (far, curl) | warm requests | warm s (far) | warm s (near) | warm requests, max-age | warm s (far, max-age) | local s | warm far / local | warm max-age / local |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
$ROWS
* **cold**: an empty disk cache: the manifest, each pack's header and index (one range request
  each, on the loader's threads, every level's pack under the camera at once), then the blocks:
  the loader offers the pack store the queued tiles around each one it starts, and neighbours
  whose blocks lie end to end (a tile's children, stored together in Morton order) are read by
  one range request; up to 24 requests at once over at most 16 connections, with the
  refinement's next levels requested ahead (3 levels).
* **z/x/y**: the same blocks the cold run loaded (those read together cut apart), each its own
  file, fetched by
  \`curl --parallel --parallel-max 24\` given the exact list up front: a floor for the transport
  alone (no selection, no rendering, no index; a z/x/y viewer would also have to ask for tiles
  that do not exist to learn so).
* **warm**: the same cache again: one conditional GET of the manifest (304), everything else from
  the disk cache. "near" goes straight to nginx; "local" reads the directory. "max-age": the
  manifest served with \`Cache-Control: max-age=300\` (nginx \`expires 5m\`): a warm start
  within those 5 minutes asks nothing at all.
EOF
mv "$OUT.tmp" "$OUT"
cat "$OUT"
