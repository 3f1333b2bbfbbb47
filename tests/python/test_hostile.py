"""Hostile input through the module raises Python exceptions and never takes the interpreter
down. The reproducers of the core's and the CLI's hostile-input tests (tests/core/
hostile_input_test.cpp, tests/app/hostile_cli_test.cpp), and the shipped scenes cut short and
with bytes flipped, go through the module and through the CLI: where the CLI exits 1, the
module raises DataError with the CLI's message; where it exits 0, the module's report equals
the CLI's. Arguments only Python can pass (wrong types, indices, sizes) raise too."""

import json
import math
import random

import pytest

import patchlab
from conftest import ASSETS, cli_message, run_cli, sample_scenes


def loop_scene(vertices, loop):
    """One face over `loop` of the given vertices, straight edges."""
    edges = []
    for i, a in enumerate(loop):
        b = loop[(i + 1) % len(loop)]
        pa, pb = vertices[a], vertices[b]
        h1 = [pa[c] + (pb[c] - pa[c]) / 3 for c in range(3)]
        h2 = [pa[c] + 2 * (pb[c] - pa[c]) / 3 for c in range(3)]
        edges.append({"v": [a, b], "handles": [h1, h2]})
    return json.dumps({"patchlab": 1, "network": {"vertices": vertices, "edges": edges,
                                                   "faces": [{"loop": loop}]}})


def ring(n):
    return [[math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), 0.0] for i in range(n)]


def cc_scene(faces, vertices):
    return json.dumps({"patchlab": 1, "patches": [{"type": "catmull-clark",
                                                    "vertices": ring(vertices), "faces": faces}]})


def bezier_scene(points):
    return ('{"patchlab": 1, "patches": [{"type": "bezier", "degree": [1, 1], "points": '
            + points + "}]}")


def scaled(node, s):
    if isinstance(node, list) and len(node) == 3 and all(
            isinstance(c, (int, float)) and not isinstance(c, bool) for c in node):
        return [c * s for c in node]
    if isinstance(node, list):
        return [scaled(v, s) for v in node]
    if isinstance(node, dict):
        return {k: scaled(v, s) for k, v in node.items()}
    return node


def reproducers():
    """(name, file name, content) of the hostile-input tests' inputs."""
    wave = json.loads((ASSETS / "bezier-wave.json").read_text())
    wave["patches"][0]["points"][5][2] = 1e308
    yield "duplicate-key", "dup.json", (
        '{"patchlab": 1, "patches": [{"type": 7, "type": "bezier", "degree": [1, 1],'
        ' "points": [[0,0,0],[1,0,0],[0,1,0],[1,1,1]]}]}')
    yield "duplicate-version", "dup2.json", '{"patchlab": 1, "patchlab": 1}'
    yield "deep-nesting", "deep.json", (
        '{"patchlab": 1, "view": {"a": ' + "[" * 200 + "]" * 200 + "}}")
    yield "nul-key", "nul.json", '{"patchlab": 1, "ab\\u0000cd": 2}'
    yield "huge-integer", "int.json", (
        '{"patchlab": 1, "patches": [{"type": "bezier", "degree": [18446744073709551615, 1],'
        ' "points": []}]}')
    yield "coordinate-1e308", "big.json", bezier_scene("[[0,0,0],[1,0,0],[0,1,0],[1,1,1e308]]")
    yield "wave-1e308", "wave.json", json.dumps(wave)
    yield "tiny-span", "tiny.json", bezier_scene("[[0,0,0],[1e-160,0,0],[0,1e-160,0],[0,0,0]]")
    yield "star", "star.json", loop_scene(ring(5), [0, 2, 4, 1, 3])
    yield "bow-tie", "bow.json", loop_scene([[0, 0, 0], [1, 1, 0], [1, 0, 0], [0, 1, 0]],
                                            [0, 1, 2, 3])
    yield "65-sides", "ring.json", loop_scene(ring(65), list(range(65)))
    for i, faces in enumerate([[[0, 0, 1, 2, 3]], [[0, 1, 2, 3, 3]], [[0, 1, 0, 2, 3]]]):
        yield f"cc-repeated-{i}", f"cc{i}.json", cc_scene(faces, 4)
    yield "cc-flipped", "flip.json", cc_scene([[0, 1, 2], [1, 2, 3]], 4)
    yield "cc-257", "cc257.json", cc_scene([list(range(257))], 257)
    yield "cc-10004", "huge.json", cc_scene([list(range(10004))], 10004)
    yield "gbp-1e308", "t.gbp", "3 1\n0 0 0\n1 0 0\n0 1 1e308\n1 1 0\n"
    yield "gbp-garbage", "g.gbp", "5 3\n1 2 x\n"
    yield "gbp-empty", "e.gbp", ""
    yield "default-1e300", "d300.json", json.dumps(
        scaled(json.loads((ASSETS / "default.json").read_text()), 1e300))
    yield "pair-join-1e150", "pj.json", json.dumps(
        scaled(json.loads((ASSETS / "classic" / "pair-join.json").read_text()), 1e150))
    yield "empty", "empty.json", ""
    yield "not-json", "text.json", "this is not a scene"


def mutations():
    """Every shipped scene cut short and with bytes flipped (fixed seed)."""
    rng = random.Random(20261127)
    for path in sample_scenes():
        text = path.read_text()
        name = path.stem
        for frac in (0.1, 0.5, 0.9):
            yield f"{name}-cut-{frac}", f"{name}-cut.json", text[: int(len(text) * frac)]
        chars = list(text)
        for _ in range(3):
            i = rng.randrange(len(chars))
            chars[i] = rng.choice('0123456789-+.eE[]{},":x ')
        yield f"{name}-flipped", f"{name}-flipped.json", "".join(chars)


