#!/bin/sh
# window.luz.run in the page against `luz render`: a switch of slide 19 and a model changed
# through run() change the page's picture as the matching flag changes `luz render`'s (within the
# 1% of page_matches_render.sh, and for the same reasons); the picture before the switch matches
# the render without the flag and is more than 1% away from the one with it, so a run() that
# did nothing fails. run() of a line the script language does not know, and of a line that
# cannot be done, rejects with the message. panel=0 shows the picture alone. A scene by its URL
# draws as the file does.
#   tests/web/page_run_matches_render.sh BASE_URL LUZ SCRATCH_DIR   (NODE_PATH=build-web/npm/node_modules)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/compare_pictures.sh"
size=320x240
limit=1

# Phong's specular term switched off through run(), as --no-specular.
s=$scratch/run_specular
rm -f "$s"_*.png  # a page that fails to write one must not be judged by an older run's
node "$here/page_script.mjs" "$base?scene=phong_spheres&model=phong&size=$size" \
  picture "${s}_before.png" run "set specular off" picture "${s}_page.png" shot "${s}_shot.png" || status=1
"$luz" render "$scenes/phong_spheres.gltf" --model phong --size $size --out "${s}_on.png" -q
"$luz" render "$scenes/phong_spheres.gltf" --model phong --size $size --no-specular --out "${s}_off.png" -q
within "${s}_before.png" "${s}_on.png" "$limit" "phong_spheres, specular on, before run()"
within "${s}_page.png" "${s}_off.png" "$limit" "run(\"set specular off\") against --no-specular"
apart "${s}_before.png" "${s}_off.png" "$limit" "phong_spheres with the specular term against without"

# The model changed through run(), as --model.
s=$scratch/run_model
rm -f "$s"_*.png
node "$here/page_script.mjs" "$base?scene=cornell_box&model=phong&size=$size&lang=es" \
  run "model gouraud" picture "${s}_page.png" shot "${s}_shot_es.png" || status=1
"$luz" render "$scenes/cornell_box.gltf" --model gouraud --size $size --out "${s}_render.png" -q
within "${s}_page.png" "${s}_render.png" "$limit" "run(\"model gouraud\") against --model gouraud"

# Lines run() must refuse, with the script language's messages.
node "$here/page_script.mjs" "$base?scene=cornell_box&size=$size" \
  reject "frobnicate 3" 'unknown command "frobnicate"' \
  reject "camera nowhere" 'the scene has no camera "nowhere"' \
  run "camera 0" || status=1

# panel=0: the picture alone, as luz render draws it.
s=$scratch/no_panel
rm -f "$s"_*.png
node "$here/page_script.mjs" "$base?scene=whitted&model=phong&size=$size&panel=0" \
  width 320 picture "${s}_page.png" shot "${s}_shot.png" || status=1
"$luz" render "$scenes/whitted.gltf" --model phong --size $size --out "${s}_render.png" -q
within "${s}_page.png" "${s}_render.png" "$limit" "panel=0 against luz render"
# A scene by its URL (run_page_tests.sh serves whitted.gltf and its .bin in test-scenes/): the
# page fetches the .gltf and the buffer it names, and draws what luz render draws of the file.
s=$scratch/by_url
rm -f "$s"_*.png
node "$here/page_script.mjs" "$base?scene=test-scenes/whitted.gltf&model=gouraud&size=$size" \
  picture "${s}_page.png" || status=1
"$luz" render "$scenes/whitted.gltf" --model gouraud --size $size --out "${s}_render.png" -q
within "${s}_page.png" "${s}_render.png" "$limit" "scene=test-scenes/whitted.gltf against luz render"
exit $status
