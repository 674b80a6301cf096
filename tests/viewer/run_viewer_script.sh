#!/bin/sh
# Runs the scripted viewer in a real window under Xvfb, through Mesa's software OpenGL, as CI
# does: run_viewer_script.sh LUZ SCRIPT SCENE OUT_DIR
# OUT_DIR is emptied first and receives the script's screenshots and inspector dumps, which
# tests/test_viewer.cpp then checks. Exit 77 (CTest's skip) only when xvfb-run is missing.
set -eu
luz=$1 script=$2 scene=$3 out=$4
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "xvfb-run is missing (Debian: apt-get install xvfb xauth; ./setup.sh installs them): skipped"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"
cd "$out"
# A scene the viewer must refuse while keeping the one it shows.
printf '{ "asset": { "version": "2.0" }, "meshes": [ {' > broken.gltf
# One triangle, (0, 0, 0), (1, 0, 0), (0, 1, 0), for the scenes below.
triangle='"meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]'
# A scene that loads with one warning (it brings no light: the default lights, said in the
# window); its camera, 3 m in front of the triangle, keeps the missing camera's warning away.
cat > unlit.gltf <<EOF
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
 "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.33, 0.33, 3]}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.05}}],
 $triangle}
EOF
# A scene as Blender's glTF exporter writes it in its default Lighting Mode: a 100 W lamp 3 m
# over the triangle comes as 100 / 4 pi x 683 = 5435 candela, which Luz reads as W/sr.
cat > bright.gltf <<EOF
{"asset": {"version": "2.0", "generator": "Khronos glTF Blender I/O v3.4.50"}, "scene": 0,
 "scenes": [{"nodes": [0, 1]}], "nodes": [{"mesh": 0},
   {"translation": [0.3, 0.3, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
 "extensionsUsed": ["KHR_lights_punctual"],
 "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5435.14}]}},
 $triangle}
EOF
# A triangle whose material leaves metallicFactor out, as Khronos's Box does: a metal, black in
# radiosity (which says so).
cat > metal.gltf <<EOF
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "materials": [{"name": "Red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0, 0, 1]}}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}
EOF
# A 2 m square seen from above under a lamp, its kd a texture of two texels: dark (sRGB 64) on
# the left, light (sRGB 224) on the right.
cat > textured.gltf <<EOF
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
 "nodes": [{"mesh": 0}, {"translation": [0, 1.5, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
   {"camera": 0, "translation": [0, 2.5, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]}],
 "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.05}}],
 "extensionsUsed": ["KHR_lights_punctual"],
 "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 3}]}},
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
 "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0, "roughnessFactor": 1}}],
 "textures": [{"source": 0}],
 "images": [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAIAAAB7QOjdAAAAD0lEQVR4nGNwcHB48OABAAkHA2GyJNoYAAAAAElFTkSuQmCC"}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
               {"bufferView": 1, "componentType": 5126, "count": 6, "type": "VEC2"}],
 "bufferViews": [{"buffer": 0, "byteLength": 72}, {"buffer": 0, "byteOffset": 72, "byteLength": 48}],
 "buffers": [{"byteLength": 120, "uri": "data:application/octet-stream;base64,AACAvwAAAAAAAIC/AACAvwAAAAAAAIA/AACAPwAAAAAAAIA/AACAvwAAAAAAAIC/AACAPwAAAAAAAIA/AACAPwAAAAAAAIC/AAAAAAAAAAAAAAAAAACAPwAAgD8AAIA/AAAAAAAAAAAAAIA/AACAPwAAgD8AAAAA"}]}
EOF
# -noreset: by default an X server resets when its last client leaves, and `luz` first checks
# that a display is there (a connection it closes) before opening its window (a second one); on
# a loaded machine the second connection can fall into the reset and fail.
# The X authority file lives here rather than in a temporary folder of xvfb-run's, and a lost
# race for a display number with another Xvfb starting at the same moment (parallel CI jobs) is
# retried; any other failure is the test's.
# A run that has not finished after 270 s is stopped: the viewer then says where its script
# stood, and a little before, where gdb can attach, each of its threads' stack goes to
# backtrace.log. Such a run is tried once more (CTest's limit is 600 s): a hang seen once is kept
# with its stacks in viewer_timeouts.log beside the run folders, which `./setup.sh test` prints
# at its end, so that a passing suite still shows it; a second hang fails the test.
attempt=1
timeouts=0
while :; do
  status=0
  LIBGL_ALWAYS_SOFTWARE=1 timeout -k 10 270 xvfb-run -a -n $((100 + $$ % 400)) -f "$PWD/xauthority" -e "$PWD/xvfb.log" \
    -s "-screen 0 1600x1200x24 -noreset" "$luz" --script "$script" --size 1280x760 "$scene" > viewer.log 2>&1 &
  viewer=$!
  (
    sleep 255
    pid=$(pgrep -n -f -- "--script $script") || exit 0
    command -v gdb >/dev/null && gdb -p "$pid" -batch -ex 'thread apply all bt' > backtrace.log 2>&1
  ) > /dev/null 2>&1 &
  watchdog=$!
  wait "$viewer" || status=$?
  pkill -P "$watchdog" 2>/dev/null || true
  kill "$watchdog" 2>/dev/null || true
  [ "$status" -eq 0 ] && break
  if [ "$attempt" -lt 3 ] && grep -q "Failed to open display" viewer.log; then
    echo "attempt $attempt: Xvfb was not reachable, retrying"
    attempt=$((attempt + 1))
    sleep 1
    continue
  fi
  if [ "$status" -eq 124 ]; then
    report=$(
      echo "$script on $scene: the scripted viewer did not finish in 270 s"
      cat viewer.log
      if [ -s backtrace.log ]; then
        echo "its threads 15 s before:"
        cat backtrace.log
      fi
    )
    echo "$report"
    timeouts=$((timeouts + 1))
    if [ "$timeouts" -lt 2 ]; then
      printf '%s\n\n' "$report" >> "$(dirname "$out")/viewer_timeouts.log"
      echo "trying once more"
      rm -f backtrace.log
      continue
    fi
    exit 1
  fi
  cat viewer.log
  echo "the scripted viewer exited with $status"
  exit 1
done
cat viewer.log
touch done
