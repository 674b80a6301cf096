#!/bin/sh
# The page's picture (window.luz.picture()) against `luz render` of the same scene, model, size and
# slide-19 switches: each local model on each shipped scene, then shadows (shadow maps) and glass
# (transparency: dual-source blending on the desktop, two draws in the page) on the scenes that
# have them. The two come from different rasterizers (Chromium's SwiftShader, Mesa's llvmpipe)
# and meet as 8-bit sRGB PNGs: pixels on a silhouette may fall on either side of an edge, and
# scattered pixels differ by one 8-bit step, which on a dark pixel (the Cornell spheres' ceiling)
# is a relative error of several percent. So they must agree within a mean relative error of 1%
# over the lit pixels (measured: 0.04-0.53%). A missing term, a wrong exposure or a missing sRGB
# curve moves every lit pixel by far more (the page's Gouraud against `luz render`'s Phong on the
# Cornell spheres: 42%), and so do a shadow or a pane of glass that is not drawn.
#   tests/web/page_matches_render.sh BASE_URL LUZ SCRATCH_DIR   (BASE_URL: .../luz.html, served)
#   NODE_PATH=build-web/npm/node_modules
set -eu
base=$1 luz=$2 scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
size=${LUZ_WEB_SIZE:-320x240}
limit=1
mkdir -p "$scratch"
status=0
# One case a line: scene, model, the page's effects= (the `luz render` flags of those names), or -.
cases=$(for scene in cornell_box whitted phong_spheres local_effects cornell_spheres; do
          for model in flat gouraud phong; do echo "$scene $model -"; done
        done
        echo "local_effects phong shadows,transparency"
        echo "local_effects flat shadows,transparency"
        echo "whitted phong shadows,transparency"
        echo "cornell_spheres gouraud shadows,transparency"
        echo "cornell_box phong shadows")
while read -r scene model effects; do
  name="${scene}_${model}" query="scene=$scene&model=$model&size=$size" flags=""
  if [ "$effects" != - ]; then
    name="${name}_$(echo "$effects" | tr , _)" query="$query&effects=$effects"
    flags=$(echo "$effects" | sed 's/^/--/; s/,/ --/g')
  fi
  page="$scratch/${name}_page.png" native="$scratch/${name}_render.png"
  node "$here/page_api.mjs" "$base?$query" "$page" >/dev/null </dev/null
  # shellcheck disable=SC2086  # the flags are words
  "$luz" render "$(dirname "$here")/../scenes/$scene.gltf" --model "$model" --size "$size" $flags --out "$native" >/dev/null </dev/null
  percent=$("$luz" compare "$page" "$native" | sed -n 's/^mean relative error over lit pixels: .*(\([0-9.]*\)%.*/\1/p')
  verdict=$(awk -v p="$percent" -v l="$limit" 'BEGIN { print (p != "" && p + 0 <= l + 0) ? "ok" : "FAILED" }')
  echo "$scene $model ${flags:-(no effects)} $size: mean relative error over lit pixels $percent% (limit $limit%): $verdict"
  [ "$verdict" = ok ] || status=1
done <<EOF
$cases
EOF
exit $status
