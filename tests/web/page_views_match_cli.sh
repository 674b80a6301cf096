#!/bin/sh
# What the page shows beside its pictures, against the `luz` command that computes the same
# thing headless: the ray tree of a clicked pixel, brute force beside the BVH, Whitted's
# adaptive supersampling, radiosity's adaptive subdivision and its hemicube's item buffer, slide
# 36's solvers window, the lesson's side-by-side panes and the difference view against the path
# tracer. The page's dumps (its script's `dump-...` lines) come out through page_script.mjs's
# `file` step; tests/web/views_match.mjs and ray_tree_match.mjs hold them to the command's.
#
# - The ray tree (whitted.gltf, 480x720, a pixel of the glass sphere): its JSON is `luz render
#   --ray-tree`'s, ray for ray, every number within 1e-5 relative (the page's Embree is built
#   for SSE2, the desktop's for the widest ISA; measured 1e-6); drawn over the picture along its
#   rays and nowhere else (ray_tree_match.mjs); in the panel, its table of five columns and its
#   "clear [X]" button, which clears it (the picture then the traced one without the tree).
# - Brute force (whitted.gltf, 64x48: it tests every ray against all 12,106 triangles): the
#   same rays as the BVH, its tests counted, and the same picture as the page's BVH and `luz
#   render --brute-force` (limit 0.1%, Whitted's; measured 0.00%), its ray tree `luz render
#   --brute-force --ray-tree`'s. The BVH's trace traced `luz render`'s rays, kind for kind
#   (WebAssembly keeps the subnormal light terms that `luz render`'s threads flush to zero:
#   which lights get a shadow ray is told from the terms' factors). Whitted's adaptive supersampling at the same size: `luz render --adaptive`'s
#   picture (limit 0.1%; measured 0.00%; the stratified picture is 10% away).
# - Radiosity (cornell_box.gltf, patches of 0.3 m, 60 shots): with rays for form factors and
#   adaptive subdivision, the page's mesh after the shots is `luz render --shots 60`'s, element
#   for element (the rays are Embree's in both, the solver seeded), its unshot power within
#   0.1% relative (measured 0.00%) and its picture within 1% (measured 0.16%; the shooter's
#   magenta off). With the hemicube's form factors (the item buffers WebGL 2 draws and reads
#   back), the uniform mesh: `luz render --form-factors hemicube`'s unshot power within 1%
#   relative (measured 0.03%) and its picture within 3% (measured 1.5%: two rasterizers draw
#   the hemicubes, SwiftShader and llvmpipe, and a patch on an edge of a hemicube pixel falls
#   either way); the item-buffer window shows the last shooter's hemicube in false colours.
# - Slide 36's solvers window (cornell_box.gltf, the window's defaults, 1200 rows): `luz
#   solvers`'s patches, and each method's residual and error at every row count the CSV has,
#   within 5% relative (measured at most 2.9%: the hemicubes that give visibility are
#   rasterized by SwiftShader in the page and by OSMesa's llvmpipe in the command; at these rows
#   Jacobi's curve is twice Gauss-Seidel's); its plots drawn as the rows go from 0 to 30.
# - The lesson's side-by-side panes (step 58: flat, Gouraud, Phong and Whitted on whitted.gltf,
#   traced), the page opened at the step (`lesson=58`), with size=320x240 and without (the
#   canvas the browser's window): `luz render --model flat,gouraud,phong,whitted`'s grid with
#   its labels, within 1% (the local models' limit; measured 0.20%); the Whitted pane below its
#   label within 0.1% (Whitted's limit; measured 0.00%; untraced, 68% and 78%); one drag moves
#   every pane's camera.
# - The difference view (Whitted against 4 path-traced samples a pixel, seed 7, whitted.gltf at
#   160x120): its figures are `luz compare`'s of `luz render`'s two pictures within what the
#   page's paths change (a path's last bits, another Embree ISA and libm, send it elsewhere:
#   measured 0.0007 of mean relative error, 0.0008 of rel-RMSE, 5e-5 of mean error; two seeds
#   differ by 0.002, 0.004 and 3e-4); limits 0.01, 0.01 and 0.002. Its heat map is `luz compare
#   --heatmap`'s: the same colour where that map is clearly red or blue (limit 95%, measured
#   98%) and 10 codes apart on average at most (measured 4.4; the model's picture instead: 81).
# Broken on purpose in the page's build, each fails: the tree's rays drawn half their length
# (2191 of 2867 points changed), brute force keeping the last hit instead of the nearest (9.4%,
# other rays), adaptive supersampling's threshold 4x (0.67%), adaptive subdivision's 1.5x (3307
# elements), the item buffer naming the next patch (181%), Jacobi gathering from the sweep it
# writes (the page stops), the panes' pictures shifted by one (34%), the difference taken the
# other way round (its signs and its map); the page before its traces followed a resize (the
# step's trace cancelled as the page fitted its canvas: its Whitted pane 68% and 78% away, the
# note "trace cancelled"); `luz render` telling a light's shadow ray from its term's product
# (2131 shadow rays against the page's 2507).
#   tests/web/page_views_match_cli.sh BASE_URL LUZ SCRATCH_DIR   (NODE_PATH=build-web/npm/node_modules)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/compare_pictures.sh"
script() { node "$here/page_script.mjs" "$@" || status=1; }
match() { node "$here/views_match.mjs" "$@" || status=1; }

