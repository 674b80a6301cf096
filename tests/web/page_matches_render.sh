#!/bin/sh
# The page's picture (window.luz.picture()) against `luz render` of the same scene, model and size,
# for each local model the page draws on each shipped scene. The two come from different
# rasterizers (Chromium's SwiftShader, Mesa's llvmpipe) and meet as 8-bit sRGB PNGs: pixels on a
# silhouette may fall on either side of an edge, and scattered pixels differ by one 8-bit step,
# which on a dark pixel (the Cornell spheres' ceiling) is a relative error of several percent. So
# they must agree within a mean relative error of 1% over the lit pixels (measured: 0.04-0.53%).
# A missing term, a wrong exposure or a missing sRGB curve moves every lit pixel by far more
# (the page's Gouraud against `luz render`'s Phong on the Cornell spheres: 42%).
#   tests/web/page_matches_render.sh BASE_URL LUZ SCRATCH_DIR   (BASE_URL: .../luz.html, served)
#   NODE_PATH=build-web/npm/node_modules
set -eu
base=$1 luz=$2 scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
size=${LUZ_WEB_SIZE:-320x240}
limit=1
mkdir -p "$scratch"
status=0
for scene in cornell_box whitted phong_spheres local_effects cornell_spheres; do
  for model in gouraud phong; do
    page="$scratch/${scene}_${model}_page.png" native="$scratch/${scene}_${model}_render.png"
    node "$here/page_api.mjs" "$base?scene=$scene&model=$model&size=$size" "$page" >/dev/null
    "$luz" render "$(dirname "$here")/../scenes/$scene.gltf" --model "$model" --size "$size" --out "$native" >/dev/null
    percent=$("$luz" compare "$page" "$native" | sed -n 's/^mean relative error over lit pixels: .*(\([0-9.]*\)%.*/\1/p')
    verdict=$(awk -v p="$percent" -v l="$limit" 'BEGIN { print (p != "" && p + 0 <= l + 0) ? "ok" : "FAILED" }')
    echo "$scene $model $size: mean relative error over lit pixels $percent% (limit $limit%): $verdict"
    [ "$verdict" = ok ] || status=1
  done
done
exit $status
