#!/usr/bin/env python3
"""Keys in the editor's own windows, in the real editor with xdotool, run under Xvfb by
editor_keys_e2e.sh.

It opens WORKDIR/scene.json (a copy of the default scene: two faces), then
1. clicks face 1 and opens F1's window (it has the keyboard focus); Esc must close it and leave
   the selection as it was (no selection change reported); a second Esc, with no window focused,
   clears the selection as the Edit menu's Esc does;
2. picks the Add Vertex tool, clicks the middle one of its typed coordinates (y), types 0.5 and
   presses Enter: a vertex must be added at (0, 0.5, 0) (the other fields start at 0), once, and
   saved there by Ctrl+S.
Every step waits for what the editor reports (--debug-state), never for a fixed time.

Usage: editor_keys_e2e.py PATCHLAB WORKDIR (WORKDIR holds scene.json, cwd/, config/, state/).
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from editor_driver import Editor, check, shot  # noqa: E402

binary, work = sys.argv[1:3]
env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
           XDG_STATE_HOME=os.path.join(work, "state"))
path = os.path.join(work, "scene.json")
FACE = 1


ed = Editor(binary, ["--size", "1200x760", path], work, env)
with ed:
    s = ed.wait_state(lambda s: s.count("faces") == 2 and s.faces.get(FACE) is not None,
                      "the scene")
    ed.focus()

    # 1. Esc in F1's window.
    ed.click(s.faces[FACE])
    ed.wait_line(rf"^selection: face {FACE}$", f"face {FACE} selected")
    ed.shortcut("F1")
    ed.wait_line(r"^help-window 1 focused$", "F1's window with the keyboard focus")
    shot("help")
    start = len(ed.lines())
    ed.key("Escape")
    # The frame that takes the Esc reports a selection change before the window's state.
    m = ed.wait_line(r"^(help-window 0$|selection: )", "F1's window closed", since=start)
    check(m.group(1) == "help-window 0", "Esc in F1's window cleared the selection behind it")
    after = ed.lines()[start:]
    check(not any(line.startswith("selection: ") for line in after),
          f"the selection changed: {[l for l in after if l.startswith('selection: ')]}")
    s = ed.wait_state(lambda s: s.count("selected") == 1, "the selection kept")
    # With no window focused, Esc is the editor's again.
    ed.shortcut("Escape")
    ed.wait_line(r"^selection: none$", "the second Esc clears the selection")

    # 2. Enter in the Add Vertex tool's coordinates.
    s = ed.tool("v", "Add Vertex")
    before = s.count("vertices")
    field = ed.panel_item("New vertex fields")  # the centre of the three: the y field
    ed.click(field)
    # A number field selects its text when it takes the keyboard: typing replaces it.
    ed.wait_line(r"^text-input 1$", "the y field takes the keyboard")
    ed.type_text("0.5")
    shot("typed")
    # ImGui 1.86 reads keys as held or not once a frame, so Enter is held until it took effect
    # (as the other tests do); the characters typed are queued and not lost.
    ed.hold("Return")
    s = ed.wait_state(lambda s: s.count("vertices") == before + 1, "the vertex added by Enter")
    ed.let_go("Return")
    ed.wait_line(r"^text-input 0$", "the field lets go of the keyboard")
    ed.shortcut("ctrl+s")
    ed.wait_line(r"^saved " + re.escape(path), "the save")
    ed.quit()

scene = json.load(open(path))
vertices = scene["network"]["vertices"]
check(len(vertices) == before + 1, f"{len(vertices)} vertices saved, expected {before + 1}")
check(vertices[-1] == [0, 0.5, 0], f"the new vertex is at {vertices[-1]}, expected [0, 0.5, 0]")
print(f"Esc closed F1's window with the selection kept; Enter added vertex {before} at "
      f"{vertices[-1]}")
