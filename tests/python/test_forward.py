"""Model.forward against the independent numpy forward pass of the round-trip tests
(tests/roundtrip/model_math.py: SMPL, Loper et al. 2015, eqs. 1-9, written from the equations),
on the SMPL, SMPL-H and SMPL-X fixtures, with numpy and torch inputs: within 1e-6 m."""
import numpy as np
import pytest
import torch

import model_math
from conftest import MODELS

TOLERANCE = 1e-6  # metres


def reference(path, betas, poses, trans, expression=None):
    """(T,V,3) vertices and (T,K,3) joints by model_math, per frame (betas/expression rows)."""
    m = model_math.load_model_npz(str(path))
    shapedirs = m["shapedirs"]
    b = shapedirs.shape[2] if shapedirs.shape[2] <= 300 else 300
    verts, joints = [], []
    for t in range(len(poses)):
        beta = betas[t] if betas.ndim == 2 else betas
        v = m["v_template"] + shapedirs[:, :, :len(beta)] @ beta
        if expression is not None:
            e = expression[t] if expression.ndim == 2 else expression
            v = v + shapedirs[:, :, b:b + len(e)] @ e
        j = m["J_regressor"] @ v
        pv, pj, _ = model_math.forward(m, v, j, poses[t], m["weights"])
        verts.append(pv + trans[t])
        joints.append(pj + trans[t])
    return np.array(verts), np.array(joints)


def random_inputs(model, frames, rng):
    k = model.num_joints
    poses = rng.uniform(-0.6, 0.6, (frames, k, 3))
    betas = rng.normal(0, 1.0, min(10, model.num_betas))
    trans = rng.normal(0, 0.5, (frames, 3))
    return betas, poses, trans


@pytest.mark.parametrize("name", ["smpl_small", "smplh_small", "smplx_small", "mano_small"])
@pytest.mark.parametrize("kind", ["numpy", "torch"])
def test_forward_matches_numpy(se, name, kind):
    path = MODELS / f"{name}.npz"
    model = se.load_model(path)
    rng = np.random.default_rng(7)
    betas, poses, trans = random_inputs(model, 5, rng)
    want_v, want_j = reference(path, betas, poses, trans)
    if kind == "torch":  # float32 tensors, as a PyTorch pipeline holds them
        args = [torch.tensor(a, dtype=torch.float32) for a in (betas, poses, trans)]
        betas, poses, trans = (a.numpy().astype(np.float64) for a in args)
        want_v, want_j = reference(path, betas, poses, trans)
    else:
        args = [betas, poses, trans]
    v, j = model.forward(*args, dtype="float64")
    assert np.abs(v - want_v).max() < TOLERANCE
    assert np.abs(j - want_j).max() < TOLERANCE
    v32, _ = model.forward(*args)  # float32 output: within float32 rounding of the same
    assert v32.dtype == np.float32 and np.abs(v32 - want_v).max() < TOLERANCE
    # the plausible wrong readings are far: the rotations transposed, the translation dropped
    wrong, _ = reference(path, betas, -poses, trans)
    assert np.abs(v - wrong).max() > 1e-3
    assert np.abs(v - (want_v - trans[:, None, :])).max() > 1e-3


def test_matrices_flat_and_single_translation(se):
    path = MODELS / "smplh_small.npz"
    model = se.load_model(path)
    rng = np.random.default_rng(3)
    betas, poses, trans = random_inputs(model, 4, rng)
    want_v, want_j = reference(path, betas, poses, np.repeat(trans[:1], 4, 0))
    matrices = model_math.rodrigues(poses)
    for p in (matrices, poses.reshape(4, -1), np.asfortranarray(poses), poses.astype(np.float32)):
        v, j = model.forward(betas, p, trans[0], dtype=np.float64)
        tol = TOLERANCE if p.dtype == np.float64 else 1e-5
        if p.dtype == np.float32:
            want = reference(path, betas, poses.astype(np.float32).astype(np.float64),
                             np.repeat(trans[:1], 4, 0))[0]
            assert np.abs(v - want).max() < TOLERANCE
        else:
            assert np.abs(v - want_v).max() < tol and np.abs(j - want_j).max() < tol


def test_per_frame_betas_and_expression(se):
    path = MODELS / "smplx_small.npz"
    model = se.load_model(path)
    rng = np.random.default_rng(11)
    _, poses, trans = random_inputs(model, 3, rng)
    betas = rng.normal(0, 1, (3, 12))
    expression = rng.normal(0, 1, (3, 6))
    want_v, want_j = reference(path, betas, poses, trans, expression)
    v, j = model.forward(betas, poses, trans, expression, dtype="float64")
    assert np.abs(v - want_v).max() < TOLERANCE and np.abs(j - want_j).max() < TOLERANCE
    v1, _ = model.forward(betas[0], poses, trans, expression[0], dtype="float64")
    want1, _ = reference(path, betas[0], poses, trans, expression[0])
    assert np.abs(v1 - want1).max() < TOLERANCE
    no_expr, _ = reference(path, betas[0], poses, trans)
    assert np.abs(v1 - no_expr).max() > 1e-3  # the expression is applied


def test_cuda_like_tensor_goes_through_cpu(se):
    """The shim calls detach().cpu(): a tensor that requires grad is accepted."""
    model = se.load_model(MODELS / "smpl_small.npz")
    poses = torch.zeros((1, 24, 3), requires_grad=True)
    v, _ = model.forward(None, poses)
    assert v.shape == (1, model.num_vertices, 3)
