#!/usr/bin/env bash
# Installs the Debian 12 packages Inkwire needs (only those missing), then configures and builds.
#   scripts/setup.sh            install + Release build into build/
#   INKWIRE_SKIP_INSTALL=1 ...  build only
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

sudo=""
[ "$(id -u)" = 0 ] || sudo="sudo"
if [ "${INKWIRE_SKIP_INSTALL:-0}" != 1 ]; then
  mapfile -t wanted < <(grep -vE '^\s*(#|$)' scripts/packages.txt)
  missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${#missing[@]} missing packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  else
    echo "setup: all packages present"
  fi
fi

# The browser tests drive Firefox through puppeteer-core, pinned in tests/web/package-lock.json
# (nothing else is downloaded: it uses Debian's firefox-esr). Node's package manager comes from
# Debian when the machine's node has none.
if [ "${INKWIRE_SKIP_INSTALL:-0}" != 1 ] && [ ! -d tests/web/node_modules/puppeteer-core ]; then
  if ! command -v npm >/dev/null; then
    $sudo apt-get install -y -qq --no-install-recommends npm
  fi
  echo "setup: installing the browser tests' puppeteer-core (npm ci --prefix tests/web)"
  # Without it only the Firefox runs of the browser tests skip (and say why): no reason to stop.
  npm ci --prefix tests/web --no-audit --no-fund --loglevel=error ||
    echo "setup: puppeteer-core could not be installed: the browser tests will skip Firefox"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${INKWIRE_CMAKE_ARGS:-}
cmake --build build -j "$(nproc)"
