#!/usr/bin/env bash
# The README's picture of the viewer, made by a scripted run of the viewer itself
# (docs/viewer_picture.txt): in a 1280x760 window, under Xvfb when there is no display.
# Usage: docs/make_viewer_picture.sh [LUZ_BINARY]   (default: build/luz)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
luz=${1:-$root/build/luz}
out="$root/docs/images"
mkdir -p "$out"
cd "$out"
run=("$luz" --script "$root/docs/viewer_picture.txt" --size 1280x760 "$root/scenes/cornell_box.gltf")
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  "${run[@]}"
else
  # Mesa's software GL: the same picture on every machine. -noreset: luz checks the display
  # (one connection) before opening its window (another); a reset between them would fail it.
  LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1600x1200x24 -noreset" "${run[@]}"
fi
echo "picture in $out/viewer.png"
