"""The module gives what the CLI gives: for every sample scene, the samples of Scene.evaluate equal
the vertices of `patchlab export` (PLY: positions, normals and the four curvatures in double
precision; OBJ: the objects' names and vertex counts), and analyze equals `analyze --json`."""

import json

import numpy as np
import pytest

import patchlab
from conftest import ASSETS, run_cli, sample_scenes

TOLERANCE = 1e-12


def read_ply(path):
    """The vertex rows (x y z nx ny nz H K k_min k_max) of an ASCII PLY file."""
    with open(path) as f:
        count = 0
        for line in f:
            if line.startswith("element vertex "):
                count = int(line.split()[2])
            if line.strip() == "end_header":
                break
        rows = [next(f).split() for _ in range(count)]
    return np.array(rows, dtype=np.float64).reshape(count, 10)


def read_obj_objects(path):
    """(name, vertex count) of each object of an OBJ file, in order."""
    objects = []
    with open(path) as f:
        for line in f:
            if line.startswith("o "):
                objects.append([line[2:].rstrip("\n"), 0])
            elif line.startswith("v "):
                objects[-1][1] += 1
    return [tuple(o) for o in objects]


@pytest.mark.parametrize("scene_file", sample_scenes(), ids=lambda p: str(p.relative_to(ASSETS)))
def test_samples_equal_the_cli_export(scene_file, tmp):
    code, _, err = run_cli("export", scene_file, "-o", tmp / "s.ply")
    assert code == 0, err
    code, _, err = run_cli("export", scene_file, "-o", tmp / "s.obj")
    assert code == 0, err
    ply = read_ply(tmp / "s.ply")
    objects = read_obj_objects(tmp / "s.obj")

    samples = patchlab.load(scene_file).evaluate()
    assert [(s.name, len(s)) for s in samples] == objects[: len(samples)]
    assert len(objects) - len(samples) == patchlab.load(scene_file).curve_count
    if not samples:
        assert ply.shape[0] == 0
        return
    ours = np.hstack(
        [
            np.vstack([s.positions for s in samples]),
            np.vstack([s.normals for s in samples]),
            np.concatenate([s.mean_curvature for s in samples])[:, None],
            np.concatenate([s.gaussian_curvature for s in samples])[:, None],
            np.concatenate([s.k_min for s in samples])[:, None],
            np.concatenate([s.k_max for s in samples])[:, None],
        ]
    )
    assert ours.shape == ply.shape
    deviation = np.abs(ours - ply).max(axis=0)
    assert (deviation <= TOLERANCE).all(), deviation


@pytest.mark.parametrize("scene_file", sample_scenes(), ids=lambda p: str(p.relative_to(ASSETS)))
def test_analyze_equals_the_cli_json(scene_file):
    code, out, err = run_cli("analyze", scene_file, "--json", "--density", "12")
    assert code == 0, err
    assert patchlab.analyze(patchlab.load(scene_file), density=12) == json.loads(out)


@pytest.mark.parametrize("scheme", ["gregory", "gb"])
def test_a_scheme_fills_every_face_as_the_cli_does(scheme, tmp):
    scene_file = ASSETS / "default.json"
    code, _, err = run_cli("export", scene_file, "-o", tmp / "s.ply", "--scheme", scheme,
                           "--density", "9")
    assert code == 0, err
    ply = read_ply(tmp / "s.ply")
    samples = patchlab.load(scene_file).evaluate(density=9, scheme=scheme)
    positions = np.vstack([s.positions for s in samples])
    assert np.abs(positions - ply[:, :3]).max() <= TOLERANCE
    code, out, _ = run_cli("analyze", scene_file, "--json", "--scheme", scheme)
    assert patchlab.analyze(patchlab.load(scene_file), scheme=scheme) == json.loads(out)
