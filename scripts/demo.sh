#!/usr/bin/env bash
# The demo: installs what is missing, builds, and renders packaged models in every registered
# style into a gallery, plus turntable videos.
#   scripts/demo.sh [OUT_DIR]      (default: demo-output/)
# Writes OUT_DIR/contact-sheet.png (models x styles), OUT_DIR/styles/<model>-<style>.png,
# OUT_DIR/shade-maps.png (the comic shade-map library on one model), OUT_DIR/paintings.png (every
# shipped painting style), OUT_DIR/turntable-<style>.mp4 and OUT_DIR/painted-video.mp4 (a
# recorded video painted frame by frame), OUT_DIR/tween-methods.png and OUT_DIR/tween/ (views
# synthesised between sample images: methods side by side, orbit videos, real photos of a ring
# when ../shared/data is there, a morph between two faces, dropped video frames regenerated),
# OUT_DIR/network/ (a server, a viewer recording a shared
# session while a director client changes its style and camera, a turntable session, and a
# conference whose client rebuilds the speaker's face from expression codes; products turned by
# customers: turntable.mp4, duck-product.mp4 from a folder of photos (duck-product-zoomed.mp4 zoomed in), temple-product.mp4 from the
# real temple photos when ../shared/data is there), OUT_DIR/call/call.mp4 (a call between two
# members' own faces and voices, recorded with its sound by a listener).
set -euo pipefail
say() { echo "demo: $*"; }
here=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$here/demo-output}")
"$here/scripts/setup.sh"

bin="$here/build/bin"
meshes="$here/build/packaged-data/data/meshes"
say "rendering every packaged model in every style (contact-sheet.png, styles/)"
# Packaged models: a textured duck (assimp-testmodels) and a closed cow (libcgal-demo).
models=("duck:/usr/share/assimp/models/Collada/duck.dae" "cow:$meshes/cow.off")
mapfile -t styles < <("$bin/inkwire-render" --style list | awk '/^[^ ]/ {print $1}')
styles+=("hatching+sketch-pencil")  # styles also combine
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
mkdir -p "$out/styles"

