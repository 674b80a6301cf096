#!/usr/bin/env bash
# The README's pictures of the viewer, made by scripted runs of the viewer itself: the Cornell
# box (docs/viewer_picture.txt), a ray tree over Whitted's scene
# (docs/whitted_viewer_picture.txt) and radiosity spreading in the Cornell box
# (docs/radiosity_viewer_picture.txt), the hybrid traced over radiosity
# (docs/hybrid_viewer_picture.txt) and slide 36's window of solvers
# (docs/solvers_viewer_picture.txt), in a 1280x760 window, under Xvfb when there is no display.
# Usage: docs/make_viewer_picture.sh [LUZ_BINARY]   (default: build/luz)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
luz=${1:-$root/build/luz}
out="$root/docs/images"
mkdir -p "$out"
cd "$out"
run() {  # run SCRIPT SCENE
  local args=("$luz" --script "$root/docs/$1" --size 1280x760 "$root/scenes/$2")
  if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
    "${args[@]}"
  else
    # Mesa's software GL: the same picture on every machine. -noreset: luz checks the display
    # (one connection) before opening its window (another); a reset between them would fail it.
    LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1600x1200x24 -noreset" "${args[@]}"
  fi
}
run viewer_picture.txt cornell_box.gltf
run whitted_viewer_picture.txt whitted.gltf
run radiosity_viewer_picture.txt cornell_box.gltf
run hybrid_viewer_picture.txt cornell_spheres.gltf
run solvers_viewer_picture.txt cornell_box.gltf
echo "pictures in $out: viewer.png, whitted-ray-tree.png, radiosity-viewer.png, hybrid-viewer.png, solvers-viewer.png"
