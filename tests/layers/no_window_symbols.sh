#!/bin/sh
# Usage: no_window_symbols.sh FILE...   (programs or static libraries)
# Fails, naming the file and a symbol, where one defines or needs a symbol of Dear ImGui or GLFW:
# the command line and the headless models must build without the window.
status=0
for file in "$@"; do
  symbols=$(nm -C "$file" 2>/dev/null) || { echo "$file: nm cannot read it" >&2; status=1; continue; }
  found=$(printf '%s\n' "$symbols" | grep -E ' (ImGui::|ImGui[A-Z]|glfw[A-Z])' | head -n 3)
  if [ -n "$found" ]; then
    printf '%s: ImGui or GLFW:\n%s\n' "$(basename "$file")" "$found"
    status=1
  fi
done
exit $status
