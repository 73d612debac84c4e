#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) and runs
# each for SECONDS (default 600), two at a time, then prints a table of executions, coverage and
# crashes (the one in docs/fuzzing.md came from this script).
#   scripts/fuzz.sh [SECONDS] [TARGET ...]     corpora in fuzz-corpus/, crashes in fuzz-out/
#   FUZZ_TABLE_ONLY=1 scripts/fuzz.sh ...       the table of the last run's logs again
#   scripts/fuzz.sh --build-only [TARGET ...]   build and seed only (ctest's FuzzBuild fixture)
#   scripts/fuzz.sh --no-build SECONDS TARGET   run what is built (ctest's Fuzz_TARGET, the fuzz tier)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
build=1 fuzz=1
case "${1:-}" in
  --build-only) fuzz=0; shift ;;
  --no-build) build=0; shift ;;
esac
seconds=600
if [ $fuzz = 1 ]; then seconds=${1:-600}; shift || true; fi
# (The fuzz tier's seconds, when scripts/test.sh or a person says otherwise than the build.)
if [ $build = 0 ] && [ "${INKWIRE_FUZZ_SECONDS:-0}" != 0 ]; then seconds=$INKWIRE_FUZZ_SECONDS; fi
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_frames fuzz_message fuzz_tween fuzz_landmarks fuzz_http fuzz_websocket fuzz_config fuzz_broker fuzz_voice fuzz_glb fuzz_video fuzz_calibration fuzz_upload)
[ "${FUZZ_TABLE_ONLY:-0}" != 1 ] || build=0 fuzz=0

if [ $build = 1 ]; then
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ -n "${missing[*]:-}" ]; then
  sudo=""; [ "$(id -u)" = 0 ] || sudo="sudo"
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DINKWIRE_BUILD_FUZZ=ON \
  -DINKWIRE_BUILD_TESTS=OFF -DINKWIRE_BUILD_BENCH=OFF "${launcher[@]}" > /dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}" > /dev/null

# Seeds: a few well-formed inputs each fuzzer would take long to invent.
mkdir -p fuzz-out
for t in "${targets[@]}"; do mkdir -p "fuzz-corpus/$t"; done
[ -d fuzz-corpus/fuzz_http ] && printf 'GET /ws HTTP/1.1\r\nHost: 127.0.0.1:8080\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n' > fuzz-corpus/fuzz_http/upgrade
# A masked binary message holding a ping frame (6-byte header, 8-byte nonce), then a close.
[ -d fuzz-corpus/fuzz_websocket ] && printf '\x82\x8e\x00\x00\x00\x00\x08\x00\x00\x00\x04\x00\x01\x02\x03\x04\x05\x06\x07\x08\x88\x80\x00\x00\x00\x00' > fuzz-corpus/fuzz_websocket/ping
if [ -d fuzz-corpus/fuzz_config ]; then
  cp deploy/example/instance-a.json deploy/example/instance-b.json fuzz-corpus/fuzz_config/
  printf '{"tls": {"certificate": "c.pem", "key": "k.pem"}, "max_connections": 10, "sessions": [{"name": "t", "kind": "turntable", "product": {"photos": "p", "step": 15}}, {"name": "c", "kind": "conference", "face": {"source": "camera:0"}}]}' > fuzz-corpus/fuzz_config/keys.json
fi

# Uploads: every file of assimp's invalid corpus as the one file of a multipart body (the first
# byte chooses the pieces the body comes in), and a glTF with its .bin.
if [ -d fuzz-corpus/fuzz_upload ]; then
  /usr/bin/python3 - <<'PY'
import os
def body(files):
    out = b"\x10"
    for name, data in files:
        out += b"--inkwire-fuzz-boundary\r\nContent-Disposition: form-data; name=\"file\"; filename=\"" + name.encode() + b"\"\r\n\r\n" + data + b"\r\n"
    return out + b"--inkwire-fuzz-boundary--\r\n"
invalid = "/usr/share/assimp/models/invalid"
for name in sorted(os.listdir(invalid)) if os.path.isdir(invalid) else []:
    path = os.path.join(invalid, name)
    if os.path.isfile(path) and os.path.getsize(path) < 1 << 20:
        open(f"fuzz-corpus/fuzz_upload/invalid-{name}", "wb").write(body([(name, open(path, "rb").read())]))
box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF"
if os.path.isdir(box):
    open("fuzz-corpus/fuzz_upload/box", "wb").write(body([(n, open(os.path.join(box, n), "rb").read())
                                                          for n in ("BoxTextured.gltf", "BoxTextured0.bin", "CesiumLogoFlat.png")]))
PY
fi

# A calibration of four cameras round an object, 10 degrees apart (a lab's *_par.txt).
if [ -d fuzz-corpus/fuzz_calibration ]; then
  {
    echo 4
    for i in 0 1 2 3; do
      awk -v i="$i" 'BEGIN { a = i * 10 * 3.14159265 / 180; c = cos(a); s = sin(a);
        printf "view%d.png 1520 0 302 0 1525 247 0 0 1 %f 0 %f 0 1 0 %f 0 %f 0 0 0.6\n", i, c, -s, s, c }'
    done
  } > fuzz-corpus/fuzz_calibration/ring_par.txt
