#!/usr/bin/env python3
"""Checks what editor_pick_e2e.sh recorded.

The log holds every selection change: face 1, then face 1 and face 0 (Shift), edge 0, none,
face 0 (right-click). The screenshots before and after selecting both faces differ by the
highlight: the selected faces are tinted with the accent colour (orange), so many more view
pixels are warm (red well above blue) afterwards. The saved scene differs from the original
only in face 0's scheme, set to GB from the context menu.
"""
import json
import sys

log, before, both, original, after = sys.argv[1:6]

selections = [l.strip() for l in open(log) if l.startswith("selection: ")]
expected = ["selection: face 1", "selection: face 1, face 0", "selection: edge 0",
            "selection: none", "selection: face 0"]
assert selections == expected, f"selections {selections}, expected {expected}"


def read_ppm(path):
    data = open(path, "rb").read()
    # P6 header: magic, width, height, maxval, each separated by whitespace.
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    assert fields[0] == b"P6" and fields[3] == b"255", f"{path}: not an 8-bit PPM"
    return int(fields[1]), int(fields[2]), data[pos + 1:]


def warm_pixels(path):
    w, h, rgb = read_ppm(path)
    count = 0
    # The 3D view: left of the side panel (the right 340 px of the 1200 px window at 0, 0).
    for y in range(0, 760):
        row = rgb[3 * w * y:3 * w * (y + 1)]
        for x in range(0, 1200 - 340):
            r, b = row[3 * x], row[3 * x + 2]
            if r > 150 and r - b > 30:
                count += 1
    return count


cold, warm = warm_pixels(before), warm_pixels(both)
print(f"warm view pixels: {cold} before, {warm} with both faces selected")
assert warm - cold > 20000, "the selected faces are not highlighted on screen"

a, b = json.load(open(original)), json.load(open(after))
assert b["network"]["faces"][0].get("scheme") == "gb", b["network"]["faces"][0]
b["network"]["faces"][0].pop("scheme")
a["network"]["faces"][0].pop("scheme", None)
assert a == b, "the save changed more than face 0's scheme"
print("checks passed")
