"""PatchSamples: the arrays are views of PatchLab's storage, the samples are the surface (checked
against a tensor-product Bézier patch evaluated here with NumPy), and a moved control point
updates the samples it influences to what a fresh evaluation of the moved patch gives."""

import gc
from math import comb

import numpy as np
import pytest

import patchlab
from conftest import ASSETS, SOURCE


def bernstein(n, t):
    """B_i^n(t) and its first and second derivatives, each len(t) x (n + 1)."""
    def basis(m):
        if m < 0:
            return np.zeros((len(t), 1))
        i = np.arange(m + 1)
        return comb_row(m) * t[:, None] ** i * (1 - t[:, None]) ** (m - i)

    def comb_row(m):
        return np.array([comb(m, i) for i in range(m + 1)], dtype=np.float64)

    def pad(b, m):  # B_{i}^{m} placed at column i, zero elsewhere (n + 1 columns)
        out = np.zeros((len(t), n + 1))
        out[:, : m + 1] = b
        return out

    b = basis(n)
    b1 = basis(n - 1)
    d1 = n * (pad(np.hstack([np.zeros((len(t), 1)), b1]), n) - pad(b1, n - 1))
    b2 = basis(n - 2)
    shifted = lambda k: np.hstack([np.zeros((len(t), k)), b2])  # noqa: E731
    d2 = n * (n - 1) * (pad(shifted(2), n) - 2 * pad(shifted(1), n - 1) + pad(b2, n - 2))
    return b, d1, d2


def bezier_surface(points, m, n, uv):
    """S, Su, Sv, Suu, Suv, Svv of the tensor-product patch P_ij = points[i (n + 1) + j]."""
    p = points.reshape(m + 1, n + 1, 3)
    bu, du, ddu = bernstein(m, uv[:, 0])
    bv, dv, ddv = bernstein(n, uv[:, 1])
    f = lambda a, b: np.einsum("si,sj,ijc->sc", a, b, p)  # noqa: E731
    return f(bu, bv), f(du, bv), f(bu, dv), f(ddu, bv), f(du, dv), f(bu, ddv)


def test_arrays_are_read_only_views_that_outlive_the_scene():
    samples = patchlab.load(ASSETS / "default.json").evaluate(density=8)
    positions = samples[0].positions
    for a in (positions, samples[0].normals, samples[0].mean_curvature, samples[0].params):
        assert not a.flags.owndata and not a.flags.writeable
        assert a.base is not None
    with pytest.raises(ValueError):
        positions[0, 0] = 1.0
    copy = np.array(positions)
    del samples
    gc.collect()
    assert np.array_equal(positions, copy)  # the storage lives as long as the array


def test_bezier_samples_equal_an_independent_evaluation():
    scene = patchlab.load(ASSETS / "bezier-wave.json")
    (s,) = scene.evaluate(density=24)
    points = s.control_points
    uv = np.array(s.params)
    S, Su, Sv, Suu, Suv, Svv = bezier_surface(points, 4, 4, uv)
    scale = np.abs(points).max()
    assert np.abs(s.positions - S).max() <= 1e-13 * scale * 10
    assert np.abs(s.su - Su).max() <= 1e-12 * scale * 10
    assert np.abs(s.sv - Sv).max() <= 1e-12 * scale * 10
    assert np.abs(s.suu - Suu).max() <= 1e-11 * scale * 10
    assert np.abs(s.suv - Suv).max() <= 1e-11 * scale * 10
    assert np.abs(s.svv - Svv).max() <= 1e-11 * scale * 10
    # The differential geometry from the fundamental forms.
    normal = np.cross(Su, Sv)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    E, F, G = (Su * Su).sum(1), (Su * Sv).sum(1), (Sv * Sv).sum(1)
    L, M, N = (Suu * normal).sum(1), (Suv * normal).sum(1), (Svv * normal).sum(1)
    K = (L * N - M * M) / (E * G - F * F)
    H = (E * N - 2 * F * M + G * L) / (2 * (E * G - F * F))
    root = np.sqrt(np.maximum(H * H - K, 0))
    assert np.abs(s.normals - normal).max() <= 1e-12
    curvature_scale = np.abs(np.concatenate([H, K, H - root, H + root])).max()
    for ours, theirs in ((s.mean_curvature, H), (s.gaussian_curvature, K),
                         (s.k_min, H - root), (s.k_max, H + root)):
        assert np.abs(ours - theirs).max() <= 1e-9 * curvature_scale


