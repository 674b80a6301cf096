#!/usr/bin/env bash
# The README's pictures, made by `luz render` from the shipped scenes, and the viewer's
# (docs/make_viewer_picture.sh).
# Usage: docs/make_pictures.sh [LUZ_BINARY]   (default: build/luz)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
luz=${1:-$root/build/luz}
case $luz in /*) ;; */*) luz=$PWD/$luz ;; esac  # the viewer's script runs in another folder
out="$root/docs/images"
mkdir -p "$out"
for model in flat gouraud phong; do
  "$luz" render "$root/scenes/cornell_box.gltf" --model "$model" --size 360x360 -q --out "$out/cornell_box-$model.png"
  "$luz" render "$root/scenes/phong_spheres.gltf" --model "$model" --size 480x360 -q --out "$out/phong_spheres-$model.png"
done
"$luz" render "$root/scenes/whitted.gltf" --model phong --size 480x360 -q --out "$out/whitted-phong.png"
"$luz" render "$root/scenes/phong_spheres.gltf" --model phong --blinn --size 480x360 -q --out "$out/phong_spheres-blinn.png"
"$luz" render "$root/scenes/phong_spheres.gltf" --model phong --no-specular --size 480x360 -q --out "$out/phong_spheres-no-specular.png"
# The Whitted tracer: Whitted's scene (4 samples per pixel), with Fresnel, at depth 1 (the local
# model with shadows), and the Cornell box with hard (centroid) and soft (16 samples) shadows.
"$luz" render "$root/scenes/whitted.gltf" --model whitted --spp 4 --size 480x360 -q --out "$out/whitted-whitted.png"
"$luz" render "$root/scenes/whitted.gltf" --model whitted --spp 4 --fresnel --size 480x360 -q --out "$out/whitted-fresnel.png"
"$luz" render "$root/scenes/whitted.gltf" --model whitted --spp 4 --depth 1 --size 480x360 -q --out "$out/whitted-depth1.png"
"$luz" render "$root/scenes/cornell_box.gltf" --model whitted --spp 4 --size 360x360 -q --out "$out/cornell_box-whitted.png"
"$luz" render "$root/scenes/cornell_box.gltf" --model whitted --spp 4 --light-samples 16 --size 360x360 -q --out "$out/cornell_box-whitted-soft.png"
# Slide 19's other possibilities on scenes/local_effects.gltf, one switch at a time, then all.
plate="$root/scenes/local_effects.gltf"
fog=(--fog linear --fog-near 6 --fog-far 24)
"$luz" render "$plate" --model phong --size 480x360 -q --out "$out/local_effects-plain.png"
"$luz" render "$plate" --model phong --size 480x360 -q "${fog[@]}" --out "$out/local_effects-fog.png"
"$luz" render "$plate" --model phong --size 480x360 -q --shadows --out "$out/local_effects-shadows.png"
"$luz" render "$plate" --model phong --size 480x360 -q --transparency --out "$out/local_effects-transparency.png"
"$luz" render "$plate" --model phong --size 480x360 -q --reflection-map --out "$out/local_effects-reflection.png"
for model in flat gouraud phong; do
  "$luz" render "$plate" --model "$model" --size 480x360 -q --shadows --transparency --reflection-map "${fog[@]}" \
    --out "$out/local_effects-all-$model.png"
done
"$luz" render "$root/scenes/cornell_box.gltf" --model phong --size 360x360 -q --shadows --out "$out/cornell_box-shadows.png"
"$luz" render "$root/scenes/whitted.gltf" --model phong --size 480x360 -q --shadows --reflection-map --transparency \
  --out "$out/whitted-effects.png"
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
# Whitted's scene at the radiosity defaults and with finer elements (docs/radiosity-meshing.md).
"$luz" render "$root/scenes/whitted.gltf" --model radiosity --size 480x360 -q \
  --out "$out/whitted-radiosity-elements4.png"
"$luz" render "$root/scenes/whitted.gltf" --model radiosity --elements 8 --size 480x360 -q \
  --out "$out/whitted-radiosity-elements8.png"
# The hybrid (slides 41-43) on the Cornell spheres, beside radiosity and Whitted alone; the
# radiosity solution is the same in the first and the last (3000 patches, 1% unshot).
spheres="$root/scenes/cornell_spheres.gltf"
"$luz" render "$spheres" --model radiosity --size 360x360 -q --out "$out/cornell_spheres-radiosity.png"
"$luz" render "$spheres" --model whitted --spp 4 --fresnel --size 360x360 -q --out "$out/cornell_spheres-whitted.png"
"$luz" render "$spheres" --model hybrid --spp 4 --fresnel --size 360x360 -q --out "$out/cornell_spheres-hybrid.png"
# Slide 36: the four solvers' curves on the Cornell box (400 patches, 20 sweeps' worth of rows).
"$luz" solvers "$root/scenes/cornell_box.gltf" -q --csv "$out/solvers-cornell_box.csv" \
  --png "$out/solvers-cornell_box.png"
"$root/docs/make_viewer_picture.sh" "$luz"
echo "pictures in $out"
