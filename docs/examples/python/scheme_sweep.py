#!/usr/bin/env python3
"""Fills one curve network with every filling scheme PatchLab has, at several densities, and
tabulates the figures: the quality figures of `patchlab analyze` (boundary deviation, the normal
angle and mean-curvature jump across shared edges) and one computed here with NumPy from the
samples, the bending energy ∫ H² dA (triangle areas times the mean of H² at their corners).

    PYTHONPATH=build/python python3 docs/examples/python/scheme_sweep.py assets/default.json

Options: --density N (repeatable; default 8 16 32), --csv (comma-separated output).
"""

import argparse
import sys

import numpy as np

import patchlab

# The schemes a network face can be filled with (Scene.evaluate's and analyze's `scheme`). A
# new scheme is one more name here.
SCHEMES = ["gregory", "gb"]

COLUMNS = [
    "scheme",
    "density",
    "samples",
    "max_boundary_deviation",
    "max_normal_angle_deg",
    "max_mean_curvature_jump",
    "mean_curvature_min",
    "mean_curvature_max",
    "bending_energy",
]


def bending_energy(samples):
    """∫ H² dA over the surfaces, by the triangles of their samples."""
    total = 0.0
    for s in samples:
        t = s.triangles.astype(np.intp)
        p = s.positions
        area = 0.5 * np.linalg.norm(np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]]),
                                    axis=1)
        h2 = s.mean_curvature[t] ** 2
        total += float((area * h2.mean(axis=1)).sum())
    return total


def sweep(path, densities, schemes=SCHEMES):
    """One row (a dict of COLUMNS) per scheme and density."""
    scene = patchlab.load(path)
    rows = []
    for scheme in schemes:
        for density in densities:
            report = patchlab.analyze(scene, density=density, scheme=scheme)
            samples = scene.evaluate(density=density, scheme=scheme)
            patches, edges = report["patches"], report["edges"]
            rows.append({
                "scheme": scheme,
                "density": density,
                "samples": sum(len(s) for s in samples),
                "max_boundary_deviation": max(p["max_boundary_deviation"] for p in patches),
                "max_normal_angle_deg": max((e["max_normal_angle_deg"] for e in edges),
                                            default=0.0),
                "max_mean_curvature_jump": max((e["max_mean_curvature_jump"] for e in edges),
                                               default=0.0),
                "mean_curvature_min": min(p["mean_curvature"][0] for p in patches),
                "mean_curvature_max": max(p["mean_curvature"][1] for p in patches),
                "bending_energy": bending_energy(samples),
            })
    return rows


def print_table(rows, csv):
    def cell(v):
        return f"{v:.6g}" if isinstance(v, float) else str(v)

    table = [COLUMNS] + [[cell(r[c]) for c in COLUMNS] for r in rows]
    if csv:
        for line in table:
            print(",".join(line))
        return
    widths = [max(len(line[i]) for line in table) for i in range(len(COLUMNS))]
    for line in table:
        print("  ".join(v.rjust(w) for v, w in zip(line, widths)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("--density", type=int, action="append")
    parser.add_argument("--csv", action="store_true")
    args = parser.parse_args()
    try:
        rows = sweep(args.scene, args.density or [8, 16, 32])
    except patchlab.DataError as e:  # the CLI's message, naming the file and the place
        print(f"scheme_sweep: {e}", file=sys.stderr)
        return 1
    print_table(rows, args.csv)
    return 0


if __name__ == "__main__":
    sys.exit(main())