def through_both(tmp, file_name, content, density):
    path = tmp / file_name
    path.write_text(content)
    code, out, err = run_cli("analyze", path, "--json", "--density", str(density))
    assert code in (0, 1), err  # never a crash
    try:
        report = patchlab.analyze(patchlab.load(str(path)), density=density)
    except patchlab.DataError as e:
        assert code == 1, out
        assert str(e) == cli_message(err)
        assert e.source == str(path)
        assert str(e).startswith(e.source)
        return
    assert code == 0, err
    assert report == json.loads(out)


def test_an_unknown_extension_is_refused_by_both(tmp):
    # The command line calls it wrong usage (exit 2, docs/cli.md); the module, which has no
    # usage, raises the DataError of the reader, naming the file.
    path = tmp / "scene.txt"
    path.write_text("{}")
    code, _, err = run_cli("analyze", path, "--json")
    assert code == 2, err
    assert ".txt" in err
    with pytest.raises(patchlab.DataError) as e:
        patchlab.load(str(path))
    assert e.value.source == str(path)
    assert ".txt" in str(e.value)


@pytest.mark.parametrize("name, file_name, content", list(reproducers()),
                         ids=[r[0] for r in reproducers()])
def test_reproducers_raise_the_cli_message(name, file_name, content, tmp):
    through_both(tmp, file_name, content, 32)


def test_a_located_error_carries_the_json_path(tmp):
    path = tmp / "dup.json"
    path.write_text('{"patchlab": 1, "patches": [{"type": 7, "type": "bezier"}]}')
    with pytest.raises(patchlab.DataError) as e:
        patchlab.load(path)
    assert isinstance(e.value, ValueError)
    assert e.value.where == "patches[0].type"
    assert "duplicate key" in e.value.message
    with pytest.raises(patchlab.DataError) as e:
        patchlab.loads('{"patchlab": 1, "x": [1, 2}', source="inline")
    assert e.value.source == "inline"


@pytest.mark.parametrize("name, file_name, content", list(mutations()),
                         ids=[m[0] for m in mutations()])
def test_damaged_scenes_raise_or_read_as_the_cli_reads_them(name, file_name, content, tmp):
    through_both(tmp, file_name, content, 6)


def test_work_is_bounded_before_it_starts():
    scene = patchlab.load(str(ASSETS / "default.json"))
    code, _, err = run_cli("analyze", ASSETS / "default.json", "--density", "2000")
    assert code == 1
    with pytest.raises(patchlab.DataError) as e:
        scene.evaluate(density=2000)
    assert str(e.value) == cli_message(err)
    for bad in (0, -1, 4097):
        with pytest.raises(ValueError):
            scene.evaluate(density=bad)
    with pytest.raises((TypeError, OverflowError)):
        scene.evaluate(density=2**70)
    with pytest.raises(ValueError):
        scene.evaluate(scheme="coons")


def test_files_that_are_not_scenes_raise(tmp):
    for path in (tmp / "missing.json", tmp, ASSETS / "default.json" / "x.json"):
        with pytest.raises(patchlab.DataError):
            patchlab.load(path)
    with pytest.raises(TypeError):
        patchlab.load(None)
    with pytest.raises(TypeError):
        patchlab.analyze(None)
    with pytest.raises(patchlab.DataError):
        patchlab.loads("x" * 10, source="s")


def test_documents_refuse_hostile_commands_without_changing():
    doc = patchlab.Document(patchlab.load(ASSETS / "default.json"))
    before = doc.scene.to_json()
    calls = [
        lambda: doc.add_edge(-1, 2**31 - 1),
        lambda: doc.add_edge(0, 0),
        lambda: doc.make_face(list(range(100000))),
        lambda: doc.make_face([0, 0, 0]),
        lambda: doc.delete(vertices=[-5], edges=[10**6], faces=[2**31 - 1]),
        lambda: doc.split_edge(0, float("nan")),
        lambda: doc.split_edge(0, 0.0),
        lambda: doc.split_edge(0, 1.5),
        lambda: doc.split_edge(-1, 0.5),
        lambda: doc.set_face_scheme(99, "gb"),
        lambda: doc.set_face_degree(1, 10**6),
        lambda: doc.set_face_degree(-3, 4),
        lambda: doc.set_face_name(99, "x"),
        lambda: doc.set_vertex_normal(0, (0, 0, 0)),
        lambda: doc.set_vertex_normal(99, (0, 0, 1)),
        lambda: doc.move_vertex(0, (1e300, 0, 0)),
        lambda: doc.move_handle(0, 2, (0, 0, 0)),
        lambda: doc.move_handle(99, 0, (0, 0, 0)),
        lambda: doc.move_patch_point(0, 0, (0, 0, 0)),
        lambda: doc.add_curve("bezier", []),
        lambda: doc.add_curve("bezier", [(0, 0, 0)] * 40),
        lambda: doc.add_curve("nurbs", [(0, 0, 0), (float("nan"), 0, 0)]),
        lambda: doc.add_curve("interpolating", [(0, 0, 0), (1, 0, 0)]),
        lambda: doc.move_curve_point(0, 0, (0, 0, 0)),
        lambda: doc.fill_holes(max_sides=10**9),
        lambda: doc.fill_holes(max_sides=-1),
    ]
    for i, call in enumerate(calls):
        state = doc.scene.to_json()
        try:
            call()
        except (ValueError, IndexError, TypeError, OverflowError):
            assert doc.scene.to_json() == state, i
        else:  # accepted: the result is a scene the reader takes and evaluates
            patchlab.loads(doc.scene.to_json()).evaluate(density=3)
            doc.undo()
    assert doc.scene.to_json() == before
