#!/bin/sh
# The one-thread page (luz-1thread.js: where the page cannot be cross-origin isolated, docs/web.md
# "Threads") in a browser without service workers, served without the isolation headers:
# - Phong on the Cornell box against `luz render`, within page_matches_render.sh's 1%;
# - the page stays live while it traces on its one thread: Whitted's scene at 1024x1024 and 4
#   samples a pixel, which takes several seconds there, traced a few tiles a frame, the browser's frames coming at most a second
#   apart (a trace run within one frame leaves a gap of its whole length), the trace still
#   running after two seconds of them, then cancelled at once (Backspace's line);
# - Whitted, radiosity, the hybrid and the path tracer against `luz render`, as
#   page_tracers_match_render.sh holds the threaded page to it, with its limits: the same
#   script, on the one-thread page.
#   tests/web/page_one_thread_matches_render.sh BASE_URL LUZ SCRATCH_DIR
#   (BASE_URL: .../luz.html served without the headers; NODE_PATH=build-web/npm/node_modules)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
. "$here/compare_pictures.sh"
export LUZ_PAGE_NO_SERVICE_WORKERS=1

s=$scratch/phong
rm -f "$s"_*.png  # a page that fails to write one must not be judged by an older run's
node "$here/page_api.mjs" "$base?scene=cornell_box&model=phong&size=320x240" "${s}_page.png" || status=1
"$luz" render "$scenes/cornell_box.gltf" --model phong --size 320x240 --out "${s}_render.png" -q
within "${s}_page.png" "${s}_render.png" 1 "one thread: phong in the page against luz render --model phong"

node "$here/page_script.mjs" "$base?scene=whitted&model=whitted&size=1024x1024&panel=0" \
  run "set spp 4" live "trace --no-wait" 2 1000 trace-state tracing run "cancel-trace" trace-state raster || status=1

sh "$here/page_tracers_match_render.sh" "$base" "$luz" "$scratch" || status=1
exit $status
