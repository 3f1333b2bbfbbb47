"""export and render through the module give the CLI's files and images: the same bytes for
meshes, the same report for STEP and IGES, the same pixels as the PNG of `patchlab render`."""

import struct
import zlib

import numpy as np
import pytest

import patchlab
from conftest import ASSETS, run_cli


def decode_png(path):
    """An 8-bit RGBA, non-interlaced PNG as an h x w x 4 array (the five row filters)."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        body = data[pos + 8 : pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 6, 0)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * 4
    out = np.zeros((height, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        f = raw[y * (stride + 1)]
        row = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1)
        row = row.astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - 4] if x >= 4 else 0
            b = prev[x]
            c = prev[x - 4] if x >= 4 else 0
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (row[x] + p) & 0xFF
        out[y] = cur
        prev = cur
    return out.reshape(height, width, 4).astype(np.uint8)


@pytest.mark.parametrize("ext", ["obj", "ply", "off", "stl"])
def test_mesh_export_writes_the_cli_file(ext, tmp):
    scene_file = ASSETS / "gb-interior.json"
    code, out, err = run_cli("export", scene_file, "-o", tmp / f"cli.{ext}", "--density", "7")
    assert code == 0, err
    said = patchlab.export(patchlab.load(scene_file), tmp / f"py.{ext}", density=7)
    assert (tmp / f"py.{ext}").read_bytes() == (tmp / f"cli.{ext}").read_bytes()
    assert said == out.replace("cli." + ext, "py." + ext)


@pytest.mark.parametrize("ext", ["step", "igs"])
def test_cad_export_reports_what_the_cli_reports(ext, tmp):
    scene_file = ASSETS / "default.json"
    code, out, err = run_cli("export", scene_file, "-o", tmp / f"cli.{ext}")
    assert code == 0, err
    said = patchlab.export(patchlab.load(scene_file), tmp / f"py.{ext}")
    assert said == out.replace("cli." + ext, "py." + ext)
    head = (tmp / f"py.{ext}").read_bytes()[:200]
    assert head.startswith(b"ISO-10303-21") if ext == "step" else len(head) == 200
    with pytest.raises(ValueError):
        patchlab.export(patchlab.load(scene_file), tmp / "x.obj", tolerance=1e-3)


@pytest.mark.parametrize(
    "mode, options, kwargs",
    [
        ("shaded", [], {}),
        ("mean+isophotes+control-net", ["--view", "top"], {"view": "top"}),
        ("gaussian", ["--compare"], {"compare": True}),
    ],
)
def test_render_gives_the_pixels_of_the_cli_png(mode, options, kwargs, tmp):
    scene_file = ASSETS / "default.json"
    code, _, err = run_cli("render", scene_file, "-o", tmp / "cli.png", "--size", "160x120",
                           "--mode", mode, "--density", "12", *options)
    assert code == 0, err
    image = patchlab.render(patchlab.load(scene_file), size=(160, 120), mode=mode, density=12,
                            **kwargs)
    assert image.shape == (120, 160, 4) and image.dtype == np.uint8
    assert np.array_equal(image, decode_png(tmp / "cli.png"))
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 10  # a picture, not a blank


def test_render_refuses_what_the_cli_refuses():
    scene = patchlab.load(ASSETS / "bezier-wave.json")
    for bad in [dict(size=(0, 10)), dict(size=(5000, 10)), dict(mode="plaid"),
                dict(range=(1.0, 2.0)), dict(scheme="coons"), dict(density=0)]:
        with pytest.raises(ValueError):
            patchlab.render(scene, **bad)
    with pytest.raises(patchlab.DataError) as e:
        patchlab.render(scene, size=(16, 16), compare=True)
    assert "--compare needs a scene with a curve network" in str(e.value)
