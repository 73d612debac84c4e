#!/usr/bin/env bash
# Installs the Debian 12 packages Inkwire needs (only those missing), then configures and builds.
#   scripts/setup.sh            install + Release build into build/
#   INKWIRE_SKIP_INSTALL=1 ...  build only
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

if [ "${INKWIRE_SKIP_INSTALL:-0}" != 1 ]; then
  mapfile -t wanted < <(grep -vE '^\s*(#|$)' scripts/packages.txt)
  missing=()
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${#missing[@]} missing packages: ${missing[*]}"
    sudo=""
    [ "$(id -u)" = 0 ] || sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  else
    echo "setup: all packages present"
  fi
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release ${INKWIRE_CMAKE_ARGS:-}
cmake --build build -j "$(nproc)"
