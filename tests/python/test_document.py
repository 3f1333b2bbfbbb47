"""patchlab.Document: the editor's commands, one undo step each, undo and redo bit for bit,
refusals that change nothing, and saves that read back."""

import numpy as np
import pytest

import patchlab
from conftest import ASSETS


def square_document():
    doc = patchlab.Document()
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0.2), (0, 1, 0)]
    vertices = [doc.add_vertex(p) for p in corners]
    assert vertices == [0, 1, 2, 3]
    assert doc.make_face(vertices, towards=(0, 0, 1)) == 0
    return doc


def test_a_network_built_by_commands_is_filled_and_undone_step_by_step():
    doc = square_document()
    scene = doc.scene
    assert (scene.vertex_count, scene.edge_count, scene.face_count) == (4, 4, 1)
    (face,) = scene.evaluate(density=6)
    assert len(face) == 49  # the unit square's grid
    # The face interpolates its corners.
    corners = np.array([(0, 0, 0), (1, 0, 0), (1, 1, 0.2), (0, 1, 0)], dtype=float)
    for c in corners:
        assert np.linalg.norm(face.positions - c, axis=1).min() <= 1e-15
    # The normal faces +z as asked.
    assert (face.normals[:, 2] > 0).all()
    states = [doc.scene.to_json()]
    doc.split_edge(0, 0.5)
    states.append(doc.scene.to_json())
    assert doc.scene.vertex_count == 5
    doc.move_vertex(4, (0.5, -0.2, 0.1))
    states.append(doc.scene.to_json())
    doc.set_face_scheme(0, "gb")
    states.append(doc.scene.to_json())
    for state in reversed(states[:-1]):
        assert doc.undo()
        assert doc.scene.to_json() == state
    for state in states[1:]:
        assert doc.redo()
        assert doc.scene.to_json() == state
    assert not doc.can_redo and doc.redo() is False


def test_refused_commands_raise_and_change_nothing():
    doc = square_document()
    before = doc.scene.to_json()
    with pytest.raises(patchlab.EditRefused):
        doc.make_face([0, 1])
    with pytest.raises(patchlab.EditRefused):
        doc.make_face([0, 1, 99])
    with pytest.raises(patchlab.EditRefused):
        doc.split_edge(42, 0.5)
    with pytest.raises(patchlab.EditRefused):
        doc.set_face_degree(0, 99)  # a Gregory face has no free interior
    with pytest.raises(patchlab.EditRefused):
        doc.move_curve_point(3, 0, (0, 0, 0))
    with pytest.raises(IndexError):
        doc.move_vertex(17, (0, 0, 0))
    with pytest.raises(ValueError):
        doc.move_vertex(0, (0, float("inf"), 0))
    with pytest.raises(ValueError):
        doc.set_face_scheme(0, "coons")
    assert doc.scene.to_json() == before


def test_curves_are_added_moved_and_undone():
    doc = patchlab.Document()
    c = doc.add_curve("bspline", [(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0), (4, 0, 0)])
    assert c == 0 and doc.scene.curve_count == 1
    before = doc.scene.to_json()
    doc.move_curve_point(0, 2, (2, -1, 0.5))
    assert doc.scene.to_json() != before
    doc.undo()
    assert doc.scene.to_json() == before
    with pytest.raises(ValueError):
        doc.add_curve("spiral", [(0, 0, 0), (1, 0, 0)])


def test_saves_read_back_and_a_failed_save_keeps_the_file(tmp):
    doc = patchlab.Document.open(ASSETS / "default.json")
    assert not doc.dirty
    doc.move_vertex(0, (0.1, 0.2, 0.3))
    assert doc.dirty
    target = tmp / "edited.json"
    doc.save_as(target)
    assert not doc.dirty and doc.path == str(target)
    again = patchlab.load(target)
    assert again.to_json() == doc.scene.to_json()
    a = np.vstack([s.positions for s in again.evaluate(density=5)])
    b = np.vstack([s.positions for s in doc.scene.evaluate(density=5)])
    assert np.array_equal(a, b)
    saved = target.read_bytes()
    with pytest.raises(patchlab.DataError):
        doc.save_as(tmp / "edited.txt")  # not a type Open reads
    with pytest.raises(patchlab.DataError):
        doc.scene.save(tmp / "no-such-dir" / "x.json")
    assert target.read_bytes() == saved
    # A scene of one GB patch saves as .gbp and reads back the same.
    gb = patchlab.load(ASSETS.parent / "tests" / "data" / "gb" / "cagd86.gbp")
    gb.save(tmp / "copy.gbp")
    p = patchlab.load(tmp / "copy.gbp").evaluate(density=4)[0].positions
    assert np.array_equal(p, gb.evaluate(density=4)[0].positions)
