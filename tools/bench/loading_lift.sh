#!/usr/bin/env bash
# Pops while loading: the largest lift in one frame that newly arrived ground gives the camera
# (`globe play --real-time`'s "largest lift by new ground in one frame"), in a fast descent
# (tools/bench/paths/zion-descent.json) over the README's pyramid served by nginx behind a proxy
# that adds a round trip (globe-delay-proxy), each run with an empty disk cache. Finer tiles that
# arrive near the camera morph in over --morph-frames frames (8, as globe view) or pop in at once
# (0); runs alternate between the two and the medians are printed. nginx and the proxy listen on
# 127.0.0.1 only and stop by themselves (timeout) if this dies.
#
#   tools/bench/loading_lift.sh BUILD_DIR [PYRAMID] [RTT_MS] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${1:?build directory}
PYRAMID=$(realpath "${2:-pyramid}")
RTT=${3:-150}
RUNS=${4:-3}
cmake --build "$BUILD" -j"$(nproc)" --target globe globe-delay-proxy >/dev/null
GLOBE=$BUILD/apps/globe/globe
PROXY=$BUILD/tools/bench_http/globe-delay-proxy
PATHFILE=tools/bench/paths/zion-descent.json
WORK=$(mktemp -d /tmp/globe-loading-lift.XXXXXX)
cleanup() {
  kill "${NGINX_PID:-}" "${PROXY_PID:-}" 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
NGINX_PORT=$(free_port)
PROXY_PORT=$(free_port)
mkdir -p "$WORK/www" "$WORK/nginx/tmp"
ln -s "$PYRAMID" "$WORK/www/pyramid"
cat > "$WORK/nginx/nginx.conf" <<CONF
daemon off; master_process off; worker_processes 1;
pid $WORK/nginx/nginx.pid; error_log $WORK/nginx/error.log warn;
events { worker_connections 512; }
http {
  access_log off;
  client_body_temp_path $WORK/nginx/tmp/b; proxy_temp_path $WORK/nginx/tmp/p;
  fastcgi_temp_path $WORK/nginx/tmp/f; uwsgi_temp_path $WORK/nginx/tmp/u; scgi_temp_path $WORK/nginx/tmp/s;
  types { application/json json; } default_type application/octet-stream;
  server { listen 127.0.0.1:$NGINX_PORT; root $WORK/www; }
}
CONF
timeout 1800 /usr/sbin/nginx -p "$WORK/nginx" -c "$WORK/nginx/nginx.conf" -e "$WORK/nginx/error.log" &
NGINX_PID=$!
timeout 1800 "$PROXY" "$PROXY_PORT" "$NGINX_PORT" "$RTT" 1800 &
PROXY_PID=$!
for _ in $(seq 50); do curl -sf "http://127.0.0.1:$PROXY_PORT/pyramid/manifest.json" >/dev/null && break; sleep 0.1; done

# One flight: "LIFT_M MIN_CLEARANCE_M" from its summary.
fly() {
  local morph=$1 glide=$2 run=$3 out="$WORK/out-$1-$2-$3"
  "$GLOBE" play "http://127.0.0.1:$PROXY_PORT/pyramid" "$PATHFILE" --out "$out" --no-frames \
    --size 960x540 --real-time --morph-frames "$morph" $glide --cache-dir "$WORK/cache-$1-$3$2" \
    > "$out.txt"
  python3 - "$out.txt" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
lift = re.search(r"largest lift by new ground in one frame ([0-9.]+) m", text).group(1)
clearance = re.search(r"min clearance: (-?[0-9.]+) m", text).group(1)
print(lift, clearance)
PY
}
median() { sort -g | awk '{v[NR]=$1} END {print (NR%2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

echo "fast descent over $PYRAMID via http, +$RTT ms round trip, $RUNS runs each (largest lift by new ground in one frame, m; lowest eye clearance, m)"
for glide in --no-glide ""; do
  declare -A lifts=() clear=()
  for run in $(seq "$RUNS"); do
    for morph in 0 8; do
      read -r l c < <(fly "$morph" "$glide" "$run")
      lifts[$morph]+="$l "; clear[$morph]+="$c "
    done
  done
  for morph in 0 8; do
    printf '%-10s morph %d: lift %s (median %s), lowest clearance %s\n' "${glide:-glide}" "$morph" \
      "${lifts[$morph]}" "$(echo "${lifts[$morph]}" | tr ' ' '\n' | grep . | median)" "${clear[$morph]}"
  done
  unset lifts clear
done
