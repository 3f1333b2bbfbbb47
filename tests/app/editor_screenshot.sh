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
# The legends of the picture are the window's: in a curvature mode one (the curvature's); with
# difference colouring too, two (the base pane's curvature and the others' distance), one under
# the other at the right edge. Counted as the opaque white panels crossed by a column just inside
# their right edge.
check_legends() {  # extra-args expected-panels
  local extra=$1 expected=$2 out="$work/shot-legends-$2.png"
  printf 'screenshot_width = 1000\nscreenshot_height = 600\nscreenshot_transparent = 0\n%s\n' \
    'base = curvature' > "$XDG_CONFIG_HOME/patchlab/preferences.ini"
  # shellcheck disable=SC2086
  (cd "$work" && timeout 60 xvfb-run -a -s "-screen 0 1024x768x24" \
     "$patchlab" "$src/assets/default.json" --size 800x600 --screenshot "$out" $extra) \
    >/dev/null 2>&1 || true
  python3 - "$out" "$expected" <<'PY'
import struct, sys, zlib
path, expected = sys.argv[1], int(sys.argv[2])
data = open(path, "rb").read()
pos, idat = 8, b""
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IHDR": width, height, _, colour = struct.unpack(">IIBB", data[pos + 8:pos + 18])
    if kind == b"IDAT": idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
bpp = {2: 3, 6: 4}[colour]
raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
for y in range(height):  # undo the PNG row filters
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line)
    prev = line
scale = max(1.0, min(width * 0.75, height) / 400.0)  # render/legend.cpp's legend_scale
x = width - round(8 * scale) - round(4 * scale) - 2  # inside the panels' right padding
panels, run = 0, 0
for y in range(height):
    white = tuple(rows[y][x * bpp:x * bpp + 3]) == (255, 255, 255)
    run = run + 1 if white else 0
    if run == 10: panels += 1
assert panels == expected, f"{path}: {panels} legend panel(s) at the right edge, expected {expected}"
print(f"{path.split('/')[-1]}: {panels} legend panel(s)")
PY
}
check_legends "" 1
check_legends --difference 2
# Nothing was written to the working directory of the run.
[ -z "$(ls -A "$work" | grep -v -e '^config$' -e '^state$' -e '^shot-')" ]
