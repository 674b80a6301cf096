#!/usr/bin/env bash
# Luz on a fresh Debian (bookworm or later): installs the Debian packages that are missing,
# builds (Release) into build/, then
#   ./setup.sh [SCENE]   runs luz (the viewer; with no display, `luz render` makes a PNG instead)
#   ./setup.sh test      runs the whole test suite with ctest, then builds the web page and runs
#                        its tests (as ./setup.sh web test)
#   ./setup.sh web       builds the web page into build-web/ instead (docs/web.md; twice: with
#                        threads, luz.html's luz.js, and without, luz-1thread.js): Debian's
#                        emscripten and chromium, libdeflate's, imgui's and embree's source
#                        packages, puppeteer-core and coi-serviceworker (npm)
#   ./setup.sh web serve serves build-web/ on 127.0.0.1:8000, cross-origin isolated
#   ./setup.sh web test  builds the page and the desktop's luz, runs the CPU libraries' unit tests
#                        in node (tests/web/run_node_tests.sh), then the page's tests in headless
#                        Chromium against `luz render` (tests/web/run_page_tests.sh)
set -euo pipefail
cd "$(dirname "$0")"
# Each long step says when it starts, in seconds since setup began: the test run takes most of an
# hour on a fresh 2-core machine, and this is where its time goes.
step() { echo "setup: $1 ($SECONDS s)"; }

if [ "${1:-}" = web ] && [ "${2:-}" = serve ]; then
  exec python3 src/app/web/serve.py build-web
fi

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

# gdb and pgrep: a viewer test that hangs prints its threads' stacks (tests/viewer/run_viewer_script.sh).
[ "${1:-}" = test ] && packages+=(gdb procps)
if [ "${1:-}" = web ] || [ "${1:-}" = test ]; then
  packages+=(emscripten chromium)
  command -v npm >/dev/null || packages+=(npm)
fi

sudo=()
[ "$(id -u)" -eq 0 ] || sudo=(sudo)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The web page: Emscripten's build of the sources into build-web/ (docs/web.md).
build_web() {
  # Debian's source packages the page compiles (libdeflate, embree, imgui), unpacked once into
  # build-web/sources.
  mkdir -p build-web/sources
  if ! ls -d build-web/sources/libdeflate-*/lib build-web/sources/embree-3.*/kernels \
         build-web/sources/imgui-*/imgui.cpp >/dev/null 2>&1; then
    if ! apt-get source --print-uris libdeflate >/dev/null 2>&1; then
      echo "setup: adding deb-src lines to apt's sources (for apt-get source)"
      if [ -f /etc/apt/sources.list.d/debian.sources ]; then
        sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources |
          "${sudo[@]}" tee /etc/apt/sources.list.d/luz-deb-src.sources >/dev/null
      else
        grep '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' |
          "${sudo[@]}" tee /etc/apt/sources.list.d/luz-deb-src.list >/dev/null
      fi
      "${sudo[@]}" apt-get update -qq
    fi
  fi
  if ! ls -d build-web/sources/libdeflate-*/lib >/dev/null 2>&1; then
    (cd build-web/sources && apt-get source -qq --download-only libdeflate 2>/dev/null &&
       tar xzf libdeflate_*.orig.tar.gz)
  fi
  if ! ls -d build-web/sources/embree-3.*/kernels >/dev/null 2>&1; then
    # Only the upstream (orig) tarball is used: apt-get fails when Debian's packaging tarball is
    # missing from the mirror, so its success is judged by the orig tarball alone.
    (cd build-web/sources && { apt-get source -qq --download-only embree 2>/dev/null || true; } &&
       tar xJf embree_*.orig.tar.xz)
  fi
  # Dear ImGui's core sources (the desktop links Debian's libimgui-dev, which has no WebAssembly),
  # judged by the orig tarball as Embree's.
  if ! ls build-web/sources/imgui-*/imgui.cpp >/dev/null 2>&1; then
    (cd build-web/sources && { apt-get source -qq --download-only imgui 2>/dev/null || true; } &&
       tar xJf imgui_*.orig.tar.xz)
  fi
  # The browser tests' driver of Debian's chromium, and the service worker that isolates the page
  # where its host sends no headers (served beside luz.html), kept in the build folder.
  [ -d build-web/npm/node_modules/puppeteer-core ] && [ -d build-web/npm/node_modules/coi-serviceworker ] ||
    npm install --silent --no-save --prefix build-web/npm puppeteer-core@23 coi-serviceworker@0.1.7
  # Emscripten's JavaScript tools find their modules in Debian's folder whatever node runs them.
  export NODE_PATH=/usr/share/nodejs
  # The node tests are built on request only (test_web); ON also for a build-web/ configured without them.
  step "building the web page into build-web/"
  emcmake cmake -S . -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release -DLUZ_BUILD_TESTS=ON
  cmake --build build-web --parallel "$(nproc)"
}

# The CPU libraries' unit tests in node, then the page's tests, which hold its pictures to the
# desktop's `luz render` (build/luz); both run even when the first fails.
test_web() {
  local status=0
  cmake --build build-web --parallel "$(nproc)" --target luz_node_tests
  step "the CPU libraries' tests in node"
  sh tests/web/run_node_tests.sh build-web || status=1
  step "the page's tests in headless Chromium"
  sh tests/web/run_page_tests.sh build-web build/luz build-web/test-output || status=1
  return $status
}

if [ "${1:-}" = web ]; then
  build_web
  echo "setup: the page is build-web/luz.html; ./setup.sh web serve, then open http://127.0.0.1:8000/luz.html"
  [ "${2:-}" = test ] || exit 0
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
  cmake --build build --parallel "$(nproc)" --target luz
  test_web
  exit
fi

step "building luz into build/"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel "$(nproc)"

if [ "${1:-}" = test ]; then
  # Both suites run even when the first fails, so one run reports everything.
  status=0
  rm -f build/tests/viewer_timeouts.log
  step "the desktop's tests"
  ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600 || status=1
  build_web
  test_web || status=1
  if [ -s build/tests/viewer_timeouts.log ]; then
    echo "setup: a viewer script hung once and passed when tried again; where it stood:"
    cat build/tests/viewer_timeouts.log
  fi
  step "tests done"
  exit $status
elif [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  # The viewer needs a window; on a headless machine show that the build works with a picture.
  scene=${1:-scenes/cornell_box.gltf}
  out=$(basename "${scene%.*}").png
  echo "setup: no display for the viewer; rendering $scene headless to $out instead"
  ./build/luz render "$scene" --out "$out"
else
  ./build/luz "$@"
fi
