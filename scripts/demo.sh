#!/usr/bin/env bash
# The demo: installs what is missing, builds, and renders packaged models in every registered
# style into a gallery, plus turntable videos.
#   scripts/demo.sh [OUT_DIR]      (default: demo-output/)
# Writes OUT_DIR/contact-sheet.png (models x styles), OUT_DIR/styles/<model>-<style>.png,
# OUT_DIR/shade-maps.png (the comic shade-map library on one model) and
# OUT_DIR/turntable-<style>.mp4.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$here/demo-output}")
"$here/scripts/setup.sh"

bin="$here/build/bin"
meshes="$here/build/packaged-data/data/meshes"
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

for style in "${styles[@]}"; do
  "$bin/inkwire-render" --mesh "$meshes/cow.off" --style "$style" --view 35,15,1.3 --size 640x480 \
    --frames 96 --out "$out/turntable-$style.mp4"
done

echo "demo: wrote $out/contact-sheet.png, $out/shade-maps.png, $out/styles/ and $out/turntable-*.mp4"
