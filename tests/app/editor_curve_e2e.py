#!/usr/bin/env python3
"""End-to-end free curve in the real editor, with the mouse and keys only (xdotool), run under
Xvfb by editor_curve_e2e.sh.

From File > New (Ctrl+N) in an orthographic iso view, the New Curve tool (B, type B-spline)
takes six clicks on the XY work plane and Enter makes a cubic B-spline of six points (its last
point selected). A right-click on its point 2 opens the context menu: Insert Knot (a knot at
the curve parameter there; 7 points), then Curvature Graph (the window opens). With the select
tool (Q), point 4 is dragged (one undo step), and the scene is saved (Ctrl+S, a path typed
into the Save As dialog, Enter).

The checks: the saved file has one bspline curve of 7 points, the dragged point where it was
dropped; `patchlab analyze --json` of it lists the curve with 7 control points and finite
length and curvature figures.

Then the curve by its line: a click on the drawn curve, away from its points, selects the curve
(not a point); a right-click there offers the curve actions, and Split Curve cuts it where the
menu was opened. The two pieces meet in a joint that the editor labels G2 with its figures (no
gap, no tangent angle, no curvature jump: a spline split is C2), and `analyze` of the scene saved
again reports the same joint. Every step waits for the state the editor reports
(--debug-state), never for a fixed time.

Usage: editor_curve_e2e.py PATCHLAB WORKDIR (WORKDIR holds cwd/, config/, state/).
"""
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from editor_driver import Editor, check, shot  # noqa: E402

binary, work = sys.argv[1:3]
env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(work, "config"),
           XDG_STATE_HOME=os.path.join(work, "state"))
saved_path = os.path.join(work, "curve.json")
POINTS = [(-1.5, 0), (-0.9, 0.9), (-0.3, -0.4), (0.3, 0.8), (0.9, -0.3), (1.5, 0.6)]
SCALE = 0.75


