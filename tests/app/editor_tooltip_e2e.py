#!/usr/bin/env python3
"""The side panel's tooltips in the real editor, with xdotool, run under Xvfb by
editor_tooltip_e2e.sh.

It opens WORKDIR/scene.json (a copy of the default scene) and moves the mouse onto each tool
button of the lowest row (the nearest to the tool's hint below the buttons). The tooltip the
editor reports (--debug-state: "panel-item tooltip ... rect X0 Y0 X1 Y1") must lie left of the
panel (over the view), inside the window, and must not cover the hint's rectangle. Every step waits for what the
editor reports, never for a fixed time.

Usage: editor_tooltip_e2e.py PATCHLAB WORKDIR (WORKDIR holds scene.json, cwd/, config/, state/).
"""
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from editor_driver import Editor, check  # noqa: E402

binary, work = sys.argv[1:3]
env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
           XDG_STATE_HOME=os.path.join(work, "state"))
TOOLS = ["Select", "Add Vertex", "Add Edge", "Make Face", "Split Edge", "New Curve"]
RECT = re.compile(r"^panel-item (.+) [0-9.]+ [0-9.]+ window -?\d+ -?\d+ "
                  r"rect ([-0-9.]+) ([-0-9.]+) ([-0-9.]+) ([-0-9.]+)$")


def rects(ed, label):
    """Every rectangle reported for a panel item, in order."""
    out = []
    for line in ed.lines():
        m = RECT.match(line)
        if m and m.group(1) == label:
            out.append(tuple(float(m.group(k)) for k in range(2, 6)))
    return out


def overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


ed = Editor(binary, ["--size", "1200x760", os.path.join(work, "scene.json")], work, env)
with ed:
    ed.wait_state(lambda s: s.count("faces") == 2, "the scene")
    ed.focus()
    ed.wait_line(r"^panel-item Tool hint ", "the tool's hint", since=0)
    hint = rects(ed, "Tool hint")[-1]
    buttons = {t: rects(ed, t)[-1] for t in TOOLS if rects(ed, t)}
    check(len(buttons) >= 3, f"tool buttons reported: {sorted(buttons)}")
    lowest = max(r[1] for r in buttons.values())
    row = [t for t, r in buttons.items() if r[1] == lowest]
    for tool in row:
        r = buttons[tool]
        seen = len(rects(ed, "tooltip"))
        ed.move(((r[0] + r[2]) / 2, (r[1] + r[3]) / 2))
        # The tooltip is laid out on its second frame: wait for a rectangle with a size.
        ed.wait_line(r"^panel-item tooltip ", f"the tooltip of {tool}", since=0)
        deadline = time.time() + 20
        while time.time() < deadline:
            tips = [t for t in rects(ed, "tooltip")[seen:] if t[2] - t[0] > 20 and t[3] - t[1] > 5]
            if tips:
                break
            time.sleep(0.05)
        check(tips, f"no tooltip laid out for {tool}")
        tip = tips[-1]
        check(not overlap(tip, hint), f"the tooltip of {tool} {tip} covers the tool's hint {hint}")
        check(tip[2] <= hint[0], f"the tooltip of {tool} {tip} is not beside the panel "
                                 f"(the panel's text starts at x {hint[0]})")
        check(tip[0] >= 0, f"the tooltip of {tool} {tip} runs out of the window")
        print(f"{tool}: tooltip {tip}, hint {hint}")
        # Away from the buttons before the next one, so each tooltip is a new one.
        ed.move((100, 400))
    ed.quit()
