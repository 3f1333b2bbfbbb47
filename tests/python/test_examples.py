"""The examples in docs/examples/python run: the scheme sweep prints one row per scheme and
density whose figures are analyze's, and its bending energy ∫ H² dA is the closed form 4π on
the exact NURBS unit sphere. (The CAD-file example waits for the CAD import it would use.)"""

import csv
import importlib.util
import io
import math
import os
import subprocess
import sys

import patchlab
from conftest import ASSETS, SOURCE

EXAMPLES = SOURCE / "docs" / "examples" / "python"


def load_example(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_scheme_sweep_tabulates_every_scheme_and_density():
    r = subprocess.run(
        [sys.executable, EXAMPLES / "scheme_sweep.py", ASSETS / "default.json",
         "--density", "6", "--density", "12", "--csv"],
        capture_output=True, text=True, env=dict(os.environ))
    assert r.returncode == 0, r.stderr
    rows = list(csv.DictReader(io.StringIO(r.stdout)))
    sweep = load_example("scheme_sweep")
    assert [(row["scheme"], int(row["density"])) for row in rows] == [
        (s, d) for s in sweep.SCHEMES for d in (6, 12)]
    scene = patchlab.load(ASSETS / "default.json")
    for row in rows:
        report = patchlab.analyze(scene, density=int(row["density"]), scheme=row["scheme"])
        angle = max(e["max_normal_angle_deg"] for e in report["edges"])
        assert math.isclose(float(row["max_normal_angle_deg"]), angle, rel_tol=1e-5, abs_tol=1e-12)
        samples = scene.evaluate(density=int(row["density"]), scheme=row["scheme"])
        assert int(row["samples"]) == sum(len(s) for s in samples)
    # The two schemes fill the quad differently: the tables differ.
    by_scheme = {row["scheme"]: row["bending_energy"] for row in rows if row["density"] == "12"}
    assert by_scheme["gregory"] != by_scheme["gb"]


def test_a_bad_scene_is_reported_with_the_cli_message(tmp):
    bad = tmp / "bad.json"
    bad.write_text('{"patchlab": 1, "patchlab": 1}')
    r = subprocess.run([sys.executable, EXAMPLES / "scheme_sweep.py", bad],
                       capture_output=True, text=True, env=dict(os.environ))
    assert r.returncode == 1
    assert r.stderr == f"scheme_sweep: {bad}: patchlab: duplicate key (a key may appear once in an object)\n"


def test_the_bending_energy_of_the_unit_sphere_is_4_pi():
    sweep = load_example("scheme_sweep")
    scene = patchlab.load(ASSETS / "classic" / "nurbs.json")
    errors = []
    for density in (16, 32):
        sphere = [s for s in scene.evaluate(density=density) if s.name == "sphere"]
        assert len(sphere) == 1
        errors.append(abs(sweep.bending_energy(sphere) - 4 * math.pi) / (4 * math.pi))
    assert errors[1] < 1e-2
    assert errors[1] < errors[0] / 3  # second order in the triangle size
