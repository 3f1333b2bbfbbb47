"""Shared pieces of the module's tests: the source tree, the CLI binary the module is compared
with (ctest passes PATCHLAB_BINARY and PYTHONPATH; tests/CMakeLists.txt), and a CLI runner."""

import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
ASSETS = SOURCE / "assets"


def cli_binary():
    binary = os.environ.get("PATCHLAB_BINARY")
    if not binary or not os.path.exists(binary):
        raise RuntimeError("PATCHLAB_BINARY must name the patchlab executable (ctest sets it)")
    return binary


def run_cli(*args):
    """The CLI's exit status, stdout and stderr."""
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    r = subprocess.run([cli_binary(), *map(str, args)], capture_output=True, text=True, env=env)
    return r.returncode, r.stdout, r.stderr


def cli_message(stderr):
    """What the CLI says after "patchlab: " (its one-line bad-input message)."""
    assert stderr.startswith("patchlab: "), stderr
    assert stderr.count("\n") == 1, stderr
    return stderr[len("patchlab: "):-1]


def sample_scenes():
    """Every scene shipped in assets/, sorted."""
    return sorted(ASSETS.rglob("*.json"))


@pytest.fixture
def tmp(tmp_path):
    return tmp_path
