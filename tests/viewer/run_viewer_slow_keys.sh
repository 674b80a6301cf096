#!/bin/sh
# The viewer under Xvfb, fed real key events by xdotool while its frames are slow:
# run_viewer_slow_keys.sh LUZ SCRIPT SCENE OUT_DIR. The script makes every frame take 400 ms,
# dumps widgets.json and start.json, idles, and dumps end.json; in between this Ctrl+clicks the
# patch size field (to type its value), types 0.0577, BackSpace, Return and plus with 30 ms
# between keys. Exit 77 (CTest's skip) when xvfb-run or xdotool is missing.
set -eu
luz=$1 script=$2 scene=$3 out=$4
for tool in xvfb-run xdotool; do
  if ! command -v $tool >/dev/null 2>&1; then
    echo "$tool is missing (./setup.sh installs it): skipped"
    exit 77
  fi
done
rm -rf "$out"
mkdir -p "$out"
cd "$out"
cat > drive.sh <<DRIVE
#!/bin/sh
set -eu
LIBGL_ALWAYS_SOFTWARE=1 "$luz" --script "$script" --size 1280x760 "$scene" > viewer.log 2>&1 &
viewer=\$!
for i in \$(seq 1 1200); do [ -f start.json ] && break; sleep 0.1; done
[ -f start.json ] || { kill \$viewer; echo "the viewer never dumped start.json"; exit 1; }
# The centre of the widget "patch size (m)": the four numbers after its label in widgets.json.
centre=\$(awk '/"label": "patch size \\(m\\)"/ { found = 1; n = 0; next }
               found && /^ *-?[0-9.]+,?$/ { gsub(",", ""); v[n++] = \$1; if (n == 4) { printf "%d %d", (v[0] + v[2]) / 2, (v[1] + v[3]) / 2; exit } }' widgets.json)
[ -n "\$centre" ] || { kill \$viewer; echo "no patch size field in widgets.json"; exit 1; }
window=\$(xdotool search --name "Luz - ")
xdotool windowfocus --sync "\$window" mousemove --window "\$window" \$centre
sleep 1
# Ctrl+click: edit the slider's value as text (held across frames: this is only the setup).
xdotool keydown ctrl
sleep 1
xdotool click 1
sleep 1
xdotool keyup ctrl
sleep 1
# What is tested: keys far quicker than the frames.
xdotool type --delay 30 "0.0577"
xdotool key --delay 30 BackSpace Return plus
wait \$viewer
DRIVE
status=0
xvfb-run -a -n $((900 + $$ % 400)) -f "$PWD/xauthority" -e "$PWD/xvfb.log" \
  -s "-screen 0 1600x1200x24 -noreset" sh drive.sh || status=$?
cat viewer.log
[ "$status" -eq 0 ] || { echo "the keyboard run exited with $status"; exit 1; }
touch done