tiles=()
for entry in "${models[@]}"; do
  model=${entry%%:*}; file=${entry#*:}
  for style in "${styles[@]}"; do
    tile="$out/styles/$model-$style.png"
    "$bin/inkwire-render" --mesh "$file" --style "$style" --view 35,15,1.3 --size 400x320 --out "$tile"
    tiles+=("$tile" --text:x=12:y=26:size=18:color=1,1,1:shadow=2:font=$font "$model / $style")
  done
done
# Six tiles to a row; blank paper fills the last row.
count=$(( ${#styles[@]} * ${#models[@]} ))
columns=6
rows=$(( (count + columns - 1) / columns ))
for ((i = count; i < columns * rows; ++i)); do tiles+=(--pattern constant:color=0.96,0.94,0.9,1 400x320 4); done
oiiotool "${tiles[@]}" --mosaic:pad=4 "${columns}x${rows}" --ch R,G,B -o "$out/contact-sheet.png"

say "the comic shade-map library (shade-maps.png)"
# Every shipped comic shade map, on the textured duck.
mapfile -t shade_maps < <("$bin/inkwire-render" --style list | awk '$1 == "shade_map" {sub(/,$/, "", $3); print $3}' | head -1 | tr '|' '\n')
maps=()
for map in "${shade_maps[@]}"; do
  tile="$out/styles/duck-comic-extended-$map.png"
  "$bin/inkwire-render" --mesh /usr/share/assimp/models/Collada/duck.dae --style comic-extended --set "shade_map=$map" \
    --view 35,15,1.3 --size 320x256 --out "$tile"
  maps+=("$tile" --text:x=10:y=22:size=16:color=1,1,1:shadow=2:font=$font "$map")
done
oiiotool "${maps[@]}" --mosaic:pad=2 "4x$(( (${#shade_maps[@]} + 3) / 4 ))" --ch R,G,B -o "$out/shade-maps.png"

say "every shipped painting style (paintings.png) and a turntable video per style"
# Every shipped painting style, on the textured duck.
paintings=()
for file in "$here"/client/render/painterly/styles/*.json; do
  name=$(basename "$file" .json)
  tile="$out/styles/duck-painterly-$name.png"
  "$bin/inkwire-render" --mesh /usr/share/assimp/models/Collada/duck.dae --style painterly --set "style=$name" \
    --view 35,15,1.2 --size 400x320 --out "$tile"
  paintings+=("$tile" --text:x=12:y=26:size=18:color=1,1,1:shadow=2:font=$font "painterly / $name")
done
painting_count=$(( ${#paintings[@]} / 3 ))  # tile, caption option, caption
painting_rows=$(( (painting_count + 2) / 3 ))
for ((i = painting_count; i < 3 * painting_rows; ++i)); do paintings+=(--pattern constant:color=0.96,0.94,0.9,1 400x320 4); done
oiiotool "${paintings[@]}" --mosaic:pad=4 "3x$painting_rows" --ch R,G,B -o "$out/paintings.png"

for style in "${styles[@]}"; do
  "$bin/inkwire-render" --mesh "$meshes/cow.off" --style "$style" --view 35,15,1.3 --size 640x480 \
    --frames 96 --out "$out/turntable-$style.mp4"
done

say "painting a recorded video frame by frame (painted-video.mp4)"
# Video painting: the duck's default turntable as a recorded video, painted over itself frame by frame.
"$bin/inkwire-render" --mesh /usr/share/assimp/models/Collada/duck.dae --style default --view 35,15,1.2 --size 480x360 \
  --frames 72 --out "$out/duck-turntable.mp4"
"$bin/inkwire-render" --video "$out/duck-turntable.mp4" --style painterly --out "$out/painted-video.mp4"

say "tweening between sample images: methods, orbits, a face morph, restored frames (tween/)"
# Super-realistic tweening: a textured product photographed (rendered) every 15 degrees; every
# view in between synthesised by warping the two nearest samples along their control points.
truck=/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf
mkdir -p "$out/tween"
tween_tiles=()
"$bin/inkwire-render" --mesh "$truck" --style default --view 52.5,0,1.4 --size 320x320 --out "$out/tween/truth.png"
tween_tiles+=("$out/tween/truth.png" --text:x=10:y=24:size=16:color=0,0,0:font=$font "true view at 52.5 deg")
for method in nearest crossfade bilinear; do
  "$bin/inkwire-render" --mesh "$truck" --style tween --set "method=$method" --view 52.5,0,1.4 --size 320x320 \
    --out "$out/tween/$method.png"
  tween_tiles+=("$out/tween/$method.png" --text:x=10:y=24:size=16:color=0,0,0:font=$font "$method from 45 + 60 deg")
done
oiiotool "${tween_tiles[@]}" --mosaic:pad=4 4x1 --ch R,G,B -o "$out/tween-methods.png"
"$bin/inkwire-render" --mesh "$truck" --style tween --view 0,0,1.4 --size 480x360 --frames 96 --out "$out/tween/truck-orbit.mp4"
"$bin/inkwire-render" --mesh "$truck" --style tween --set method=trilinear --view 0,30,1.4 --size 480x360 --frames 96 \
  --out "$out/tween/truck-orbit-trilinear.mp4"
if [[ -d "$here/../shared/data/templeRing" ]]; then  # real photos, when the data folder is beside the checkout
  "$bin/inkwire-eval" tween-ring --dataset "$here/../shared/data/templeRing" --limit 4 --images "$out/tween/temple" \
    --json "$out/tween/temple.json" > /dev/null
fi
# The same warp engine between two different faces (landmarks from the face model, both photos
# cut to one framing), and regenerating dropped video frames: the comic turntable keeps every
# third frame and the two in between are tweened (the sheet: input | hold | cross-fade | tween).
faces=/usr/share/doc/libdlib19.1/examples/faces
"$bin/inkwire-tween" morph --from "$faces/Tom_Cruise_avp_2014_4.jpg" --to "$faces/2008_001009.jpg" --frame-faces \
  --out "$out/tween/morph-faces.mp4" --sheet "$out/tween/morph-faces.png" > /dev/null
yale="$here/../shared/data/yalefaces"
if [[ -d "$yale" ]]; then
  "$bin/inkwire-tween" morph --from "$yale/subject02_normal.png" --to "$yale/subject07_happy.png" --frame-faces \
    --out "$out/tween/morph-yale.mp4" --sheet "$out/tween/morph-yale.png" > /dev/null
fi
"$bin/inkwire-tween" restore --input "$out/turntable-comic.mp4" --keep-every 3 --out "$out/tween/restored-turntable.mp4" \
  --sheet "$out/tween/restored-turntable.png" --json "$out/tween/restored-turntable.json" > /dev/null

say "a speaker's face sent as expression codes and rebuilt (conference/)"
# Low-bandwidth conferencing: the speaker's frames are analysed (dlib landmarks -> expression
# code), only the codes cross the wire, and the receiver deforms the neutral photo by them.
# Packaged photos hold no face video, so the speaker is synthesised from one packaged photo;
# with the Yale faces beside the checkout, a real subject's photos play the speaker too.
mkdir -p "$out/conference"
"$bin/inkwire-conference" --speaker /usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg \
  --script neutral:1,smile@200:1,surprise:1,viseme-open@180:0.6,viseme-round:0.6,laugh@220:1,eyes-closed:0.8,wink-left:0.8,neutral:0.6 \
  --fps 25 --out "$out/conference/packaged-speaker.mp4" --input-out "$out/conference/packaged-speaker-input.mp4" \
  --json "$out/conference/packaged-speaker.json" > /dev/null
yale="$here/../shared/data/yalefaces"
if [[ -d "$yale" ]]; then
  rm -rf "$out/conference/yale-input" && mkdir -p "$out/conference/yale-input"
  i=0
  for label in normal happy normal surprised sleepy normal wink happy sad normal; do
    cp "$yale/subject11_$label.png" "$out/conference/yale-input/$(printf %02d $i)_$label.png"; i=$((i + 1))
  done
  "$bin/inkwire-conference" --input "$out/conference/yale-input" --neutral "$yale/subject11_normal.png" --repeat 15 --fps 15 \
    --out "$out/conference/yale-subject11.mp4" --json "$out/conference/yale-subject11.json" > /dev/null
fi

say "starting a server; a viewer follows a session while a director changes its style (network/)"
# Over the network: a real server with the embedded default's sessions plus a conference whose
# speaker is the synthesised clip above, a viewer recording the shared "demo" session, and a
# director client that changes the session's style and camera once a second. The viewer draws
# every change locally from control messages of a few bytes.
mkdir -p "$out/network"
rm -rf "$out/network/server-data"
cat > "$out/network/server.json" <<EOF
{ "sessions": [
  { "name": "demo", "kind": "scene", "style": "comic-extended", "assets": [ { "path": "$meshes/cow.off" } ] },
  { "name": "sketchbook", "kind": "scene", "style": "sketch-pencil", "assets": [ { "path": "$meshes/bull.off" } ] },
  { "name": "turntable", "kind": "turntable", "style": "tween", "product": { "mesh": "$truck", "samples": 24, "size": 512 } },
  { "name": "conference", "kind": "conference",
    "face": { "source": "$out/conference/packaged-speaker-input.mp4", "loop": true } },
  { "name": "call", "kind": "conference" } ] }
EOF
# A shop owner's product: studio photos of the duck turning on a turntable in front of white, every
# 15 degrees (the view's azimuth falls as the object turns: --step -15), put on the server with one
# command; at 1024 pixels they are shown first at 512 and kept at 1024 for zooming in. With
# ../shared/data beside the checkout, the real temple photos become a product too.
rm -rf "$out/network/duck-photos" && mkdir -p "$out/network/duck-photos"
"$bin/inkwire-render" --mesh /usr/share/assimp/models/Collada/duck.dae --style default --view 0,0,1.4 --frames 24 \
  --size 1024x1024 --backdrop '#ffffff' --out "$out/network/duck-photos/IMG_%04d.jpg"
"$bin/inkwire-server" add-product duck --photos "$out/network/duck-photos" --step -15 --data "$out/network/server-data" \
  > "$out/network/add-product-duck.log"
if [[ -d "$here/../shared/data/templeRing" ]]; then
  "$bin/inkwire-server" add-product temple --photos "$here/../shared/data/templeRing" --data "$out/network/server-data" \
    > "$out/network/add-product-temple.log"
fi
"$bin/inkwire-server" --listen 127.0.0.1:0 --http 127.0.0.1:0 --data "$out/network/server-data" --config "$out/network/server.json" \
  2> "$out/network/server.log" &
server_pid=$!
trap 'kill $server_pid 2>/dev/null || true' EXIT
port=""
for _ in $(seq 100); do
  port=$(sed -n 's/.*"event":"listening".*"port":\([0-9]*\).*/\1/p' "$out/network/server.log")
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { echo "demo: the server did not start" >&2; cat "$out/network/server.log" >&2; exit 1; }
http_port=$(sed -n 's/.*"event":"http-listening".*"port":\([0-9]*\).*/\1/p' "$out/network/server.log")
client=("$bin/inkwire-client" --connect "127.0.0.1:$port" --headless --cache "$out/network/cache")
"${client[@]}" --session demo --name viewer --frames 96 --fps 12 --size 480x360 --out "$out/network/viewer.mp4" \
  2> "$out/network/viewer.log" &
viewer_pid=$!
azimuth=30
for style in comic-extended sketch-pencil hatching painterly hatching+sketch-charcoal comic; do
  sleep 1
  azimuth=$(( azimuth + 50 ))
  "${client[@]}" --session demo --name director --style "$style" --view "$azimuth,20,1.3" --frames 1 --size 320x240 \
    --out "$out/network/director-$style.png" 2>> "$out/network/director.log"
done
wait $viewer_pid
say "customers turn products put on the server from photos (network/*-product.mp4)"
# Products: each visitor turns the product on their own (nothing is sent while they do); every
# view between the photos is synthesised by the client. The first visit shows what arrives first.
"${client[@]}" --session turntable --name customer --view 0 --frames 96 --fps 24 --size 640x480 --wait-for-product \
  --out "$out/network/turntable.mp4" --frame-log "$out/network/turntable.jsonl" 2>> "$out/network/viewer.log"
"${client[@]}" --session duck --name customer --view 0 --frames 96 --fps 24 --size 512x512 \
  --out "$out/network/duck-product.mp4" --frame-log "$out/network/duck-product.jsonl" 2>> "$out/network/viewer.log"
# Zoomed in three times and turned slowly (a turn in 10 s): the client fetches the 1024-pixel
# photos of the views it shows as it turns.
"${client[@]}" --session duck --name zoomed-customer --view 0,0,3 --frames 240 --fps 24 --size 512x512 --wait-for-product \
  --out "$out/network/duck-product-zoomed.mp4" --frame-log "$out/network/duck-product-zoomed.jsonl" 2>> "$out/network/viewer.log"
if [[ -d "$here/../shared/data/templeRing" ]]; then
  "${client[@]}" --session temple --name customer --view 0 --frames 120 --fps 24 --size 384x512 --wait-for-product \
    --out "$out/network/temple-product.mp4" 2>> "$out/network/viewer.log"
fi
say "the product and conference pages in headless Chromium (web/)"
# A customer's browser: the session index, the duck's product page, a drag of the element, and
# the conference's page.
/usr/bin/python3 "$here/scripts/web_demo.py" "$http_port" duck conference "$out/web"
say "the shared scene's page in headless Chromium while native clients change its style (web/scene.mp4)"
# The same C++ renderers compiled to WebAssembly draw the scene in the page.
/usr/bin/python3 "$here/scripts/web_scene_demo.py" "$http_port" "$port" demo "$bin" "$out/web"
# The conference: the server analyses the speaker and sends codes only; the listener deforms the
# neutral photo (fetched once) by them. Then one member asks for paint, and the face is painted.
"${client[@]}" --session conference --name listener --frames 120 --fps 15 --size 360x480 \
  --out "$out/network/conference.mp4" 2>> "$out/network/viewer.log"
"${client[@]}" --session conference --name painter --style painterly --set style=impressionist --frames 45 --fps 15 \
  --size 360x480 --out "$out/network/conference-painted.mp4" 2>> "$out/network/viewer.log"
# A call: two members publish their own face (a camera clip made from a real photo each) and
# voice (sentences spoken by espeak-ng) from native clients; a third only listens and records the
# grid with its sound. Only face crops go up; expression codes and Opus voice come down.
say "recording a call between two members and a listener ($out/call/call.mp4, with sound)"
mkdir -p "$out/call"
"$bin/inkwire-conference" --speaker /usr/share/doc/libdlib19.1/examples/faces/2009_004587.jpg \
  --script neutral:1.5,smile@220:2,neutral:1,surprise:1.5,smile:2,neutral:2 --fps 15 \
  --out "$out/call/bea-reconstruction.mp4" --input-out "$out/call/bea-camera.mp4" > /dev/null
espeak-ng -s 140 -w "$out/call/ada.wav" "Hello Bea. Can you hear me? The new turntable pages are live, and the shop looks lovely."
espeak-ng -v en+f3 -s 140 -w "$out/call/bea.wav" "Yes, I hear you well. Let us show the customers on Monday."
"${client[@]}" --session call --name Listener --frames 210 --fps 15 --size 720x300 --out "$out/call/call.mp4" \
  --audio-out "$out/call/call.wav" --frame-log "$out/call/listener.jsonl" 2> "$out/call/listener.log" &
listener_pid=$!
sleep 1
"${client[@]}" --session call --name Ada --camera "$out/conference/packaged-speaker-input.mp4" --microphone "$out/call/ada.wav" \
  --frames 180 --fps 15 --size 320x240 --out "$out/call/ada-view.mp4" 2> "$out/call/ada.log" &
ada_pid=$!
sleep 6
"${client[@]}" --session call --name Bea --camera "$out/call/bea-camera.mp4" --microphone "$out/call/bea.wav" \
  --frames 90 --fps 15 --size 320x240 --out "$out/call/bea-view.mp4" 2> "$out/call/bea.log"
wait $ada_pid $listener_pid
kill -TERM $server_pid && wait $server_pid || true
trap - EXIT

say "two server instances sharing a session through Redis (network/instances/)"
# Two server instances sharing their sessions through Redis (deploy/README.md): instance a
# defines the session, instance b takes it (mesh included) from the broker; a viewer on b records
# while a director on a changes the style.
inst="$out/network/instances"
mkdir -p "$inst" && rm -rf "${inst:?}/"*
broker_port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
redis-server --port "$broker_port" --bind 127.0.0.1 --save "" --appendonly no > "$inst/redis.log" 2>&1 &
broker_pid=$!
a_pid="" b_pid=""
trap 'kill $broker_pid $a_pid $b_pid 2>/dev/null || true' EXIT
printf '{ "name": "a", "broker": "redis://127.0.0.1:%s", "sessions": [\n  { "name": "shared", "kind": "scene", "style": "comic", "assets": [ { "path": "%s" } ] } ] }\n' \
  "$broker_port" "$here/build/packaged-data/data/meshes/cow.off" > "$inst/a.json"
printf '{ "name": "b", "broker": "redis://127.0.0.1:%s", "sessions": [] }\n' "$broker_port" > "$inst/b.json"
for name in a b; do
  "$bin/inkwire-server" --listen 127.0.0.1:0 --data "$inst/data-$name" --config "$inst/$name.json" 2> "$inst/$name.log" &
  declare "${name}_pid=$!"
  for _ in $(seq 100); do  # serving, and holding the shared session (b: taken from the broker)
    grep -q '"event":"broker-connected"' "$inst/$name.log" && grep -q '"session":"shared"' "$inst/$name.log" && break
    sleep 0.1
  done
  declare "${name}_port=$(sed -n 's/.*"event":"listening".*"port":\([0-9]*\).*/\1/p' "$inst/$name.log")"
done
[ -n "$a_port" ] && [ -n "$b_port" ] || { echo "demo: the two instances did not start" >&2; cat "$inst/"*.log >&2; exit 1; }
"$bin/inkwire-client" --connect "127.0.0.1:$b_port" --headless --cache "$inst/cache-b" --session shared --name viewer-on-b \
  --frames 66 --fps 12 --size 480x360 --out "$inst/viewer-on-b.mp4" 2> "$inst/viewer.log" &
viewer_pid=$!
for style in sketch-pencil painterly comic-extended; do
  sleep 1
  "$bin/inkwire-client" --connect "127.0.0.1:$a_port" --headless --cache "$inst/cache-a" --session shared --name director-on-a \
    --style "$style" --frames 1 --size 320x240 --out "$inst/director-$style.png" 2>> "$inst/director.log"
done
wait $viewer_pid
kill -TERM "$a_pid" "$b_pid" && wait "$a_pid" "$b_pid" || true
kill "$broker_pid" && wait "$broker_pid" || true
trap - EXIT

echo "demo: wrote $out/contact-sheet.png, $out/shade-maps.png, $out/paintings.png, $out/styles/, $out/turntable-*.mp4, $out/painted-video.mp4, $out/tween-methods.png, $out/tween/, $out/conference/ (input | reconstruction | painted, with bytes sent in the .json) and $out/network/ (viewer.mp4: a shared session followed over the network; turntable.mp4 and duck-product.mp4: products turned by a customer, every in-between view synthesised, duck-product-zoomed.mp4 zoomed in on its finer photos; $out/web/: the product, the conference and the shared scene (scene.mp4) in a browser; conference.mp4 and conference-painted.mp4: a speaker's face rebuilt from expression codes; instances/viewer-on-b.mp4: a session shared by two server instances through Redis) and $out/call/call.mp4 (a call between two members, with its sound)"