# The ray tree: traced, a pixel clicked, its tree dumped and drawn, then cleared by the panel's
# button.
s=$scratch/views_tree
rm -f "$s"_*
script "$base?scene=whitted&model=whitted&size=480x720" run "trace" run "click-picture 150 330" \
  run "dump-ray-tree /tmp/tree.json" file /tmp/tree.json "${s}_page.json" \
  run "dump-windows /tmp/windows.json" file /tmp/windows.json "${s}_windows.json" picture "${s}_drawn.png" \
  run "dump-widgets /tmp/widgets.json" file /tmp/widgets.json "${s}_widgets.json" \
  run 'click-widget "clear [X]"' picture "${s}_cleared.png" \
  run "dump-widgets /tmp/widgets.json" file /tmp/widgets.json "${s}_widgets_cleared.json"
"$luz" render "$scenes/whitted.gltf" --model whitted --size 480x720 --ray-tree 150,330 --out "${s}_luz.png" -q
node "$here/ray_tree_match.mjs" "${s}_page.json" "${s}_luz.ray-tree.json" 1e-5 "$scenes/whitted.gltf" \
  "${s}_drawn.png" "${s}_cleared.png" || status=1
within "${s}_cleared.png" "${s}_luz.png" 0.1 "the traced picture once the panel's clear [X] took the tree away"
match ray-tree-panel "${s}_windows.json" "${s}_widgets.json" "${s}_widgets_cleared.json"

# Brute force beside the BVH, then adaptive supersampling (each trace before a click: the tree
# would be drawn over the picture).
s=$scratch/views_brute
rm -f "$s"_*
script "$base?scene=whitted&model=whitted&size=64x48&panel=0" \
  run "trace" picture "${s}_bvh.png" run "dump-trace /tmp/bvh.json" file /tmp/bvh.json "${s}_bvh.json" \
  run "set brute-force on" run "trace" picture "${s}_page.png" run "dump-trace /tmp/brute.json" file /tmp/brute.json "${s}_brute.json" \
  run "click-picture 20 22" run "dump-ray-tree /tmp/tree.json" file /tmp/tree.json "${s}_tree.json" run "key X" \
  run "set brute-force off" run "set adaptive on" run "trace" picture "${s}_adaptive.png"
"$luz" render "$scenes/whitted.gltf" --model whitted --size 64x48 --brute-force --ray-tree 20,22 --out "${s}_luz.png" -q
"$luz" render "$scenes/whitted.gltf" --model whitted --size 64x48 --adaptive --out "${s}_luz_adaptive.png" -q
match brute "${s}_bvh.json" "${s}_brute.json"
"$luz" render "$scenes/whitted.gltf" --model whitted --size 64x48 --out "${s}_luz_bvh.png" >"${s}_luz_bvh.txt" || status=1
match rays "${s}_bvh.json" "${s}_luz_bvh.txt"
within "${s}_page.png" "${s}_bvh.png" 0.1 "brute force in the page against the page's BVH"
within "${s}_page.png" "${s}_luz.png" 0.1 "brute force in the page against luz render --brute-force"
node "$here/ray_tree_match.mjs" "${s}_tree.json" "${s}_luz.ray-tree.json" 1e-5 || status=1
within "${s}_adaptive.png" "${s}_luz_adaptive.png" 0.1 "adaptive supersampling in the page against luz render --adaptive"

