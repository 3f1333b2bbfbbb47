#!/usr/bin/env bash
# End-to-end test of the editor: runs the real window under Xvfb, drives it with xdotool (drag a
# network vertex where the editor says it projects, Ctrl+S, Ctrl+Z, Ctrl+S, Ctrl+Y, Ctrl+S,
# Ctrl+Q), and checks the saved scenes with editor_e2e_check.py: the vertex moved by the drag's
# expected world offset, undo restored it exactly, redo re-applied it exactly, the file is valid.
# Usage: editor_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without xvfb-run/xdotool.
set -euo pipefail
bin=$1
src=$2
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
cp "$src/assets/default.json" "$tmp/scene.json"
cp "$src/assets/default.json" "$tmp/original.json"

# The part that needs the X display.
cat > "$tmp/drive.sh" <<'INNER'
set -euo pipefail
tmp=$1 bin=$2
source "$3"
e2e_start "$bin" "$tmp/scene.json" --size 1200x760 --debug-point "vertex 2"
wait_for '^debug-point' 1
read -r _ px py _ wx wy _ < <(grep '^debug-point' "$log")
x=$(( wx + ${px%.*} )); y=$(( wy + ${py%.*} ))
win=$(xdotool search --sync --pid $pid | head -1)
xdotool windowfocus --sync "$win" 2> /dev/null || true
step xdotool mousemove $x $y
step xdotool mousedown 1
for dx in 10 20 30 40; do step xdotool mousemove $((x + dx)) $y; done
step xdotool mouseup 1
echo "drag_pixels 40 0" > "$tmp/drag.txt"
step xdotool key ctrl+s
wait_for '^saved' 1
cp "$tmp/scene.json" "$tmp/after_drag.json"
step xdotool key ctrl+z
step xdotool key ctrl+s
wait_for '^saved' 2
cp "$tmp/scene.json" "$tmp/after_undo.json"
step xdotool key ctrl+y
step xdotool key ctrl+s
wait_for '^saved' 3
cp "$tmp/scene.json" "$tmp/after_redo.json"
e2e_quit
INNER

SECONDS=0
xvfb-run -a -s "-screen 0 1280x800x24" bash "$tmp/drive.sh" "$tmp" "$bin" "$lib"
e2e_check_cwd
[ -f "$tmp/state/patchlab/imgui.ini" ] || { echo "FAIL: no imgui.ini under XDG_STATE_HOME"; exit 1; }
"$bin" analyze "$tmp/after_redo.json" > /dev/null || { echo "FAIL: saved file is invalid"; exit 1; }
python3 "$(dirname "$0")/editor_e2e_check.py" "$tmp/editor.log" "$tmp/drag.txt" "$tmp/original.json" \
  "$tmp/after_drag.json" "$tmp/after_undo.json" "$tmp/after_redo.json"
echo "editor e2e passed in ${SECONDS} s"
