#!/usr/bin/env python3
"""Checks the scenes saved by editor_e2e.sh.

The editor printed where vertex 2 projects, the world size of one pixel at its depth and the
camera's right/up axes; the script dragged it by (dx, dy) pixels. A view-plane drag moves the
vertex (and the handles attached to it) by dx * s * right - dy * s * up exactly, up to the
rounding of doubles; undo must restore the original bit for bit and redo the dragged state.
"""
import json
import math
import sys

log, drag, original, dragged, undone, redone = sys.argv[1:7]
fields = None
pixels = None
for line in list(open(log)) + list(open(drag)):
    w = line.split()
    if w and w[0] == "debug-point":
        fields = w
    if w and w[0] == "drag_pixels":
        pixels = (float(w[1]), float(w[2]))
assert fields and pixels, "log lacks debug-point or drag_pixels lines"
s = float(fields[7])
right = [float(v) for v in fields[9:12]]
up = [float(v) for v in fields[13:16]]
expected = [pixels[0] * s * r - pixels[1] * s * u for r, u in zip(right, up)]

def network(path):
    return json.load(open(path))["network"]

a, b, u, r = network(original), network(dragged), network(undone), network(redone)
moved = [b["vertices"][2][k] - a["vertices"][2][k] for k in range(3)]
size = math.sqrt(sum(e * e for e in expected))
# Relative to the drag: doubles through projection, ray and plane maths.
tolerance = 1e-9 * max(size, 1.0)
error = math.sqrt(sum((m - e) ** 2 for m, e in zip(moved, expected)))
print(f"vertex 2 moved by {moved}, expected {expected}, error {error:.3g}")
assert size > 1e-3, "the drag moved nothing measurable"
assert error <= tolerance, f"moved {moved} instead of {expected}"
# The handles attached to vertex 2 follow it; nothing else moves.
for i, (ea, eb) in enumerate(zip(a["edges"], b["edges"])):
    for end in range(2):
        d = [eb["handles"][end][k] - ea["handles"][end][k] for k in range(3)]
        if ea["v"][end] == 2:
            assert all(abs(x - y) <= tolerance for x, y in zip(d, expected)), (i, end, d)
        else:
            assert d == [0, 0, 0], f"edge {i} handle {end} moved by {d}"
for k, (va, vb) in enumerate(zip(a["vertices"], b["vertices"])):
    if k != 2:
        assert va == vb, f"vertex {k} moved"
assert u == a, "undo did not restore the original network exactly"
assert r == b, "redo did not restore the dragged network exactly"
print("checks passed")
