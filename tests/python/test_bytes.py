"""Same request, same bytes: se.export against the smpl-export process, for GLB, FBX and BVH,
with and without a motion, from a path, a Motion and a dict of arrays (which must export as
np.savez of that dict: no silent dtype cast on the way in)."""
import numpy as np
import pytest
import torch

from conftest import FIXTURES, MODELS, VIDEO, cli_bytes

AMASS = FIXTURES / "motions" / "amass_smplx.npz"
SMPLX = MODELS / "smplx_small.npz"


@pytest.mark.parametrize("fmt", ["glb", "fbx", "bvh"])
def test_rest_pose_bytes(se, tmp_path, fmt):
    model = se.load_model(SMPLX)
    assert se.export(model, format=fmt) == cli_bytes(tmp_path, SMPLX, fmt)


@pytest.mark.parametrize("fmt", ["glb", "fbx", "bvh"])
def test_motion_bytes(se, tmp_path, fmt):
    model = se.load_model(SMPLX)
    expected = cli_bytes(tmp_path, SMPLX, fmt, "--motion", AMASS, "--fps", "24")
    assert se.export(model, motion=str(AMASS), format=fmt, fps=24) == expected
    motion = se.read_motion(AMASS, model=model)
    assert se.export(model, motion=motion, format=fmt, fps=24) == expected


def test_options_bytes(se, tmp_path):
    model = se.load_model(SMPLX)
    args = ["--motion", AMASS, "--max-influences", "all", "--up", "y", "--root-bone",
            "--betas", "0.5,-1.25", "--quantize-animation"]
    expected = cli_bytes(tmp_path, SMPLX, "glb", *args)
    got = se.export(model, motion=str(AMASS), max_influences="all", up="y", root_bone=True,
                    betas=np.array([0.5, -1.25]), quantize_animation=True)
    assert got == expected
    assert se.export(model, motion=str(AMASS), preset="web") == cli_bytes(
        tmp_path, SMPLX, "glb", "--motion", AMASS, "--preset", "web")


def test_gltf_in_memory_needs_embed(se, tmp_path):
    model = se.load_model("builtin")
    with pytest.raises(se.UsageError, match="gltf-embed"):
        se.export(model, format="gltf")
    assert se.export(model, format="gltf", gltf_embed=True) == cli_bytes(
        tmp_path, "builtin", "gltf", "--gltf-embed")


def test_mjcf_motion_in_memory_is_refused(se):
    """An .xml with a motion is two files (the XML and <stem>.qpos.npz): memory
    would keep one of them, so it is refused; without a motion the XML alone is
    the whole output."""
    model = se.load_model("builtin")
    with pytest.raises(se.UsageError, match="qpos.npz beside it"):
        se.export(model, motion=str(AMASS), format="xml")
    assert se.export(model, format="xml").startswith(b"<mujoco")


@pytest.mark.parametrize("dtype", ["float64", "float32"])
def test_dict_exports_as_its_npz(se, tmp_path, dtype):
    """A dict of arrays (numpy, or torch tensors) exports the bytes the CLI writes for np.savez
    of that dict, float32 values included (they must not be rounded differently on the way)."""
    data = dict(np.load(AMASS))
    for key in ("root_orient", "pose_body", "trans"):
        data[key] = data[key].astype(dtype)
    path = tmp_path / "motion.npz"
    np.savez(path, **data)
    expected = cli_bytes(tmp_path, SMPLX, "glb", "--motion", path)
    model = se.load_model(SMPLX)
    assert se.export(model, motion=data) == expected
    tensors = {k: torch.from_numpy(v) if v.dtype.kind == "f" else v for k, v in data.items()}
    assert se.export(model, motion=tensors) == expected
    if dtype == "float32":  # the float32 values matter: the same dict in float64 differs
        wider = {k: (v.astype(np.float64) + 1e-6 if k == "pose_body" else v) for k, v in data.items()}
        assert se.export(model, motion=wider) != expected


def test_nested_dict_exports_as_its_torch_file(se, tmp_path):
    """GVHMR's result as a dict of tensors in memory: the bytes of the CLI on the .pt file."""
    pt = VIDEO / "gvhmr" / "hmr4d_results.pt"
    result = torch.load(pt)
    model = se.load_model(SMPLX)
    expected = cli_bytes(tmp_path, SMPLX, "glb", "--motion", pt)
    motion = se.read_motion(result, model=model, name="hmr4d_results")
    assert motion.layout == "gvhmr"
    assert se.export(model, motion=motion) == expected


def test_host_rounding_mode_does_not_change_bytes(se, tmp_path):
    """A host that changed its thread's floating-point environment (here: rounding toward
    minus infinity and, on x86-64, flush-to-zero, as libraries built with -ffast-math do)
    still gets the CLI's bytes: the module exports in the default environment."""
    import ctypes
    import platform
    libm = ctypes.CDLL("libm.so.6")
    fe_downward, fe_tonearest = 0x400, 0  # glibc x86-64 <fenv.h>
    assert platform.machine() == "x86_64", "the constants above are x86-64's"
    model = se.load_model(SMPLX)
    expected = cli_bytes(tmp_path, SMPLX, "glb", "--motion", AMASS)
    assert libm.fesetround(fe_downward) == 0
    torch.set_flush_denormal(True)
    try:
        assert libm.fegetround() == fe_downward
        got = se.export(model, motion=str(AMASS))
        assert libm.fegetround() == fe_downward  # the host's mode is back afterwards
    finally:
        torch.set_flush_denormal(False)
        libm.fesetround(fe_tonearest)
    assert got == expected
