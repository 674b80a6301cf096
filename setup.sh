#!/usr/bin/env bash
# Luz on a fresh Debian (bookworm or later): installs the Debian packages that are missing,
# builds (Release) into build/, then
#   ./setup.sh [SCENE]   runs luz (the viewer; with no display, `luz render` makes a PNG instead)
#   ./setup.sh test      runs the whole test suite with ctest
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  cmake ninja-build g++ pkg-config python3
  libgl-dev libx11-dev libosmesa6-dev libglfw3-dev libglm-dev
  libtinygltf-dev libtinyexr-dev libdeflate-dev libimgui-dev libstb-dev libopenimageio-dev
  libembree-dev libtbb-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev xvfb xauth fonts-dejavu-core gettext locales xdotool
  libegl-dev libegl-mesa0 assimp-testmodels
  librsvg2-bin desktop-file-utils appstream dpkg-dev groff-base
  libcairo2-dev poppler-utils
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"

if [ "${1:-}" = test ]; then
  ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
elif [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  # The viewer needs a window; on a headless machine show that the build works with a picture.
  scene=${1:-scenes/cornell_box.gltf}
  out=$(basename "${scene%.*}").png
  echo "setup: no display for the viewer; rendering $scene headless to $out instead"
  ./build/luz render "$scene" --out "$out"
else
  ./build/luz "$@"
fi