ed = Editor(binary, ["--size", "1200x760"], work, env)
with ed:
    ed.wait_state(lambda s: True, "the first state")
    ed.focus()
    ed.new_scene()

    s = ed.tool("b", "New Curve")
    for i, (x, y) in enumerate(POINTS):
        px = s.world_to_pixel((SCALE * x, SCALE * y, 0))
        check(60 < px[0] < 840 and 40 < px[1] < 720, f"point {i} would be off the view: {px}")
        ed.click(px)
        ed.wait_line(rf"^status bspline curve with {i + 1} points", f"point {i}")
    shot("new_curve")
    ed.key("Return")
    s = ed.wait_state(lambda s: s.count("curves") == 1 and len(s.curve_points) == 6,
                      "the new curve")
    ed.wait_line(r"^selection: curve 0 point 5$", "the curve's last point selected")
    shot("curve_made")

    # Insert a knot where the right-click menu is opened (on point 2), then the curvature graph.
    s = ed.tool("q", "Select")
    ed.click(s.curve_points[(0, 2)], button=3)
    m = ed.wait_line(r"^menu-item Insert Knot ([0-9.]+) ([0-9.]+) window", "Insert Knot")
    shot("curve_menu")
    ed.click((float(m.group(1)), float(m.group(2))))
    ed.wait_line(r"^status insert", "the knot insertion")
    s = ed.wait_state(lambda s: len(s.curve_points) == 7, "seven points")
    ed.click(s.curve_points[(0, 2)], button=3)
    m = ed.wait_line(r"^menu-item Curvature Graph ([0-9.]+) ([0-9.]+) window", "Curvature Graph")
    ed.click((float(m.group(1)), float(m.group(2))))
    ed.move((5, 5))
    shot("curvature_graph")

    # Drag point 4 by (40, -30) pixels: one undo step.
    s = ed.state()
    start = s.curve_points[(0, 4)]
    before = s.revision
    ed.press(start)
    for d in (10, 20, 30, 40):
        ed.drag_to((start[0] + d, start[1] - 0.75 * d))
    ed.release()
    s = ed.wait_state(lambda s: s.revision > before and
                      abs(s.curve_points[(0, 4)][0] - start[0] - 40) < 1.5, "the dragged point")
    shot("curve_dragged")
    # One undo takes the whole drag back (and only it); redo brings it again.
    r = s.revision
    ed.key("ctrl+z")
    s = ed.wait_state(lambda s: s.revision > r, "the drag undone")
    back = s.curve_points[(0, 4)]
    check(abs(back[0] - start[0]) < 1.5 and abs(back[1] - start[1]) < 1.5 and
          len(s.curve_points) == 7, f"undo of the drag: {back} vs {start}")
    r = s.revision
    ed.key("ctrl+y")
    s = ed.wait_state(lambda s: s.revision > r and
                      abs(s.curve_points[(0, 4)][0] - start[0] - 40) < 1.5, "the drag redone")

    ed.key("ctrl+s")
    ed.wait_line(r"^text-input 1$", "the Save As dialog's name field")
    ed.type_text(saved_path)
    ed.hold("Return")
    ed.wait_line(r"^saved " + re.escape(saved_path), "the save")
    ed.let_go("Return")
    first_save = json.load(open(saved_path))

    # The curve by its line: a click on it (no point there) selects the whole curve.
    s = ed.wait_state(lambda s: s.curves.get(0) is not None, "a pixel on the curve's line")
    on_line = s.curves[0]
    check(all(math.dist(on_line, p) > 12 for p in s.curve_points.values() if p),
          f"the pixel on the line {on_line} is no control point's")
    ed.click(on_line)
    ed.wait_line(r"^selection: curve 0$", "the curve selected by its line")
    shot("curve_by_line")
    # A right-click on the line: the curve actions; Split Curve cuts it there.
    ed.click(on_line, button=3)
    m = ed.wait_line(r"^menu-item Split Curve ([0-9.]+) ([0-9.]+) window", "Split Curve")
    ed.click((float(m.group(1)), float(m.group(2))))
    s = ed.wait_state(lambda s: s.count("curves") == 2 and len(s.joints) == 1,
                      "two curves and their joint")
    a, b, g, gap, angle, jump = s.joints[0]
    print(f"joint in the editor: curves {a}/{b} {g} gap {gap} angle {angle} deg jump {jump}")
    check((a, b) == (0, 1) and g == "G2", f"joint {s.joints[0]}")
    check(gap < 1e-12 and angle < 1e-9 and jump < 1e-9, f"joint figures {s.joints[0]}")
    ed.move((5, 5))
    shot("curve_joint")
    ed.key("ctrl+s")  # the scene has its path now: saved without a dialog
    ed.wait_line(r"^saved " + re.escape(saved_path), "the second save")
    ed.quit()

scene = first_save
curves = scene.get("curves", [])
check(len(curves) == 1 and curves[0]["type"] == "bspline", f"curves: {curves}")
check(len(curves[0]["points"]) == 7, f"{len(curves[0]['points'])} points")

def analyze(path):
    return json.loads(subprocess.run([binary, "analyze", path, "--json"], capture_output=True,
                                     text=True, check=True).stdout)


report = analyze(saved_path)
# The second save: the split pieces and their joint, as the editor labelled it.
check(len(report["curves"]) == 2 and len(report["joints"]) == 1, f"after the split: {report}")
joint = report["joints"][0]
check(joint["curves"] == [0, 1] and joint["gap"] < 1e-12 and joint["tangent_angle_deg"] < 1e-9 and
      joint["curvature_jump"] < 1e-9, f"analyze joint {joint}")
check(sum(c["control_points"] for c in report["curves"]) >= 7, f"pieces {report['curves']}")
first_path = os.path.join(work, "curve-first.json")
with open(first_path, "w") as f:
    json.dump(first_save, f)
report = analyze(first_path)
c = report["curves"][0]
print(json.dumps(c))
check(c["control_points"] == 7 and c["nonfinite_samples"] == 0, f"analyze: {c}")
figures = [c["length"]] + list(c["curvature"])
check(len(figures) == 3 and all(math.isfinite(v) for v in figures), f"analyze figures: {c}")
check(c["length"] > 0, f"length {c['length']}")
print("editor curve e2e checks passed")
