#!/usr/bin/env bash
# The README's pictures, made by `luz render` from the shipped scenes.
# Usage: docs/make_pictures.sh [LUZ_BINARY]   (default: build/luz)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
luz=${1:-$root/build/luz}
out="$root/docs/images"
mkdir -p "$out"
for model in flat gouraud phong; do
  "$luz" render "$root/scenes/cornell_box.gltf" --model "$model" --size 360x360 -q --out "$out/cornell_box-$model.png"
  "$luz" render "$root/scenes/phong_spheres.gltf" --model "$model" --size 480x360 -q --out "$out/phong_spheres-$model.png"
done
"$luz" render "$root/scenes/whitted.gltf" --model phong --size 480x360 -q --out "$out/whitted-phong.png"
"$luz" render "$root/scenes/phong_spheres.gltf" --model phong --blinn --size 480x360 -q --out "$out/phong_spheres-blinn.png"
"$luz" render "$root/scenes/phong_spheres.gltf" --model phong --no-specular --size 480x360 -q --out "$out/phong_spheres-no-specular.png"
# Radiosity (slides 29-40): converged, its patches, early with and without Cohen's ambient term.
"$luz" render "$root/scenes/cornell_box.gltf" --model radiosity --size 360x360 -q --out "$out/cornell_box-radiosity.png"
"$luz" render "$root/scenes/cornell_box.gltf" --model radiosity --size 360x360 -q --patch-size 0.05 \
  --flat-patches --outlines --out "$out/cornell_box-radiosity-patches.png"
"$luz" render "$root/scenes/cornell_box.gltf" --model radiosity --size 360x360 -q --shots 300 \
  --out "$out/cornell_box-radiosity-300-shots.png"
"$luz" render "$root/scenes/cornell_box.gltf" --model radiosity --size 360x360 -q --shots 300 \
  --ambient-estimate --out "$out/cornell_box-radiosity-300-shots-ambient.png"
"$luz" render "$root/scenes/whitted.gltf" --model radiosity --size 480x360 -q --patch-size 0.15 \
  --out "$out/whitted-radiosity.png"
"$luz" render "$root/scenes/phong_spheres.gltf" --model radiosity --size 480x360 -q \
  --out "$out/phong_spheres-radiosity.png"
echo "pictures in $out"
