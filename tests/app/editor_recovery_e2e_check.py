#!/usr/bin/env python3
"""Checks the crash-recovery test's files: ORIGINAL (the scene before the edit), AUTOSAVED (the
autosave written before the editor was killed) and SAVED (the file after recovery and Ctrl+S).
Vertex 2 was nudged: it moved in the autosave and the saved file holds exactly the autosaved
position; every other vertex and every handle not attached to vertex 2 is unchanged."""
import json
import sys


def load(path):
    with open(path) as f:
        return json.load(f)["network"]


original, autosaved, saved = (load(p) for p in sys.argv[1:4])
moved = autosaved["vertices"][2]
if moved == original["vertices"][2]:
    sys.exit("FAIL: the autosave does not hold the nudge")
if saved["vertices"][2] != moved:
    sys.exit("FAIL: saved vertex 2 %s, autosaved %s" % (saved["vertices"][2], moved))
for i, (a, b) in enumerate(zip(original["vertices"], saved["vertices"])):
    if i != 2 and a != b:
        sys.exit("FAIL: vertex %d changed: %s -> %s" % (i, a, b))
if saved["edges"] != autosaved["edges"] or saved["faces"] != autosaved["faces"]:
    sys.exit("FAIL: the saved edges or faces differ from the autosave")
for e, (a, b) in enumerate(zip(original["edges"], saved["edges"])):
    if 2 not in a["v"] and a != b:
        sys.exit("FAIL: edge %d changed though it does not touch vertex 2" % e)
print("recovered vertex 2: %s -> %s" % (original["vertices"][2], moved))
