#!/bin/sh
# The student's own scene in the page: a .glb given through the file input, and a .gltf with its
# buffer and texture (and one naming its texture in a folder, given without it), draw as `luz
# render` draws the same file (within page_matches_render.sh's 1%, for its reasons); the .gltf
# without its buffer, and a .glb cut short, do not load, and the page says why in its language,
# naming the file (the scene shown stays); a .glb dropped on the canvas loads; the page's buttons
# download the picture (the same PNG as luz.picture()) and the picture with the panel (a PNG of
# the canvas's size). The files are assimp-testmodels' (./setup.sh installs them).
#   tests/web/page_files_match_render.sh BASE_URL LUZ SCRATCH_DIR   (NODE_PATH=build-web/npm/node_modules)
set -eu
base=$1 luz=$2 scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
models=/usr/share/assimp/models/glTF2
glb=$models/BoxTextured-glTF-Binary/BoxTextured.glb
gltf=$models/BoxTextured-glTF
size=320x240
limit=1
mkdir -p "$scratch"
status=0
s=$scratch/files
head -c 1000 "$glb" >"${s}_cut_short.glb"
# The same .gltf naming its texture in a folder beside it, as Blender's exporter can: the file
# picker gives the texture without its folder.
sed 's#"CesiumLogoFlat.png"#"textures/CesiumLogoFlat.png"#' "$gltf/BoxTextured.gltf" >"${s}_folders.gltf"

node "$here/page_files.mjs" "$base?scene=cornell_box&size=$size&lang=es" "${s}_downloads" \
  open "$glb" "${s}_glb_page.png" \
  open "$gltf/BoxTextured.gltf,$gltf/BoxTextured0.bin,$gltf/CesiumLogoFlat.png" "${s}_gltf_page.png" \
  open "${s}_folders.gltf,$gltf/BoxTextured0.bin,$gltf/CesiumLogoFlat.png" "${s}_folders_page.png" \
  refuse "$gltf/BoxTextured.gltf" "BoxTextured.gltf,BoxTextured0.bin,la escena no se ha cargado" \
  refuse "${s}_cut_short.glb" "files_cut_short.glb" \
  drop "$glb" BoxTextured.glb \
  download save-picture picture picture \
  download save-page canvas canvas || status=1

"$luz" render "$glb" --model phong --size $size --out "${s}_glb_render.png" -q
"$luz" render "$gltf/BoxTextured.gltf" --model phong --size $size --out "${s}_gltf_render.png" -q
cp "${s}_gltf_render.png" "${s}_folders_render.png"  # the same scene
for kind in glb gltf folders; do
  percent=$("$luz" compare "${s}_${kind}_page.png" "${s}_${kind}_render.png" |
            sed -n 's/^mean relative error over lit pixels: .*(\([0-9.]*\)%.*/\1/p')
  verdict=$(awk -v p="$percent" -v l="$limit" 'BEGIN { print (p != "" && p + 0 <= l + 0) ? "ok" : "FAILED" }')
  echo "the $kind given to the page against luz render: mean relative error over lit pixels $percent% (limit $limit%): $verdict"
  [ "$verdict" = ok ] || status=1
done
exit $status