def test_triangles_index_the_samples_and_face_along_the_normals():
    (s,) = patchlab.load(ASSETS / "bezier-wave.json").evaluate(density=10)
    t = s.triangles.astype(np.int64)
    assert t.min() == 0 and t.max() == len(s) - 1
    p = s.positions
    facet = np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]])
    assert ((facet * s.normals[t[:, 0]]).sum(1) > 0).all()


@pytest.mark.parametrize(
    "scene_file, k",
    [
        (ASSETS / "bezier-wave.json", 12),  # a Bernstein point: every sample moves
        (ASSETS / "classic" / "bspline.json", 0),  # a B-spline point: the ones in its support
        (SOURCE / "tests" / "data" / "gb" / "cagd86.gbp", 17),
    ],
)
def test_a_moved_control_point_updates_the_samples_it_influences(scene_file, k, tmp):
    scene = patchlab.load(scene_file)
    samples = scene.evaluate(density=16)
    s = samples[0]
    before = {name: np.array(getattr(s, name))
              for name in ("positions", "normals", "mean_curvature", "k_max")}
    target = s.control_points[k] + np.array([0.05, -0.1, 0.3])
    changed = s.move_control_point(k, target)
    assert changed.dtype == np.uint32
    assert np.array_equal(s.control_points[k], target)
    # A fresh evaluation of the patch with that point moved, through the document.
    doc = patchlab.Document(scene)
    doc.move_patch_point(0, k, target)
    fresh = doc.scene.evaluate(density=16)[0]
    scale = np.abs(s.control_points).max()
    assert np.abs(s.positions - fresh.positions).max() <= 1e-12 * scale
    assert np.abs(s.normals - fresh.normals).max() <= 1e-10
    unchanged = np.setdiff1d(np.arange(len(s)), changed)
    for name, old in before.items():
        assert np.array_equal(getattr(s, name)[unchanged], old[unchanged]), name
    moved = np.abs(s.positions - before["positions"]).max(axis=1) > 0
    assert set(np.flatnonzero(moved)) <= set(changed.tolist())
    assert moved.any()
    if scene_file.name == "bspline.json":
        assert 0 < len(changed) < len(s)  # local support: only some samples


def test_a_bad_control_point_or_position_raises():
    (s,) = patchlab.load(ASSETS / "bezier-wave.json").evaluate(density=4)
    before = np.array(s.positions)
    with pytest.raises(IndexError):
        s.move_control_point(25, (0, 0, 0))
    for bad in ((0, 0), (0, 0, float("nan")), (0, 0, 1e300), "abc", None):
        with pytest.raises((ValueError, TypeError)):
            s.move_control_point(3, bad)
    assert np.array_equal(s.positions, before)


@pytest.mark.parametrize("scene_file", [ASSETS / "default.json", ASSETS / "gb-concave-l.json",
                                        ASSETS / "classic" / "nurbs.json"])
def test_evaluate_at_the_sample_points_gives_the_samples(scene_file):
    for s in patchlab.load(scene_file).evaluate(density=10):
        at = s.evaluate_at(s.params)
        regular = ~at["singular"]
        assert regular.sum() > len(s) // 2  # singular: collapsed corners, the poles' sides
        for name in ("positions", "su", "sv", "suu", "suv", "svv"):
            assert np.array_equal(at[name], getattr(s, name)), name
        for name in ("normals", "mean_curvature", "gaussian_curvature", "k_min", "k_max"):
            assert np.array_equal(at[name][regular], getattr(s, name)[regular]), name
        # Where Su x Sv vanishes, the flag says so and the values are zeros, never NaN.
        assert (np.linalg.norm(np.cross(at["su"], at["sv"]), axis=1)[~regular] == 0).all()
        assert np.isfinite(at["normals"]).all()


