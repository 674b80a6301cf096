#!/bin/sh
# Reproducibility of the shipped scenes: regenerates them with scenes/generate.py into a
# temporary folder and byte-compares every file with the committed one; also checks the
# committed scenes against SCENES.md's rules (generate.py --check).
# Usage: tests/check_generated_scenes.sh REPO_ROOT    (exit 0 = identical and valid)
set -eu
root=${1:?usage: check_generated_scenes.sh REPO_ROOT}
python=${PYTHON:-python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

"$python" "$root/scenes/generate.py" --out "$tmp" >/dev/null
"$python" "$root/scenes/generate.py" --check "$root/scenes"

status=0
for file in "$tmp"/*; do
  name=$(basename "$file")
  if [ ! -f "$root/scenes/$name" ]; then
    echo "scenes/$name is generated but not committed" >&2
    status=1
  elif ! cmp -s "$file" "$root/scenes/$name"; then
    echo "scenes/$name differs from what scenes/generate.py writes; rerun it and commit" >&2
    status=1
  fi
done
exit $status
