#!/usr/bin/env python3
"""End-to-end interior control of a GB face in the real editor, with the mouse and keys only
(xdotool), run under Xvfb by editor_interior_e2e.sh.

It opens WORKDIR/pentagon.json (a copy of the default scene: a Gregory quad, face 0, and a GB
pentagon, face 1, sharing an edge), clicks the pentagon, presses the face panel's Raise degree
button twice (degree 3 -> 5: the pentagon then has six free points, the centre and one on each
side's layer 2), drags the central point and the inner-row point of side 1 with the select tool,
and saves (Ctrl+S: the file it opened).

The checks: the saved file's pentagon has degree 5 and exactly two offsets, the centre's and
[1, 2, 2]'s, each the drag's world displacement (one drag step of the view plane); `patchlab
analyze --json` of it reports the pentagon with degree 5 and 2 offsets and every shared edge
below 1e-6 degrees. Every step waits for the state the editor reports (--debug-state), never
for a fixed time.

Usage: editor_interior_e2e.py PATCHLAB WORKDIR (WORKDIR holds pentagon.json, cwd/, config/,
state/).
"""
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from editor_driver import Editor, check, shot  # noqa: E402

binary, work = sys.argv[1:3]
env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
           XDG_STATE_HOME=os.path.join(work, "state"))
path = os.path.join(work, "pentagon.json")
PENTAGON = 1


def pentagon_points(s):
    return {name: at for (face, name), at in s.free_points.items() if face == PENTAGON}


ed = Editor(binary, ["--size", "1200x760", path], work, env)
with ed:
    s = ed.wait_state(lambda s: s.count("faces") == 2 and PENTAGON in s.faces, "the scene")
    ed.focus()
    shot("opened")
    # A degree-3 GB face has one free point, its centre.
    check(set(pentagon_points(s)) == {"centre"}, f"free points at degree 3: {s.free_points}")

    # Select the pentagon; the face panel offers its degree.
    check(s.faces[PENTAGON] is not None, "the pentagon is hidden")
    ed.click(s.faces[PENTAGON])
    ed.wait_line(rf"^selection: face {PENTAGON}$", "the pentagon selected")
    for degree in (4, 5):
        button = ed.panel_item("Raise degree")
        before = ed.state().revision
        ed.click(button)
        ed.wait_line(rf"^status face {PENTAGON} degree {degree}$", f"degree {degree}")
        s = ed.wait_state(lambda s: s.revision > before, f"the face at degree {degree}")
    s = ed.wait_state(lambda s: len(pentagon_points(s)) == 6, "six free points")
    shot("degree5")
    names = pentagon_points(s)
    check(set(names) == {"centre", "0,2,2", "1,2,2", "2,2,2", "3,2,2", "4,2,2"},
          f"free points at degree 5: {sorted(names)}")

    # Drag the centre, then the inner-row point of side 1, each by its own pixel offset.
    def drag(name, dx, dy):
        s = ed.state()
        start = pentagon_points(s)[name]
        check(start is not None, f"free point {name} hidden")
        before = s.revision
        ed.press(start)
        for k in (1, 2, 3, 4):
            ed.drag_to((start[0] + dx * k / 4, start[1] + dy * k / 4))
        ed.release()
        return ed.wait_state(
            lambda s: s.revision > before and pentagon_points(s).get(name) is not None and
            abs(pentagon_points(s)[name][0] - start[0] - dx) < 1.5 and
            abs(pentagon_points(s)[name][1] - start[1] - dy) < 1.5, f"{name} dragged")

    drag("centre", 0, -45)
    drag("1,2,2", 30, -25)
    shot("dragged")

    ed.key("ctrl+s")
    ed.wait_line(r"^saved " + re.escape(path), "the save")
    ed.quit()

scene = json.load(open(path))
face = scene["network"]["faces"][PENTAGON]
print(json.dumps(face))
check(face.get("degree") == 5, f"degree {face.get('degree')}")
offsets = face.get("offsets", [])
check(sorted(json.dumps(o["at"]) for o in offsets) == sorted(['"center"', "[1, 2, 2]"]),
      f"offsets: {offsets}")
check(all(sum(c * c for c in o["by"]) > 1e-6 for o in offsets), f"offsets too small: {offsets}")
report = json.loads(subprocess.run([binary, "analyze", path, "--json"], capture_output=True,
                                   text=True, check=True).stdout)
patch = [p for p in report["patches"] if p["name"] == "pentagon"][0]
print(json.dumps({k: patch[k] for k in ("degree", "offsets", "type")}))
check(patch["degree"] == 5 and patch["offsets"] == 2, f"analyze: {patch}")
edges = report["edges"]
check(len(edges) >= 1, "no shared edge reported")
for e in edges:
    check(e["max_normal_angle_deg"] < 1e-6, f"edge {e['edge']}: {e['max_normal_angle_deg']} deg")
    check(e["max_gap"] < 1e-12, f"edge {e['edge']}: gap {e['max_gap']}")
print("editor interior e2e checks passed")
