#!/bin/sh
# An installed luz at work, from the current folder (check_install.sh runs it): --version, --help,
# `luz render` on its own Cornell box with the Phong model (phong.png, left here) and with
# radiosity in Spanish. With `hide` (only ever inside a private mount namespace, where it runs as
# that namespace's root) it first puts an empty folder over the build and source trees, so that
# nothing can be read from them.
# Usage: run_installed.sh LUZ VERSION BUILD_DIR SOURCE_DIR [hide]
set -eu
luz=$1 version=$2 build=$3 source=$4 hide=${5:-}
prefix=$(cd "$(dirname "$luz")/.." && pwd)

fail() {
  echo "run_installed ($luz): $*" >&2
  exit 1
}

if [ "$hide" = hide ]; then
  for tree in "$build" "$source"; do
    mount -t tmpfs -o size=1m luz-hidden "$tree" || fail "cannot hide $tree"
    [ -z "$(ls -A "$tree")" ] || fail "$tree is still visible"
  done
fi

# --version: the project's version, and every folder of files inside this prefix.
"$luz" --version >version.txt || fail "--version failed"
head -n1 version.txt | grep -q "^luz $version\( (git [^)]*)\)\?\$" || fail "--version says: $(head -n1 version.txt)"
[ "$(wc -l <version.txt)" -eq 5 ] || fail "--version does not list its four folders: $(cat version.txt)"
tail -n +2 version.txt | while IFS= read -r line; do
  case "${line#*: }" in
    "$prefix/share/luz/"*) ;;
    *) fail "reads files outside its prefix: $line" ;;
  esac
done

"$luz" --help >help.txt || fail "--help failed"
grep -q '^  render ' help.txt || fail "--help lists no render"

scene=$prefix/share/luz/scenes/cornell_box.gltf
"$luz" render "$scene" --model phong --size 64x48 -q --out phong.png 2>stderr.txt || fail "render phong: $(cat stderr.txt)"
[ ! -s stderr.txt ] || fail "render phong: $(cat stderr.txt)"
"$luz" render "$scene" --model radiosity --shots 40 --hemicube-res 64 --size 64x48 --lang es \
  --out radiosity.png >stdout.txt 2>stderr.txt || fail "render radiosity: $(cat stderr.txt)"
[ ! -s stderr.txt ] || fail "render radiosity --lang es: $(cat stderr.txt)"
# The catalogue was read: the summary is in Spanish (without it luz warns and speaks English).
grep -q 'disparos' stdout.txt || fail "render radiosity --lang es is not in Spanish: $(cat stdout.txt)"
for picture in phong.png radiosity.png; do
  [ "$(od -An -c -j1 -N3 "$picture" | tr -d ' ')" = PNG ] || fail "$picture is not a PNG"
done
