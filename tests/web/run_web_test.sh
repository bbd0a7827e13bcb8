#!/bin/sh
# Runs one web-client test (a node script of tests/web) when what it needs is installed:
# node, tools/web/node_modules (npm ci, tools/web/install.sh), Chromium and nginx. Otherwise it
# exits 77, which CTest reports as skipped, saying what is missing and how to install it.
# Usage: run_web_test.sh SCRIPT.mjs   (GLOBE_EXE, GLOBE_TILER_EXE, GLOBE_WEB_OUT from CTest)
set -u
here=$(cd "$(dirname "$0")" && pwd)
web="$here/../../tools/web"
skip() {
  echo "SKIP: $1: run 'bash tools/web/install.sh' (the test command's install step) to run this test"
  exit 77
}
command -v node >/dev/null 2>&1 || skip "node is not installed"
for module in puppeteer-core cesium maplibre-gl; do
  [ -f "$web/node_modules/$module/package.json" ] || skip "tools/web/node_modules/$module is missing"
done
[ -x "${GLOBE_CHROMIUM:-/usr/bin/chromium}" ] || skip "${GLOBE_CHROMIUM:-/usr/bin/chromium} is missing"
[ -x /usr/sbin/nginx ] || skip "/usr/sbin/nginx is missing (nginx-light, tools/install-deps.sh)"
exec node "$here/$1"
