"""The ComfyUI sample node (samples/python/comfyui_smpl_export) turns an SMPL-X parameter dict
of torch tensors into the GLB the CLI writes for np.savez of the same parameters."""
import importlib.util
import os

import numpy as np
import torch

from conftest import MODELS, SOURCE, cli_bytes


def load_node():
    path = SOURCE / "samples" / "python" / "comfyui_smpl_export" / "__init__.py"
    spec = importlib.util.spec_from_file_location("comfyui_smpl_export", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_comfyui_node_writes_the_cli_glb(tmp_path, monkeypatch):
    rng = np.random.default_rng(2)
    frames = 6
    params = {"global_orient": rng.uniform(-0.5, 0.5, (frames, 3)),
              "body_pose": rng.uniform(-0.5, 0.5, (frames, 63)),
              "transl": rng.normal(0, 0.3, (frames, 3)),
              "betas": rng.normal(0, 1, (1, 10))}
    npz = tmp_path / "smplx_motion.npz"
    np.savez(npz, **params)
    model = MODELS / "smplx_small.npz"
    expected = cli_bytes(tmp_path, model, "glb", "--motion", npz, "--source-fps", "24")
    node = load_node()
    assert "SmplxToGlb" in node.NODE_CLASS_MAPPINGS
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    monkeypatch.chdir(out_dir)
    tensors = {k: torch.tensor(v, dtype=torch.float64) for k, v in params.items()}
    (path,) = node.SmplxToGlb().export(tensors, str(model), 24.0, "smplx_motion.glb")
    assert os.path.dirname(path) == str(out_dir)
    assert open(path, "rb").read() == expected
