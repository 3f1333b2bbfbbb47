#!/usr/bin/env bash
# Screenshot export from the real editor under Xvfb: the PNG has the size chosen in the
# preferences (not the window's), in plain and comparison layouts, opaque and transparent.
# Usage: editor_screenshot.sh PATCHLAB SOURCE_DIR. Exit 77 (skipped) without xvfb-run/python3.
set -euo pipefail
patchlab=$1
src=$2
command -v xvfb-run >/dev/null && command -v python3 >/dev/null || exit 77
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state"
mkdir -p "$XDG_CONFIG_HOME/patchlab"
check() {  # layout width height transparent
  local layout=$1 w=$2 h=$3 transparent=$4 out="$work/shot-$1-$4.png"
  printf 'screenshot_width = %s\nscreenshot_height = %s\nscreenshot_transparent = %s\n' \
    "$w" "$h" "$transparent" > "$XDG_CONFIG_HOME/patchlab/preferences.ini"
  local extra=()
  [ "$layout" = compare ] && extra=(--compare)
  (cd "$work" && timeout 60 xvfb-run -a -s "-screen 0 1024x768x24" \
     "$patchlab" "$src/assets/default.json" --size 800x600 --screenshot "$out" "${extra[@]}") \
     >/dev/null 2>&1 || true
  python3 - "$out" "$w" "$h" "$transparent" <<'PY'
import struct, sys, zlib
path, w, h, transparent = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4] == "1"
data = open(path, "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, ihdr = 8, b"", None
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR": ihdr = struct.unpack(">IIBBBBB", body)
    if kind == b"IDAT": idat += body
    pos += 12 + n
width, height, depth, colour = ihdr[0], ihdr[1], ihdr[2], ihdr[3]
assert (width, height) == (w, h), f"{path}: {width}x{height}, expected {w}x{h}"
channels = {2: 3, 6: 4}[colour]
raw = zlib.decompress(idat)
stride = width * channels + 1
corner_alpha = raw[1 + 3] if channels == 4 else 255  # first pixel of the first row
if transparent:
    assert channels == 4 and corner_alpha == 0, f"{path}: background not transparent"
else:
    assert corner_alpha == 255, f"{path}: background not opaque"
print(f"{path.split('/')[-1]}: {width}x{height}, corner alpha {corner_alpha}")
PY
}
check plain 640 360 0
check plain 1000 500 1
check compare 1200 400 0
check compare 900 450 1
# Nothing was written to the working directory of the run.
[ -z "$(ls -A "$work" | grep -v -e '^config$' -e '^state$' -e '^shot-')" ]
