#!/usr/bin/env bash
# End-to-end test of crash recovery: with HOME and XDG_STATE_HOME in a temporary folder and an
# empty working directory, the editor opens a copy of the default scene, a vertex is selected and
# nudged with an arrow key, the autosave appears under $XDG_STATE_HOME/patchlab and the editor is
# killed with SIGKILL. The scene file is unchanged and nothing was written to the working
# directory. A restarted editor offers the work back; Enter recovers it, Ctrl+S saves it:
# editor_recovery_e2e_check.py checks the saved file holds the nudged vertex (and nothing else
# changed) and that the autosave files are gone.
# Usage: editor_recovery_e2e.sh PATCHLAB_BINARY SOURCE_DIR. Exit 77 (skipped) without
# xvfb-run/xdotool.
set -euo pipefail
bin=$1
src=$2
lib=$(cd "$(dirname "$0")" && pwd)/editor_e2e_lib.sh
source "$lib"
e2e_prepare
mkdir -p "$tmp/home"
cp "$src/assets/default.json" "$tmp/scene.json"
cp "$src/assets/default.json" "$tmp/original.json"

cat > "$tmp/drive.sh" <<'INNER'
set -euo pipefail
tmp=$1 bin=$2
source "$3"
export HOME=$tmp/home
autosaves() { ls "$tmp/state/patchlab"/autosave-*.json 2> /dev/null || true; }

# 1. Edit, wait for the autosave, crash.
e2e_start "$bin" "$tmp/scene.json" --size 1200x760 --debug-point "vertex 2"
wait_for '^debug-point' 1
read -r _ px py _ wx wy _ < <(grep '^debug-point' "$log")
x=$(( wx + ${px%.*} )); y=$(( wy + ${py%.*} ))
win=$(xdotool search --sync --pid $pid | head -1)
xdotool windowfocus --sync "$win" 2> /dev/null || true
step xdotool mousemove $x $y
step xdotool click 1
wait_for '^selection: vertex 2$' 1
step xdotool key Right
for _ in $(seq 150); do [ -n "$(autosaves)" ] && break; sleep 0.1; done
[ -n "$(autosaves)" ] || { echo "FAIL: no autosave under XDG_STATE_HOME"; exit 1; }
sleep 0.5  # the .info beside it (written right after the scene)
cp "$(autosaves | head -1)" "$tmp/autosaved.json"
kill -9 $pid
wait $pid 2> /dev/null || true
ls -A "$tmp/cwd" > "$tmp/cwd_after_kill.txt"
cmp -s "$tmp/scene.json" "$tmp/original.json" || { echo "FAIL: the scene file changed"; exit 1; }

# 2. Restart: the editor offers the work back; Enter recovers it, Ctrl+S saves it.
e2e_start "$bin" "$tmp/scene.json" --size 1200x760 --debug-point "vertex 2"
wait_for '^recovery-offer' 1
wait_for '^debug-point' 1
win=$(xdotool search --sync --pid $pid | head -1)
xdotool windowfocus --sync "$win" 2> /dev/null || true
sleep 0.5
xdotool keydown Return; sleep 0.3; xdotool keyup Return; sleep 0.5
step xdotool key ctrl+s
wait_for '^saved' 1
e2e_quit
autosaves > "$tmp/autosaves_after_save.txt"
INNER

SECONDS=0
xvfb-run -a -s "-screen 0 1280x800x24" bash "$tmp/drive.sh" "$tmp" "$bin" "$lib"
[ ! -s "$tmp/cwd_after_kill.txt" ] || { echo "FAIL: files in the working directory:"; cat "$tmp/cwd_after_kill.txt"; exit 1; }
e2e_check_cwd
[ ! -s "$tmp/autosaves_after_save.txt" ] || { echo "FAIL: autosaves left:"; cat "$tmp/autosaves_after_save.txt"; exit 1; }
[ -z "$(ls -A "$tmp/state/patchlab" | grep autosave || true)" ] || { echo "FAIL: autosave files left"; ls -A "$tmp/state/patchlab"; exit 1; }
"$bin" analyze "$tmp/scene.json" > /dev/null || { echo "FAIL: saved file is invalid"; exit 1; }
python3 "$(dirname "$0")/editor_recovery_e2e_check.py" "$tmp/original.json" "$tmp/autosaved.json" \
  "$tmp/scene.json"
echo "editor recovery e2e passed in ${SECONDS} s"