# Radiosity: adaptive subdivision with the rays' form factors; the hemicube's, uniform, and its
# item-buffer window. The dump comes after the screenshot, as in tests/viewer/radiosity.txt: a frame
# draws its panel before the solver shoots, so the window's rectangle is that of the last frame
# drawn, the screenshot's. Two frames before it let the window, which sizes itself to what it held
# a frame before, grow around the last shot's hemicube where that was its first.
s=$scratch/views_radiosity
rm -f "$s"_*
script "$base?scene=cornell_box&model=radiosity&size=480x360" \
  run "radiosity patch-size 0.3" run "radiosity hemicube 128" run "radiosity budget 200" \
  run "radiosity form-factors rays" run "radiosity meshing adaptive" run "wait-shots 60" run "radiosity shooter off" \
  run "dump-radiosity /tmp/adaptive.json" file /tmp/adaptive.json "${s}_adaptive.json" picture "${s}_adaptive.png" \
  run "radiosity shooter on" run "radiosity form-factors hemicube" run "radiosity meshing uniform" run "wait-shots 60" \
  run "wait 2" run "screenshot /tmp/panel.png --with-panel" file /tmp/panel.png "${s}_panel.png" \
  run "dump-radiosity /tmp/hemicube.json" file /tmp/hemicube.json "${s}_hemicube.json" \
  run "radiosity shooter off" picture "${s}_hemicube.png"
flags="--model radiosity --patch-size 0.3 --hemicube-res 128 --shots 60 --pixel-samples 1 --size 480x360"
# shellcheck disable=SC2086  # the flags are words
"$luz" render "$scenes/cornell_box.gltf" $flags --form-factors rays --meshing adaptive --out "${s}_luz_adaptive.png" \
  >"${s}_luz_adaptive.txt" || status=1
# shellcheck disable=SC2086
"$luz" render "$scenes/cornell_box.gltf" $flags --form-factors hemicube --meshing uniform --out "${s}_luz_hemicube.png" \
  >"${s}_luz_hemicube.txt" || status=1
match radiosity "${s}_adaptive.json" "${s}_luz_adaptive.txt" adaptive 0.001
within "${s}_adaptive.png" "${s}_luz_adaptive.png" 1 "radiosity's adaptive mesh in the page against luz render --meshing adaptive"
match radiosity "${s}_hemicube.json" "${s}_luz_hemicube.txt" uniform 0.01
within "${s}_hemicube.png" "${s}_luz_hemicube.png" 3 "radiosity's hemicube form factors in the page against luz render --form-factors hemicube"
match item-buffer "${s}_hemicube.json" "${s}_panel.png"

# Slide 36's solvers window: its plots before any row and at 30 rows on a canvas where they show, at
# the default budget (the page steps between its paced frames); then, on a small one and with a
# budget chosen (every step in a drawn frame), its curves to 1200 rows.
s=$scratch/views_solvers
rm -f "$s"_*
script "$base?scene=cornell_box&size=640x600" \
  run "solvers open" run "wait 2s" run "screenshot /tmp/early.png --with-panel" file /tmp/early.png "${s}_early.png" \
  run "wait-solver-rows 30" run "dump-solvers /tmp/plots.json" file /tmp/plots.json "${s}_plots.json" \
  run "screenshot /tmp/later.png --with-panel" file /tmp/later.png "${s}_later.png"
script "$base?scene=cornell_box&size=320x240" run "solvers budget 100" \
  run "wait-solver-rows 1200" run "dump-solvers /tmp/solvers.json" file /tmp/solvers.json "${s}_page.json"