fi

# Changes and a session definition as the broker holds them, around the golden protocol frames.
if [ -d fuzz-corpus/fuzz_broker ]; then
  /usr/bin/python3 - <<'PY'
import json
frames = {f["type"]: bytes.fromhex(f["hex"]) for f in json.load(open("tests/golden/protocol-frames.json"))["frames"]}
for t in ("style-change", "camera-pose", "object-pose", "expression-code"):
    open(f"fuzz-corpus/fuzz_broker/event-{t}", "wb").write(b"\x01" + b"17 1764000000000000 3 1:a4:cows" + frames[t])
open("fuzz-corpus/fuzz_broker/definition", "wb").write(b"\x00" + b"71:sha256:" + b"0" * 64 + b"0:" + frames["snapshot"])
for t in ("voice-frame", "member-face", "roster"):
    open(f"fuzz-corpus/fuzz_broker/call-{t}", "wb").write(b"\x02" + b"M3:one4:call" + frames[t])
open("fuzz-corpus/fuzz_broker/call-photo", "wb").write(b"\x02" + b"P3:one4:call3 4:\xff\xd8\xff\xe02:{}")
PY
fi

# A real face video: six VP8 frames (a key frame, then inter frames) of 160 px, each behind its
# 2-byte length, as fuzz_video reads them.
if [ -d fuzz-corpus/fuzz_video ] && [ ! -f fuzz-corpus/fuzz_video/six-frames ]; then
  ffmpeg -v error -y -f lavfi -i testsrc=size=160x160:rate=15 -frames:v 6 -c:v libvpx -deadline realtime -lag-in-frames 0 -b:v 36k \
    fuzz-out/six-frames.ivf
  /usr/bin/python3 - <<'PY'
import struct
ivf = open("fuzz-out/six-frames.ivf", "rb").read()
at, out = 32, b""
while at + 12 <= len(ivf):
    n = struct.unpack_from("<I", ivf, at)[0]
    out += struct.pack("<H", n) + ivf[at + 12:at + 12 + n]
    at += 12 + n
open("fuzz-corpus/fuzz_video/six-frames", "wb").write(out)
PY
fi

# Real GLBs: a textured box and a model of many parts (assimp-testmodels).
if [ -d fuzz-corpus/fuzz_glb ]; then
  for f in /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb /usr/share/assimp/models/glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb; do
    [ -f "$f" ] && cp "$f" fuzz-corpus/fuzz_glb/
  done
fi
fi

if [ $fuzz = 1 ]; then
mkdir -p fuzz-out
for t in "${targets[@]}"; do
  [ -x "build-fuzz/bin/$t" ] || { echo "fuzz: build-fuzz/bin/$t is not built (scripts/fuzz.sh --build-only)" >&2; exit 1; }
  mkdir -p "fuzz-corpus/$t"
done

run() {
  local t=$1
  # -rss_limit_mb: a target that grows without bound is a finding too.
  build-fuzz/bin/"$t" -max_total_time="$seconds" -print_final_stats=1 -rss_limit_mb=2048 -artifact_prefix="fuzz-out/$t-" \
    "fuzz-corpus/$t" > "fuzz-out/$t.log" 2>&1 || true
}
running=0
for t in "${targets[@]}"; do
  run "$t" &
  running=$((running + 1))
  if [ $running -ge 2 ]; then wait -n; running=$((running - 1)); fi
done
wait
fi
[ $fuzz = 1 ] || [ "${FUZZ_TABLE_ONLY:-0}" = 1 ] || exit 0

echo "| target | seconds | executions | executions/s | coverage (edges) | features | corpus | crashes |"
echo "|---|---|---|---|---|---|---|---|"
for t in "${targets[@]}"; do
  log="fuzz-out/$t.log"
  runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{print $2}' | tail -1 || true)
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -1 || true)  # none when it crashed
  cov=$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<< "$done_line")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$done_line")
  corp=$(sed -n 's/.* corp: \([0-9]*\)\/.*/\1/p' <<< "$done_line")
  crashes=$(find fuzz-out -name "$t-crash-*" -o -name "$t-leak-*" -o -name "$t-oom-*" -o -name "$t-timeout-*" | wc -l)
  echo "| $t | $seconds | ${runs:-?} | $(( ${runs:-0} / seconds )) | ${cov:-?} | ${ft:-?} | ${corp:-?} | $crashes |"
done
# A finding of these targets fails the run (the fuzz tier runs every target briefly): the input is in fuzz-out/.
found=$(for t in "${targets[@]}"; do find fuzz-out -name "$t-crash-*" -o -name "$t-leak-*" -o -name "$t-oom-*" -o -name "$t-timeout-*"; done | sort)
if [ -n "$found" ]; then
  echo "fuzz: findings (replay with build-fuzz/bin/TARGET FILE):" $found >&2
  exit 1
fi
