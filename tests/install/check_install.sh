#!/bin/sh
# Luz installed like a Linux application: `cmake --install` into a temporary prefix, which is
# then moved, and the installed luz run from another folder with the build and source trees
# hidden (a private mount namespace puts an empty folder over each, where `unshare` is allowed);
# the desktop entry, the metainfo, the icon and the man pages checked by their own validators;
# `cpack -G DEB` packs the same files with dependencies, and the .deb unpacked gives a working luz.
# Usage: tests/install/check_install.sh BUILD_DIR SOURCE_DIR VERSION APP_ID   (exit 0 = all good)
set -eu
build=$(cd "${1:?usage: check_install.sh BUILD_DIR SOURCE_DIR VERSION APP_ID}" && pwd)
source=$(cd "${2:?}" && pwd)
version=${3:?}
id=${4:?}
here=$(cd "$(dirname "$0")" && pwd)
cmake=${CMAKE:-cmake} cpack=${CPACK:-cpack}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT INT TERM

fail() {
  echo "check_install: $*" >&2
  exit 1
}

# --- cmake --install, the prefix moved (nothing may point at where it was installed) ---------
"$cmake" --install "$build" --prefix "$scratch/installed" >/dev/null
mv "$scratch/installed" "$scratch/prefix"
prefix=$scratch/prefix
[ -x "$prefix/bin/luz" ] || fail "bin/luz is not installed"
for file in scenes/cornell_box.gltf scenes/cornell_box.bin shaders/phong.frag lessons/sintesis.json \
            locale/es/LC_MESSAGES/luz.mo locale/en/LC_MESSAGES/luz.mo; do
  [ -f "$prefix/share/luz/$file" ] || fail "share/luz/$file is not installed"
done

# Built from a Git clone, luz --version names the commit (a tarball has no description).
if [ -e "$source/.git" ] && command -v git >/dev/null; then
  "$build/luz" --version | head -n1 | grep -q "^luz $version (git [^)]*)\$" ||
    fail "luz --version of a clone's build has no Git description: $("$build/luz" --version | head -n1)"
fi
# The reference picture, by the build tree's luz, before the trees are hidden.
mkdir -p "$scratch/elsewhere"
"$build/luz" render "$source/scenes/cornell_box.gltf" --model phong --size 64x48 -q --out "$scratch/build_tree.png"

# --- the installed luz, from another folder, the build and source trees out of reach --------
hidden= hide=
# Under the sanitizers (.ci/sanitize) LeakSanitizer reads its suppressions from the source tree,
# which is about to be hidden: the installed luz reads a copy of them instead.
case "${LSAN_OPTIONS:-}" in
  *suppressions=*)
    supp=$(printf '%s\n' "$LSAN_OPTIONS" | tr ':' '\n' | sed -n 's/^suppressions=//p')
    cp "$supp" "$scratch/lsan.supp"
    LSAN_OPTIONS=$(printf '%s' "$LSAN_OPTIONS" | sed "s|suppressions=[^:]*|suppressions=$scratch/lsan.supp|")
    export LSAN_OPTIONS
    ;;
esac
if unshare --user --map-root-user --mount sh -c 'mount -t tmpfs none "$1"' sh "$scratch" 2>/dev/null; then
  hidden="unshare --user --map-root-user --mount" hide=hide
else
  echo "check_install: no private mount namespace here (unshare refused): the trees stay visible," \
       "luz --version still shows which folders the installed luz reads" >&2
fi
# shellcheck disable=SC2086  # $hidden and $hide are words or nothing
(cd "$scratch/elsewhere" && $hidden sh "$here/run_installed.sh" "$prefix/bin/luz" "$version" "$build" "$source" $hide) ||
  fail "the installed luz (above)"
cmp -s "$scratch/build_tree.png" "$scratch/elsewhere/phong.png" ||
  fail "the installed luz's Phong picture differs from the build tree's"

# --- the desktop entry, the metainfo, the icon, the man pages --------------------------------
desktop=$prefix/share/applications/$id.desktop
desktop-file-validate "$desktop" >"$scratch/desktop.log" 2>&1 || { cat "$scratch/desktop.log"; fail "desktop-file-validate"; }
if grep -v ': hint: ' "$scratch/desktop.log" | grep -q .; then cat "$scratch/desktop.log"; fail "desktop-file-validate warns"; fi
grep -qx 'Exec=luz %f' "$desktop" || fail "the desktop entry does not open luz %f"
grep -q '^Name\[es\]=\|^Comment\[es\]=' "$desktop" || fail "the desktop entry has no Spanish"
# --strict: an error, a warning or an info fails (only pedantic hints are allowed).
appstreamcli validate --no-net --strict "$prefix/share/metainfo/$id.metainfo.xml" >"$scratch/appstream.log" 2>&1 ||
  { cat "$scratch/appstream.log"; fail "appstreamcli validate"; }
