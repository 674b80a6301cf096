#!/bin/sh
# The viewer under Xvfb with a Spanish keyboard, fed real key events by xdotool while its script
# idles: run_viewer_keys.sh LUZ SCRIPT SCENE OUT_DIR. The script dumps start.json, idles, and
# dumps end.json; in between this types KP_Add, plus (the character '+', right of P on a Spanish
# keyboard), KP_Subtract and plus again. Exit 77 (CTest's skip) when xvfb-run or xdotool is missing.
set -eu
luz=$1 script=$2 scene=$3 out=$4
for tool in xvfb-run xdotool setxkbmap; do
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
setxkbmap -layout es
LIBGL_ALWAYS_SOFTWARE=1 "$luz" --script "$script" --size 1280x760 "$scene" > viewer.log 2>&1 &
viewer=\$!
for i in \$(seq 1 600); do [ -f start.json ] && break; sleep 0.1; done
[ -f start.json ] || { kill \$viewer; echo "the viewer never dumped start.json"; exit 1; }
window=\$(xdotool search --name "Luz - ")
xdotool windowfocus --sync "\$window" mousemove --window "\$window" 900 300
sleep 0.5
for key in KP_Add plus KP_Subtract plus; do
  xdotool key --window "\$window" \$key
  sleep 0.4
done
wait \$viewer
DRIVE
status=0
xvfb-run -a -n $((500 + $$ % 400)) -f "$PWD/xauthority" -e "$PWD/xvfb.log" \
  -s "-screen 0 1600x1200x24 -noreset" sh drive.sh || status=$?
cat viewer.log
[ "$status" -eq 0 ] || { echo "the keyboard run exited with $status"; exit 1; }
touch done
