#!/usr/bin/env python3
"""End-to-end authoring in the real editor, with the mouse and keys only (xdotool), run under
Xvfb by editor_authoring_e2e.sh.

From File > New (Ctrl+N) in an orthographic iso view, it clicks ten vertices onto the XY work
plane (Add Vertex, V), joins five of them into a pentagon with the Add Edge tool (E), and makes a
quad, a triangle and a second quad with the Make Face tool (M) by clicking vertices (missing
edges are made with the face) and pressing Enter or clicking the first vertex again. Then, with
the select tool (Q), it selects vertex 0 and drags its normal's knob (the tangent plane turns),
splits a boundary edge of the second quad with the Split Edge tool (K) where it clicks, deletes
the triangle (click, Del) and makes it again, sets the first quad's scheme to GB from the
right-click menu and saves (Ctrl+S, a path typed into the Save As dialog, Enter).

The checks: `patchlab analyze` of the saved file reports every shared edge below 1e-6 degrees and
no projected vertex, and the network has a triangle, a quad and two pentagons (10 + 1 vertices,
13 + 1 edges); the status bar said what the split did. Then undo back to the empty scene
(Ctrl+Z until nothing is left to undo), redo to the end (Ctrl+Y), save again (Ctrl+S): the
file is reproduced byte for byte, and it is the file the editor model's unit test saves from the
same steps (tests/data/editor/authoring_scenario.json). Every step waits for the state the editor
reports (--debug-state), never for a fixed time.

Usage: editor_authoring_e2e.py PATCHLAB WORKDIR (WORKDIR holds cwd/, config/, state/).
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
saved_path = os.path.join(work, "built.json")

# The network on the XY plane: a pentagon (0-4), a quad below it (0, 6, 5, 1), a triangle on
# its right (1, 7, 2) and a quad on its left (0, 4, 8, 9).
POINTS = [(0, 0), (1, 0), (1.3, 0.9), (0.5, 1.5), (-0.3, 0.9), (1, -1), (0, -1), (2.1, 0.3),
          (-1.1, 1.0), (-1.0, -0.1)]
SCALE = 0.75


ed = Editor(binary, ["--size", "1200x760"], work, env)
with ed:
    ed.wait_state(lambda s: True, "the first state")
    ed.focus()

    ed.new_scene()

    # Vertices: clicks on the work plane.
    s = ed.tool("v", "Add Vertex")
    for i, (x, y) in enumerate(POINTS):
        px = s.world_to_pixel((SCALE * x, SCALE * y, 0))
        check(60 < px[0] < 840 and 40 < px[1] < 720, f"vertex {i} would be off the view: {px}")
        if i == 7:
            ed.move(px)
            shot("add_vertex")
        ed.click(px)
        ed.wait_state(lambda s, n=i + 1: s.count("vertices") == n, f"vertex {i}")

    # The pentagon's edges: a chain of clicks with the Add Edge tool, back to vertex 0.
    s = ed.tool("e", "Add Edge")
    for n, v in enumerate([0, 1, 2, 3, 4, 0]):
        ed.click(s.vertices[v])
        if n > 0:
            ed.wait_state(lambda s, n=n: s.count("edges") == n, f"edge {n - 1}")
        if n == 3:
            ed.move(((s.vertices[3][0] + s.vertices[4][0]) / 2 + 30, s.vertices[3][1] - 40))
            shot("add_edge")
    ed.click(s.vertices[0])  # the chain's vertex again: the chain ends
    ed.wait_line(r"^status edge chain ended", "the end of the edge chain")

    # Faces: the pentagon on its edges, the others on their vertices.
    s = ed.tool("m", "Make Face")
    for e in range(5):
        ed.click(s.edges[e])
        ed.wait_line(rf"^status face on {e + 1} edges", f"edge {e} picked")
    ed.move((s.vertices[0][0], s.vertices[0][1] + 60))
    shot("make_face_edges")
    ed.key("Return")
    s = ed.wait_state(lambda s: s.count("faces") == 1, "the pentagon")
    for f, loop in enumerate([[0, 6, 5, 1], [1, 7, 2], [0, 4, 8, 9]]):
        for v in loop:
            ed.click(s.vertices[v])
        if f == 0:
            ed.move((s.vertices[6][0] + 20, s.vertices[6][1] + 60))
            shot("make_face_vertices")
        if f == 1:
            ed.key("Return")
        else:
            ed.click(s.vertices[loop[0]])  # the first vertex again closes the chain
        s = ed.wait_state(lambda s, f=f: s.count("faces") == f + 2, f"face {f + 1}")
    check(s.count("vertices") == 10 and s.count("edges") == 13, f"counts {s.fields}")

    # Turn vertex 0's tangent plane by its normal's knob.
    s = ed.tool("q", "Select")
    ed.click(s.vertices[0])
    s = ed.wait_state(lambda s: 0 in s.knobs and s.knobs[0], "vertex 0's knob")
    knob = s.knobs[0]
    before = s.revision
    shot("tangent_plane_selected")
    ed.press(knob)
    for d in (8, 16, 24, 32):
        ed.drag_to((knob[0] + d, knob[1] + d / 4))
    shot("tangent_plane_drag")
    ed.release()
    s = ed.wait_state(lambda s: s.revision > before and s.knobs.get(0) and
                      abs(s.knobs[0][0] - knob[0]) > 10, "the turned plane")
    ed.wait_line(r"^status fix the tangent plane of vertex 0", "the plane's undo label")

    # Split the left quad's outer edge (8 -> 9, made with that face) where it is clicked.
    s = ed.tool("k", "Split Edge")
    split_edge = 11  # a face made on vertices adds its missing edges in loop order: 4-8, 8-9, 9-0
    ed.move(s.edges[split_edge])
    shot("split_edge_hover")
    ed.click(s.edges[split_edge])
    m = ed.wait_line(r"^status (split edge .*)$", "the split's status")
    label = m.group(1)
    check("now has 5 sides (GB)" in label, f"split label: {label}")
    s = ed.wait_state(lambda s: s.count("vertices") == 11, "the split")
    shot("split_edge_done")

    # Delete the triangle (face 2) and make it again.
    s = ed.tool("q", "Select")
    ed.click(s.faces[2])
    ed.wait_line(r"^selection: face 2$", "the triangle selected")
    ed.key("Delete")
    s = ed.wait_state(lambda s: s.count("faces") == 3, "the triangle deleted")
    s = ed.tool("m", "Make Face")
    for v in [1, 7, 2]:
        ed.click(s.vertices[v])
    ed.key("Return")
    s = ed.wait_state(lambda s: s.count("faces") == 4, "the triangle made again")

    # The first quad (face 1) to GB from the right-click menu.
    s = ed.tool("q", "Select")
    ed.click(s.faces[1], button=3)
    m = ed.wait_line(r"^menu-item GB ([0-9.]+) ([0-9.]+) window", "the context menu's GB item")
    shot("context_menu")
    ed.click((float(m.group(1)), float(m.group(2))))
    ed.wait_line(r"^status face 1 scheme gb", "the scheme change")

    # Save: the Save As dialog takes the typed path; Enter is held until the editor saved.
    ed.key("ctrl+s")
    ed.wait_line(r"^text-input 1$", "the Save As dialog's name field")
    ed.type_text(saved_path)
    shot("save_as")
    ed.hold("Return")
    ed.wait_line(r"^saved " + re.escape(saved_path), "the save")
    ed.let_go("Return")
    first = open(saved_path, "rb").read()
    # The editor model's unit test (tests/editor_model) runs the same steps without a window and
    # must save this file too.
    reference = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "editor",
                             "authoring_scenario.json")
    check(first == open(reference, "rb").read(),
          f"the saved file differs from {os.path.normpath(reference)}")
    ed.move((5, 5))
    shot("saved")

    # Undo back to the empty scene, redo to the end, save again.
    s = ed.state()
    while int(s.fields["can-undo"]):
        r = s.revision
        ed.shortcut("ctrl+z")
        s = ed.wait_state(lambda s, r=r: s.revision > r, "an undo")
    check(s.count("vertices") == 0 and s.count("faces") == 0, f"undone to {s.fields}")
    while int(s.fields["can-redo"]):
        r = s.revision
        ed.shortcut("ctrl+y")
        s = ed.wait_state(lambda s, r=r: s.revision > r, "a redo")
    check(s.count("vertices") == 11 and s.count("faces") == 4, f"redone to {s.fields}")
    ed.shortcut("ctrl+s")
    ed.wait_line(r"^saved " + re.escape(saved_path), "the second save")
    check(open(saved_path, "rb").read() == first, "undo to empty and redo did not reproduce the "
          "saved file byte for byte")
    ed.quit()

# The saved network: what was built, G1 everywhere, no projected tangent.
net = json.loads(first)["network"]
sides = sorted(len(f["loop"]) for f in net["faces"])
check(sides == [3, 4, 5, 5], f"face sides {sides}")
check(len(net["vertices"]) == 11 and len(net["edges"]) == 14,
      f"{len(net['vertices'])} vertices, {len(net['edges'])} edges")
check(net["faces"][1].get("scheme") == "gb", f"face 1: {net['faces'][1]}")
normals = net.get("normals", [])
check(len(normals) > 0 and normals[0] is not None and abs(normals[0][2]) < 0.9999,
      f"vertex 0's plane was not turned: {normals[:1]}")
report = json.loads(subprocess.run([binary, "analyze", saved_path, "--json"], capture_output=True,
                                   text=True, check=True).stdout)
worst = max(e["max_normal_angle_deg"] for e in report["edges"])
print(f"{len(report['edges'])} shared edges, worst normal angle {worst:.3g} deg, "
      f"{len(report['vertices'])} projected vertices")
check(len(report["edges"]) == 3, "the pentagon should share an edge with each other face")
check(worst < 1e-6, f"a shared edge is {worst} degrees off G1")
check(not report["vertices"], f"projected vertices: {report['vertices']}")
print("editor authoring e2e checks passed")
