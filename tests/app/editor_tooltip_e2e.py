#!/usr/bin/env python3
"""The side panel's tooltips in the real editor, with xdotool, run under Xvfb by
editor_tooltip_e2e.sh.

It opens WORKDIR/scene.json (a copy of the default scene) and moves the mouse onto each tool
button of the lowest row (the nearest to the tool's hint below the buttons). The tooltip the
editor reports (--debug-state: "panel-item tooltip ... rect X0 Y0 X1 Y1") must lie left of the
panel (over the view), inside the window, and must not cover the hint's rectangle. Then it selects
a face and a vertex (each may make the Selection section taller, once), then nothing, the face,
nothing, the vertex and the face again: the Display section's header must not move (the panel does
not reflow under the mouse). Every step waits for what the
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
    s = ed.wait_state(lambda s: s.count("faces") == 2 and s.faces.get(1) is not None
                      and s.vertices.get(0) is not None, "the scene")
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

    # The sections below Selection move down at most when a taller selection than before appears
    # (the GB face and the vertex with its Transform rows, once each), and then stay put as
    # selections come and go.
    def display_top():
        return rects(ed, "Display header")[-1][1]

    face = ("the face", lambda: ed.click(s.faces[1]), r"^selection: face 1$")
    vertex = ("the vertex", lambda: ed.click(s.vertices[0]), r"^selection: vertex 0$")
    nothing = ("nothing", lambda: ed.shortcut("Escape"), r"^selection: none$")
    steps = [face, vertex, nothing, face, nothing, vertex, face]
    before = None
    for k, (what, act, expect) in enumerate(steps):
        start = len(ed.lines())
        seen = len(rects(ed, "Display header"))
        act()
        # The frame that changes the selection draws the panel before it reports the selection,
        # and the header is reported whenever it moves: a move would be in the log by now.
        ed.wait_line(expect, f"{what} selected", since=start)
        if k < 2:  # the face and the vertex: each may be the tallest yet
            before = display_top()
            continue
        moved = [r[1] for r in rects(ed, "Display header")[seen:] if r[1] != before]
        check(not moved, f"with {what} selected the Display section moved from y {before} to "
                         f"{moved}")
    print(f"the Display section stayed at y {before} as smaller selections came and went")
    ed.quit()
