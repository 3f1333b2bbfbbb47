# Shared by the editor's end-to-end tests (sourced; bash). The outer script calls
# e2e_prepare TOOLS... (skips with 77 when a tool is missing, makes $tmp with cwd/config/state
# and removes it at exit); the part that runs under xvfb-run sources this file again and uses
# e2e_start, wait_for, step and e2e_quit.

e2e_prepare() {
  local tool
  for tool in xvfb-run xdotool python3 "$@"; do
    command -v "$tool" > /dev/null || { echo "SKIP: $tool not installed"; exit 77; }
  done
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  mkdir -p "$tmp/cwd" "$tmp/config" "$tmp/state"
}

# Starts the editor from $tmp/cwd with its output in $tmp/editor.log (stderr: editor.err),
# preferences and state under $tmp; sets $pid and $log.
e2e_start() {
  log=$tmp/editor.log
  cd "$tmp/cwd"
  XDG_CONFIG_HOME=$tmp/config XDG_STATE_HOME=$tmp/state "$@" > "$log" 2> "$tmp/editor.err" &
  pid=$!
}

# Polls until `pattern` appears `count` times in the log (20 s at most).
wait_for() {
  local pattern=$1 count=$2
  for _ in $(seq 200); do
    [ "$(grep -c -- "$pattern" "$log" || true)" -ge "$count" ] && return 0
    kill -0 $pid 2> /dev/null || { echo "editor exited early"; cat "$tmp/editor.err"; exit 1; }
    sleep 0.1
  done
  echo "timed out waiting for '$pattern' x$count"; cat "$log" "$tmp/editor.err"; exit 1
}

# ImGui 1.86 samples the mouse once a frame: every event gets a few frames of its own.
step() { "$@"; sleep 0.2; }

# Ctrl+Q, then the editor must be gone within 10 s.
e2e_quit() {
  xdotool key ctrl+q
  for _ in $(seq 100); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
  if kill -0 $pid 2> /dev/null; then echo "editor did not quit"; kill $pid; exit 1; fi
}

# Fails when the editor wrote into its working directory.
e2e_check_cwd() {
  if [ -n "$(ls -A "$tmp/cwd")" ]; then
    echo "FAIL: the editor wrote into the working directory:"; ls -A "$tmp/cwd"; exit 1
  fi
}

# The tests written in Python (editor_NAME_e2e.py, driven through editor_driver.py): runs one
# under Xvfb with the editor binary $bin and the work folder $tmp, then checks the working
# directory was left alone.
e2e_drive() {
  local name=$1
  SECONDS=0
  xvfb-run -a -s "-screen 0 1280x800x24" \
    python3 "$(dirname "${BASH_SOURCE[0]}")/editor_${name}_e2e.py" "$bin" "$tmp"
  e2e_check_cwd
  echo "editor $name e2e passed in ${SECONDS} s"
}