"$luz" solvers "$scenes/cornell_box.gltf" --iterations 4 --csv "${s}_luz.csv" >"${s}_luz.txt" || status=1
match solvers "${s}_page.json" "${s}_luz.csv" "${s}_luz.txt" 0.05
match solver-plots "${s}_plots.json" "${s}_early.png" "${s}_later.png" 30

# The lesson's side-by-side panes at step 58, traced: the page opened at the step, whose trace
# starts while the page fits its canvas to the picture's size (the trace follows it), at the
# size the lesson's caption leaves the picture; then one drag over the picture. The Whitted
# pane alone, below its label, is `luz render --model whitted`'s picture at the pane's size.
s=$scratch/views_panes
rm -f "$s"_*
script "$base?lesson=58&lang=en&size=320x240" run "wait-until trace-done 3000" picture "${s}_page.png" \
  run "dump-panes /tmp/before.json" file /tmp/before.json "${s}_before.json" \
  run "drag 500 100 540 120" run "dump-panes /tmp/after.json" file /tmp/after.json "${s}_after.json"
size_of() { node -e "const b = require('fs').readFileSync(process.argv[1]); console.log(b.readUInt32BE(16) + 'x' + b.readUInt32BE(20))" "$1"; }
size=$(size_of "${s}_page.png" 2>/dev/null || echo 320x240)
"$luz" render "$scenes/whitted.gltf" --model flat,gouraud,phong,whitted --lang en --size "$size" --out "${s}_luz.png" -q
within "${s}_page.png" "${s}_luz.png" 1 "the lesson's four panes in the page against luz render --model flat,gouraud,phong,whitted"
match panes "${s}_before.json" "${s}_after.json"
node "$here/cut_pane.mjs" "${s}_before.json" whitted "${s}_page.png" "${s}_page_whitted.png" &&
  node "$here/cut_pane.mjs" "${s}_before.json" whitted "${s}_luz.png" "${s}_luz_whitted.png" || status=1
within "${s}_page_whitted.png" "${s}_luz_whitted.png" 0.1 "the lesson's Whitted pane in the page against luz render's"

# The same step from a link with no size= (the canvas takes the browser's window): the Whitted
# pane traced at the size the page settles on.
s=$scratch/views_panes_window
rm -f "$s"_*
script "$base?lesson=58&lang=en" run "wait-until trace-done 3000" picture "${s}_page.png" \
  run "dump-panes /tmp/panes.json" file /tmp/panes.json "${s}_panes.json" note-lacks "trace cancelled"
size=$(size_of "${s}_page.png" 2>/dev/null || echo 800x600)
"$luz" render "$scenes/whitted.gltf" --model flat,gouraud,phong,whitted --lang en --size "$size" --out "${s}_luz.png" -q
node "$here/cut_pane.mjs" "${s}_panes.json" whitted "${s}_page.png" "${s}_page_whitted.png" &&
  node "$here/cut_pane.mjs" "${s}_panes.json" whitted "${s}_luz.png" "${s}_luz_whitted.png" || status=1
within "${s}_page_whitted.png" "${s}_luz_whitted.png" 0.1 "the lesson's Whitted pane, opened by a link without size=, against luz render's"

# The difference view: Whitted traced, against 4 samples of the path tracer of seed 7.
s=$scratch/views_difference
rm -f "$s"_*
script "$base?scene=whitted&model=whitted&size=160x120&panel=0" run "path spp 4" run "path seed 7" run "trace" \
  run "difference on" run "wait-path" run "dump-difference /tmp/difference.json" file /tmp/difference.json "${s}_page.json" \
  picture "${s}_page.png"
"$luz" render "$scenes/whitted.gltf" --model whitted --size 160x120 --out "${s}_whitted.exr" -q
"$luz" render "$scenes/whitted.gltf" --model path --spp 4 --seed 7 --size 160x120 --out "${s}_path.exr" -q
"$luz" compare "${s}_whitted.exr" "${s}_path.exr" --heatmap "${s}_luz.png" >"${s}_luz.txt" || status=1
match difference "${s}_page.json" "${s}_luz.txt" "${s}_page.png" "${s}_luz.png"
exit $status
