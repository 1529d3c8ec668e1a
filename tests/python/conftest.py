"""Shared helpers of the Python module's tests (tests/python/, ctest label `python`).

The module comes from the build tree (PYTHONPATH=<build>/python, set by tests.cmake); the CLI it
is compared with is SMPL_EXPORT_EXE; the synthetic fixtures are SMPL_FIXTURE_DIR
(tests/fixtures/make_*.py). The independent forward pass is tests/roundtrip/model_math.py.
"""
import json
import os
import pathlib
import struct
import subprocess
import sys

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("SMPL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
FIXTURES = pathlib.Path(os.environ.get("SMPL_FIXTURE_DIR", SOURCE / "build" / "fixtures"))
EXE = os.environ.get("SMPL_EXPORT_EXE", str(SOURCE / "build" / "cli" / "smpl-export"))
sys.path.insert(0, str(SOURCE / "tests" / "roundtrip"))

MODELS = FIXTURES / "models"
VIDEO = FIXTURES / "layouts" / "video"
GENERATION = FIXTURES / "layouts" / "generation"


def run_cli(*args, check=True, quiet=True):
    """smpl-export ARGS [--quiet] as a process: (exit code, stderr)."""
    run = subprocess.run([EXE, *map(str, args)] + (["--quiet"] if quiet else []),
                         capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError(f"smpl-export {' '.join(map(str, args))}: {run.stderr}")
    return run.returncode, run.stderr


def cli_bytes(tmp_path, model, fmt, *args):
    """The bytes the CLI writes for --model MODEL --out x.FMT ARGS."""
    out = tmp_path / f"cli.{fmt}"
    run_cli("--model", model, "--out", out, *args)
    return out.read_bytes()


def read_glb(data):
    """(JSON document, BIN chunk) of GLB bytes."""
    magic, _, _ = struct.unpack_from("<III", data, 0)
    assert magic == 0x46546C67, "not a GLB"
    length, _ = struct.unpack_from("<II", data, 12)
    doc = json.loads(data[20:20 + length])
    blen, _ = struct.unpack_from("<II", data, 20 + length)
    return doc, data[28 + length:28 + length + blen]


COMPONENTS = {5126: np.float32, 5123: np.uint16, 5125: np.uint32, 5121: np.uint8, 5122: np.int16}


def accessor(doc, blob, index):
    """An accessor's values as a float64 (count, width) array (tightly packed or strided)."""
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    dtype = np.dtype(COMPONENTS[a["componentType"]])
    width = {"VEC4": 4, "VEC3": 3, "VEC2": 2, "SCALAR": 1, "MAT4": 16}[a["type"]]
    stride = view.get("byteStride", dtype.itemsize * width)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    rows = [np.frombuffer(blob, dtype, width, start + i * stride) for i in range(a["count"])]
    return np.array(rows, dtype=np.float64).reshape(a["count"], width)


def glb_rotations(data):
    """{joint name: (F,4) xyzw quaternions} of the first animation's rotation channels, and
    the keyframe times (F,)."""
    doc, blob = read_glb(data)
    anim = doc["animations"][0]
    out, times = {}, None
    for channel in anim["channels"]:
        if channel["target"]["path"] != "rotation":
            continue
        sampler = anim["samplers"][channel["sampler"]]
        name = doc["nodes"][channel["target"]["node"]]["name"]
        out[name] = accessor(doc, blob, sampler["output"])
        times = accessor(doc, blob, sampler["input"])[:, 0]
    return out, times


def quaternion_matrices(q):
    """(F,4) xyzw unit quaternions -> (F,3,3) rotation matrices."""
    x, y, z, w = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    return np.stack([
        1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
        2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
        2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1).reshape(-1, 3, 3)


@pytest.fixture(scope="session")
def se():
    import smpl_export
    return smpl_export


def pytest_configure(config):
    """The CLI's notes (smpl_export.Note warnings) are expected in these tests: not reported."""
    config.addinivalue_line("filterwarnings", "ignore::UserWarning")
