#!/usr/bin/env bash
# The README's pictures of the web page: the page as a browser shows it, 1280x720, the panel
# beside the picture, one per model on a scene that suits it (Phong on the spheres, Whitted's
# scene traced with a pixel's ray tree, radiosity spreading in the Cornell box with its item
# buffer, the hybrid on the Cornell spheres, the path tracer on the Cornell box), and the lesson
# in Spanish at slide 44's four panes. Headless Chromium drives the page through window.luz, as
# its tests do (tests/web/page_script.mjs); each picture is then reduced to 256 colours
# (docs/png_palette.mjs), which keeps it small.
# Usage: docs/make_page_pictures.sh [BUILD_WEB] [PORT]   (default: build-web, 8431; after ./setup.sh web)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
web=${1:-$root/build-web}
port=${2:-8431}
out="$root/docs/images"
mkdir -p "$out"
export NODE_PATH="$web/npm/node_modules"
python3 "$root/src/app/web/serve.py" "$web" "$port" >/dev/null 2>&1 &
server=$!
trap 'kill $server 2>/dev/null' EXIT INT TERM
sleep 1
url="http://127.0.0.1:$port/luz.html"
shot() {  # shot NAME QUERY STEP...: the page at 1280x720 after the steps, as docs/images/page-NAME.png
  local name=$1 query=$2
  shift 2
  node "$root/tests/web/page_script.mjs" "$url?$query" viewport 1280x720 "$@" shot "$out/page-$name.png" \
    >"$out/page-$name.log" 2>&1 || { grep -v '^page:' "$out/page-$name.log"; exit 1; }
  rm "$out/page-$name.log"
  node "$root/docs/png_palette.mjs" "$out/page-$name.png"
}
shot phong "scene=phong_spheres&model=phong&lang=en" run "click-picture 70% 15%" run "wait 1s"
shot whitted "scene=whitted&model=whitted&lang=en" run "trace" run "click-picture 30% 45%" run "wait 1s"
shot radiosity "scene=cornell_box&model=radiosity&lang=en" run "radiosity patch-size 0.15" run "wait-shots 150"
# The hybrid's solve and the path tracer's passes in steps, each within page_script's minute.
solve=()
for shots in 300 600 900 1200 1500 1800 2100 2400; do solve+=(run "wait-shots $shots"); done
shot hybrid "scene=cornell_spheres&model=hybrid&lang=en" run "radiosity patch-size 0.25" run "radiosity budget 500" \
  "${solve[@]}" run "trace"
shot path "scene=cornell_box&model=path&lang=en" run "path spp 16" run "wait-path 4" run "wait-path 8" run "wait-path 12" \
  run "wait-path 16"
shot lesson-es "lesson=58&lang=es" run "lesson goto 58" run "wait-until trace-done 3000"
echo "pictures in $out: page-phong.png, page-whitted.png, page-radiosity.png, page-hybrid.png, page-path.png, page-lesson-es.png"