grep -q "<release version=\"$version\"" "$prefix/share/metainfo/$id.metainfo.xml" ||
  fail "the metainfo's release is not $version"
[ -f "$prefix/share/icons/hicolor/scalable/apps/$id.svg" ] || fail "no scalable icon"
for size in 16 32 48 64 128 256; do
  png=$prefix/share/icons/hicolor/${size}x$size/apps/$id.png
  [ -f "$png" ] || fail "no ${size}x$size icon"
  # A PNG's IHDR holds its width and height, big-endian, at bytes 16-23.
  [ "$(od -An -tu1 -j16 -N8 "$png" | tr -s ' ' | sed 's/^ //')" = "0 0 $((size / 256)) $((size % 256)) 0 0 $((size / 256)) $((size % 256))" ] ||
    fail "$png is not ${size}x$size"
done
for page in man1/luz.1 es/man1/luz.1; do
  file=$prefix/share/man/$page
  [ -f "$file" ] || fail "share/man/$page is not installed"
  groff -k -man -Tutf8 -ww -z "$file" >"$scratch/groff.log" 2>&1 || { cat "$scratch/groff.log"; fail "groff reads $page with errors"; }
  [ ! -s "$scratch/groff.log" ] || { cat "$scratch/groff.log"; fail "groff warns on $page"; }
done
page=$prefix/share/man/man1/luz.1
for command in "luz render" "luz compare" "luz solvers" "luz bench whitted" "luz bench local" "luz bench radiosity"; do
  grep -q "^\.SS \"$command\"" "$page" || fail "luz.1 has no section for $command"
done
# Every flag that luz render --help lists is in the page (roff writes a '-' as '\-').
"$prefix/bin/luz" render --help | grep -o '^  *-[-a-z,]*' | tr ',' '\n' | sed 's/^ *//' | grep . | sort -u >"$scratch/flags"
[ "$(wc -l <"$scratch/flags")" -gt 40 ] || fail "luz render --help lists too few flags"
while read -r flag; do
  grep -qF -- "\\fB$(printf '%s' "$flag" | sed 's/-/\\-/g')" "$page" || grep -qF -- ",$(printf '%s' "$flag" | sed 's/-/\\-/g')" "$page" ||
    fail "luz.1 lacks $flag"
done <"$scratch/flags"

# --- cpack -G DEB: the same files, its dependencies, and a luz that runs unpacked ------------
"$cpack" -G DEB -B "$scratch/deb" --config "$build/CPackConfig.cmake" >"$scratch/cpack.log" 2>&1 ||
  { cat "$scratch/cpack.log"; fail "cpack -G DEB"; }
if grep -q 'Warning' "$scratch/cpack.log"; then cat "$scratch/cpack.log"; fail "cpack -G DEB warns"; fi
deb=$(ls "$scratch"/deb/luz_*.deb)
dpkg-deb --field "$deb" Depends >"$scratch/depends"
for package in libc6 libstdc++6 libembree3-3 libtbb12 libosmesa6 fonts-dejavu-core; do
  grep -q "\\b$package\\b" "$scratch/depends" || fail "the .deb does not depend on $package: $(cat "$scratch/depends")"
done
(cd "$prefix" && find . -type f -o -type l | sed 's|^\./|./usr/|' | sort) >"$scratch/installed.list"
dpkg-deb --fsys-tarfile "$deb" | tar -t | grep -v '/$' | sort >"$scratch/deb.list"
diff "$scratch/installed.list" "$scratch/deb.list" || fail "the .deb's files (>) are not the installed ones (<)"
dpkg-deb -x "$deb" "$scratch/root"
(cd "$scratch/elsewhere" && rm -f ./*.png && $hidden sh "$here/run_installed.sh" "$scratch/root/usr/bin/luz" "$version" "$build" "$source" $hide) ||
  fail "the luz unpacked from the .deb (above)"
echo "check_install: installed, moved, packed and unpacked: all good"
