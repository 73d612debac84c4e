#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: unit tests, headless GL tests (OSMesa),
# and the windowed GL tests on a virtual display; then every fuzz target for a few seconds
# (INKWIRE_FUZZ_SECONDS, default 5; 0 skips), so a decoder change that crashes fails here.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/scripts/setup.sh"
cd "$here"
# xvfb-run gives the GLFW tests a display; without it they skip and say so.
runner=()
command -v xvfb-run >/dev/null && runner=(xvfb-run -a -s "-screen 0 1024x768x24")
"${runner[@]}" ctest --test-dir build --output-on-failure -j "$(nproc)"
# Each untrusted decoder under libFuzzer briefly (the long runs: scripts/fuzz.sh 600).
fuzz_seconds=${INKWIRE_FUZZ_SECONDS:-5}
if [ "$fuzz_seconds" != 0 ]; then "$here/scripts/fuzz.sh" "$fuzz_seconds"; fi
