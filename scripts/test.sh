#!/usr/bin/env bash
# Installs what is missing, builds, and runs the tests by their tiers (ctest labels, tests/README.md):
#   scripts/test.sh            every tier: unit, gl, e2e, browser, fuzz, soak (what CI runs)
#   scripts/test.sh --quick    unit and gl only: a change's inner loop
# The fuzz tier runs every fuzz target for INKWIRE_FUZZ_SECONDS (default 5; 0 leaves the tier
# out), so a decoder change that crashes fails here. Other arguments go to ctest (-R NAME, -L e2e).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
tiers=()
if [ "${1:-}" = --quick ]; then
  tiers=(-L '^(unit|gl)$')
  shift
elif [ "${INKWIRE_FUZZ_SECONDS:-5}" = 0 ]; then
  tiers=(-LE '^fuzz$')
fi
"$here/scripts/setup.sh"
cd "$here"
# xvfb-run gives the GLFW tests and the browser engines that need one a display; without it
# they skip and say so.
runner=()
command -v xvfb-run >/dev/null && runner=(xvfb-run -a -s "-screen 0 1024x768x24")
"${runner[@]}" ctest --test-dir build --output-on-failure -j "$(nproc)" "${tiers[@]}" "$@"
