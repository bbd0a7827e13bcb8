#!/usr/bin/env bash
# What the web-client tests (tests/web) and tools/bench_web need, on Debian 12: Chromium, node and
# npm from apt where any is missing (as root, or through sudo), then the pinned npm packages of
# tools/web (package-lock.json) into tools/web/node_modules. Quick when all is there already:
# nothing is fetched when node_modules matches the lock file. The test command's install step.
set -euo pipefail
cd "$(dirname "$0")"
. ../lib/apt-install-missing.sh
missing=()
command -v chromium >/dev/null 2>&1 || missing+=(chromium)
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
apt_install_missing tools/web/install.sh ${missing[@]+"${missing[@]}"}
# npm ci empties node_modules and installs the lock file's versions; skipped when node_modules was
# installed from this very lock file (its hash, written after a successful npm ci).
stamp=node_modules/.globe-package-lock.sha256
lock=$(sha256sum package-lock.json | cut -d' ' -f1)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$lock" ]; then
  echo "tools/web/install.sh: node_modules is the lock file's already"
else
  npm ci --omit=dev --no-audit --no-fund --loglevel=error
  echo "$lock" >"$stamp"
fi
