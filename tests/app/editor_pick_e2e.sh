#!/usr/bin/env bash
# End-to-end test of picking in the real editor under Xvfb, driven with xdotool like a user:
# click a surface (its face is selected and highlighted on screen), Shift+click another (both),
# click a curve (its edge), click empty space (nothing), then right-click a face and choose GB
# in the context menu, save (Ctrl+S) and quit. The editor prints where faces and edges can be
# clicked, every selection change, the context menu's items and its saves (--debug-point);
# editor_pick_e2e_check.py checks the log, the screenshots (the selected faces are tinted) and
# the saved scene (only face 0's scheme changed).
# Usage: editor_pick_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without the tools.
set -euo pipefail
bin=$1
src=$2
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare import
cp "$src/assets/default.json" "$tmp/scene.json"
cp "$src/assets/default.json" "$tmp/original.json"

cat > "$tmp/drive.sh" <<'INNER'
set -euo pipefail
tmp=$1 bin=$2
source "$3"
e2e_start "$bin" "$tmp/scene.json" --size 1200x760 --debug-point "face 0" \
  --debug-point "face 1" --debug-point "edge 0"
# Window coordinates of a debug line's pixel: "debug-face face 0 X Y window WX WY".
where() {
  grep -- "^$1 $2 " "$log" | head -1 |
    awk '{ printf "%d %d\n", $(NF-4) + $(NF-1), $(NF-3) + $NF }'
}
wait_for '^debug-edge' 1
win=$(xdotool search --sync --pid $pid | head -1)
xdotool windowfocus --sync "$win" 2> /dev/null || true
read -r f0x f0y < <(where debug-face "face 0")
read -r f1x f1y < <(where debug-face "face 1")
read -r e0x e0y < <(where debug-edge "edge 0")
read -r wx wy < <(grep '^debug-face' "$log" | head -1 | awk '{ print $(NF-1), $NF }')

step xdotool mousemove 5 5  # off the view: nothing hovered
import -window root -depth 8 "$tmp/before.ppm"
step xdotool mousemove "$f1x" "$f1y"
step xdotool click 1
wait_for '^selection: face 1$' 1
step xdotool mousemove "$f0x" "$f0y"
step xdotool keydown shift
step xdotool click 1
step xdotool keyup shift
wait_for '^selection: face 1, face 0$' 1
step xdotool mousemove 5 5
sleep 0.3
import -window root -depth 8 "$tmp/both.ppm"
step xdotool mousemove "$e0x" "$e0y"
step xdotool click 1
wait_for '^selection: edge 0$' 1
# Empty space near the top left of the view (below the menu bar) clears the selection.
step xdotool mousemove $((wx + 40)) $((wy + 60))
step xdotool click 1
wait_for '^selection: none$' 1
# Right-click face 0: it becomes the selection and the menu lists the face's actions.
step xdotool mousemove "$f0x" "$f0y"
step xdotool click 3
wait_for '^selection: face 0$' 1
wait_for '^menu-item GB ' 1
read -r gx gy < <(grep '^menu-item GB ' "$log" | tail -1 |
  awk '{ printf "%d %d\n", $(NF-4) + $(NF-1), $(NF-3) + $NF }')
step xdotool mousemove "$gx" "$gy"
step xdotool click 1
step xdotool key ctrl+s
wait_for '^saved' 1
cp "$tmp/scene.json" "$tmp/after.json"
e2e_quit
INNER

SECONDS=0
xvfb-run -a -s "-screen 0 1280x800x24" bash "$tmp/drive.sh" "$tmp" "$bin" "$lib"
e2e_check_cwd
"$bin" analyze "$tmp/after.json" > /dev/null || { echo "FAIL: saved file is invalid"; exit 1; }
python3 "$(dirname "$0")/editor_pick_e2e_check.py" "$tmp/editor.log" "$tmp/before.ppm" \
  "$tmp/both.ppm" "$tmp/original.json" "$tmp/after.json"
echo "editor pick e2e passed in ${SECONDS} s"
