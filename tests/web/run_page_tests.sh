#!/bin/sh
# The page's tests in headless Chromium (./setup.sh web test runs them): build-web/ served from
# 127.0.0.1 with the isolation headers (on LUZ_WEB_PORT), and the page's files alone served as a
# static host would, without them (on the next port). The page draws (page_smoke), isolated by
# the headers or by its service worker, and says why in words where it can be neither
# (page_isolation); a bad scene is a sentence on the page in its language and so is an unknown
# effect (page_api --expect-error); each scene and model matches `luz render`
# (page_matches_render), and so do the pictures after lines run through window.luz.run, which
# rejects lines it cannot run (page_run_matches_render); the student's own .glb and .gltf given
# through the file input draw as `luz render` draws them, a broken one is refused with the
# loader's words naming it, and the screenshot buttons download PNGs (page_files_match_render);
# the canvas follows the browser's window, luz.picture() leaves no note, Esc ends nothing and
# radiosity's outlines are the window's (page_script, outlines_match); Whitted, radiosity, the
# hybrid and the path tracer match `luz render` once their work is done
# (page_tracers_match_render); the clicked pixel's ray tree, brute force, adaptive sampling and
# meshing, the item buffer, slide 36's solvers, the lesson's panes and the difference view are
# what the `luz` commands compute (page_views_match_cli), and the lesson walks to its end in
# Spanish from its first step and in English from step 54 (page_lesson). Pictures and screenshots are left in SCRATCH_DIR.
#   tests/web/run_page_tests.sh BUILD_WEB LUZ SCRATCH_DIR
set -eu
web=$1 luz=$2 scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
port=${LUZ_WEB_PORT:-8765}
export NODE_PATH="$web/npm/node_modules"
mkdir -p "$scratch"
# A scene the page fetches by its URL, as a teacher's would be: a shipped one, served beside it.
mkdir -p "$web/test-scenes"
cp "$(dirname "$(dirname "$here")")/scenes/whitted.gltf" "$(dirname "$(dirname "$here")")/scenes/whitted.bin" "$web/test-scenes/"
serve=$(dirname "$(dirname "$here")")/src/app/web/serve.py
python3 "$serve" "$web" "$port" >"$scratch/server.log" 2>&1 &
server=$!
# The page as docs/web.md says to put it on a static host: its six files alone, in a folder of
# their own, served by a plain file server that sends no isolation headers (the page's service
# worker adds them).
site=$scratch/static-site
rm -rf "$site" && mkdir -p "$site"
for file in luz.html luz.js luz.wasm luz.worker.js luz.data coi-serviceworker.js; do cp "$web/$file" "$site/"; done
python3 -m http.server "$((port + 1))" --bind 127.0.0.1 --directory "$site" >"$scratch/server_plain.log" 2>&1 &
plain=$!
trap 'kill $server $plain 2>/dev/null' EXIT INT TERM
sleep 1
url=http://127.0.0.1:$port/luz.html
plain_url=http://127.0.0.1:$((port + 1))/luz.html
status=0
node "$here/page_smoke.mjs" "$url" "$scratch/page.png" "$scratch/canvas.png" || status=1
node "$here/page_isolation.mjs" headers "$url" "$scratch/isolated_headers.png" || status=1
node "$here/page_isolation.mjs" service-worker "$plain_url" "$scratch/isolated_service_worker.png" || status=1
node "$here/page_isolation.mjs" refused "$plain_url" "$scratch/not_isolated.png" || status=1
node "$here/page_api.mjs" --expect-error "$url?scene=nope&lang=es" "$scratch/error_es.png" || status=1
node "$here/page_api.mjs" --expect-error "$url?effects=shadows,sparkle&lang=en" "$scratch/error_effects.png" || status=1
# Without size= the canvas follows the browser's window (the picture as wide as the canvas with
# panel=0); luz.picture() leaves no "saved" note, a user's screenshot does; Esc ends nothing (a
# page whose program ended answers no run() again).
node "$here/page_script.mjs" "$url?panel=0" fills picture-width 800 viewport 1000x500 fills picture-width 1000 \
  width 1000 || status=1
node "$here/page_script.mjs" "$url?size=320x240" picture "$scratch/quiet.png" note-lacks luz-picture \
  run "screenshot /tmp/shot.png" note-has "saved /tmp/shot.png" run "key esc" run "wait 3" || status=1
# Radiosity's patch outlines: the page's where the window's are (uniform patches, so that both
# meshes are the same whatever the solution reached).
node "$here/page_script.mjs" "$url?scene=cornell_box&model=radiosity&size=640x480&panel=0" \
  run "radiosity patch-size 0.6" run "radiosity meshing uniform" run "wait-shots 10" run "radiosity pause" \
  run "radiosity flat-patches on" run "radiosity outlines off" picture "$scratch/outlines_off.png" \
  run "radiosity outlines on" picture "$scratch/outlines_on.png" || status=1
for outlines in "" --outlines; do
  "$luz" render "$(dirname "$(dirname "$here")")/scenes/cornell_box.gltf" --model radiosity --size 640x480 \
    --patch-size 0.6 --meshing uniform --flat-patches $outlines --out "$scratch/luz_outlines${outlines}.png" >/dev/null || status=1
done
node "$here/outlines_match.mjs" "$scratch/outlines_off.png" "$scratch/outlines_on.png" "$scratch/luz_outlines.png" \
  "$scratch/luz_outlines--outlines.png" || status=1
sh "$here/page_matches_render.sh" "$url" "$luz" "$scratch" || status=1
sh "$here/page_run_matches_render.sh" "$url" "$luz" "$scratch" || status=1
sh "$here/page_files_match_render.sh" "$url" "$luz" "$scratch" || status=1
sh "$here/page_tracers_match_render.sh" "$url" "$luz" "$scratch" || status=1
sh "$here/page_views_match_cli.sh" "$url" "$luz" "$scratch" || status=1
lesson="$(dirname "$(dirname "$here")")/lessons/sintesis.json"
node "$here/page_lesson.mjs" "$url?lesson=1&lang=es&size=240x180" "$lesson" "$scratch/lesson_es" || status=1
node "$here/page_lesson.mjs" "$url?lesson=54&lang=en&size=240x180" "$lesson" "$scratch/lesson_en" || status=1
[ $status -eq 0 ] && echo "page tests: all passed ($scratch)" || echo "page tests: FAILED ($scratch)"
exit $status
