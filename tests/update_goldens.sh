#!/usr/bin/env bash
# Regenerates the golden images of the snapshot tests. Run it only on purpose, after looking at
# the new pictures (a failing snapshot test never rewrites them):
#   cmake --build build --target update-goldens
# Usage: tests/update_goldens.sh LUZ_BINARY
set -euo pipefail
luz=${1:?usage: $0 LUZ_BINARY}
root=$(cd "$(dirname "$0")/.." && pwd)
golden="$root/tests/data/golden"
mkdir -p "$golden"
# Keep this list in step with kScenes, kModels and kEffectFlags in tests/test_snapshots.cpp.
for scene in cornell_box phong_spheres whitted local_effects; do
  size=160x120
  [ "$scene" = cornell_box ] && size=120x120
  for model in flat gouraud phong; do
    "$luz" render "$root/scenes/$scene.gltf" --model "$model" --size "$size" -q \
      --out "$golden/$scene-$model.png"
  done
done
# The Whitted tracer (kTracedScenes in tests/test_snapshots.cpp), default settings.
for scene in whitted cornell_box cornell_spheres; do
  size=160x120
  [ "$scene" = cornell_box ] || [ "$scene" = cornell_spheres ] && size=120x120
  "$luz" render "$root/scenes/$scene.gltf" --model whitted --size "$size" -q \
    --out "$golden/$scene-whitted.png"
done
# The plate with every switch of slide 19 on.
for model in flat gouraud phong; do
  "$luz" render "$root/scenes/local_effects.gltf" --model "$model" --size 160x120 -q \
    --shadows --transparency --reflection-map --fog linear --fog-near 6 --fog-far 24 \
    --out "$golden/local_effects-$model-effects.png"
done
# Radiosity: the flags of radiosity_flags() in tests/test_snapshots.cpp.
"$luz" render "$root/scenes/cornell_box.gltf" --model radiosity --size 120x120 -q \
  --patch-size 0.1 --hemicube-res 64 --out "$golden/cornell_box-radiosity.png"
"$luz" render "$root/scenes/phong_spheres.gltf" --model radiosity --size 160x120 -q \
  --patch-size 0.1 --hemicube-res 64 --out "$golden/phong_spheres-radiosity.png"
"$luz" render "$root/scenes/whitted.gltf" --model radiosity --size 160x120 -q \
  --patch-size 0.25 --hemicube-res 64 --converge 0.02 --out "$golden/whitted-radiosity.png"
"$luz" render "$root/scenes/cornell_spheres.gltf" --model radiosity --size 120x120 -q \
  --patch-size 0.12 --hemicube-res 64 --converge 0.02 --out "$golden/cornell_spheres-radiosity.png"
# The hybrid (HybridSnapshot in tests/test_snapshots.cpp): the radiosity flags, tracer defaults.
"$luz" render "$root/scenes/cornell_spheres.gltf" --model hybrid --size 120x120 -q \
  --patch-size 0.12 --hemicube-res 64 --converge 0.02 --out "$golden/cornell_spheres-hybrid.png"
echo "goldens written to $golden"