def test_evaluate_at_takes_points_of_the_domain_only():
    (s,) = patchlab.load(ASSETS / "bezier-wave.json").evaluate(density=4)
    inside = np.array([[0.0, 0.0], [1.0, 1.0], [0.25, 0.75], [0.5, 0.0]])
    at = s.evaluate_at(inside)
    assert at["positions"].shape == (4, 3)
    S = bezier_surface(s.control_points, 4, 4, inside)[0]
    assert np.abs(at["positions"] - S).max() <= 1e-14
    assert s.evaluate_at(np.zeros((0, 2)))["positions"].shape == (0, 3)
    for bad in (np.array([[1.5, 0.5]]), np.array([[0.5, -1e-6]]), np.array([[np.nan, 0.5]]),
                np.zeros((3, 3)), np.zeros(4)):
        with pytest.raises(ValueError):
            s.evaluate_at(bad)
    with pytest.raises((ValueError, TypeError)):
        s.evaluate_at("points")


def test_evaluate_at_fills_an_earlier_result_again():
    (s,) = patchlab.load(SOURCE / "tests" / "data" / "gb" / "cagd86.gbp").evaluate(density=6)
    uv = np.array(s.params)
    result = s.evaluate_at(uv)
    first = {k: np.array(v) for k, v in result.items()}
    s.move_control_point(0, s.control_points[0] + (0, 0, 0.5))
    again = s.evaluate_at(uv, out=result)
    assert again is result
    fresh = s.evaluate_at(uv)
    for k in result:
        assert np.array_equal(result[k], fresh[k]), k
    assert not np.array_equal(result["positions"], first["positions"])
    # Anything but an earlier result for as many points is refused.
    for out in ({}, s.evaluate_at(uv[:5]), {"positions": s.positions, "normals": s.normals},
                {k: np.array(v) for k, v in fresh.items()}):
        with pytest.raises(ValueError):
            s.evaluate_at(uv, out=out)


def test_evaluating_again_reuses_dropped_storage_only():
    """Scene.evaluate writes into the storage of results Python has dropped (no new memory), never
    into that of results still held; what it writes equals a fresh scene's evaluation."""
    scene = patchlab.load(ASSETS / "gb-hole-filling.json")
    fields = ("positions", "su", "svv", "normals", "mean_curvature", "k_min")

    def copies(result):
        return [{name: np.array(getattr(s, name)) for name in fields} for s in result]

    def assert_values(result, values):
        assert len(result) == len(values)
        for s, kept in zip(result, values):
            for name in fields:
                assert np.array_equal(getattr(s, name), kept[name]), (s.name, name)

    def storage(result):
        return {s.positions.__array_interface__["data"][0] for s in result}

    gb = scene.evaluate(density=96, scheme="gb")
    assert min(len(s) for s in gb) >= 4096  # large enough to be kept for reuse
    gb_values, gb_storage = copies(gb), storage(gb)
    gregory = scene.evaluate(density=96, scheme="gregory")  # gb is held: new storage
    assert not gb_storage & storage(gregory)
    assert_values(gb, gb_values)
    gregory_values = copies(gregory)
    assert any(not np.array_equal(a["positions"], b["positions"])
               for a, b in zip(gb_values, gregory_values))
    del gb
    gc.collect()
    again = scene.evaluate(density=96, scheme="gb")  # into the storage gb had
    assert storage(again) == gb_storage
    fresh = patchlab.load(ASSETS / "gb-hole-filling.json").evaluate(density=96, scheme="gb")
    assert_values(again, copies(fresh))
    assert_values(again, gb_values)
    assert_values(gregory, gregory_values)  # untouched by the evaluation after it
