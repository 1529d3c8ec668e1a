#!/usr/bin/python3
"""Full-size SMPL stand-in for smpl-bench's load and whole-process rows.

Writes OUTDIR/:
  standin_smpl_py2.pkl   Python 2 chumpy pickle, protocol 2, as the released
                         SMPL .pkl files are written: SHORT_BINSTRING keys,
                         array payloads as py2 str (BINSTRING, read as latin-1
                         bytes), v_template and shapedirs as chumpy.ch.Ch,
                         J_regressor as scipy.sparse.csc_matrix
  standin_smpl_stored.npz    the same arrays, np.savez (stored members)
  standin_smpl_deflated.npz  the same arrays, np.savez_compressed
  standin_motion_10min.npz   a 10-minute AMASS-style SMPL motion at 120 fps
                         (72000 frames of 72 pose values, smooth sines; the
                         long-clip memory row)
6890 vertices, 24 joints, 207 pose features, 10 betas; random values (not a
body: timing only). Usage: make_standin.py OUTDIR

make_standin.py --smplx OUTDIR writes, for the WebAssembly memory benchmark
(tools/bench/wasm_memory.mjs), only:
  standin_smplx.npz      the array shapes of the SMPL-X release's SMPLX_NEUTRAL.npz
                         (v1.1): 10475 vertices, 20908 faces, 55 joints, shapedirs
                         (10475,3,400) = 300 betas + 100 expression directions,
                         posedirs (10475,3,486), hands_components/mean, float64
  standin_smplx_motion.npz  an AMASS SMPL-X clip: root_orient/pose_body/pose_hand/
                         pose_jaw/pose_eye, trans, betas (16), gender,
                         mocap_frame_rate 120; 60 s (7200 frames) of smooth sines
"""
import os
import sys

import numpy as np
import scipy.sparse as sp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "fixtures"))
from py2_pickle import Py2Writer  # noqa: E402  (the fixtures' py2 pickle writer)

N, BETAS = 6890, 10
PARENTS = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21]


def model():
    rng = np.random.default_rng(13)
    k = len(PARENTS)
    joints = np.zeros((k, 3))
    joints[0] = [0.0, 0.9, 0.0]
    for j in range(1, k):
        step = rng.normal(size=3)
        joints[j] = joints[PARENTS[j]] + 0.15 * step / np.linalg.norm(step)
    v_template = joints[np.arange(N) % k] + 0.05 * rng.normal(size=(N, 3))
    dist = np.linalg.norm(v_template[:, None, :] - joints[None, :, :], axis=2)
    weights = np.exp(-((dist / 0.1) ** 2)) + 1e-9
    weights /= weights.sum(axis=1, keepdims=True)
    regressor = np.zeros((k, N))
    for j in range(k):
        near = np.argsort(dist[:, j])[:10]
        regressor[j, near] = 0.1
    faces = np.stack([np.arange(N - 2), np.arange(1, N - 1), np.arange(2, N)], 1).astype(np.uint32)
    return dict(
        v_template=v_template, weights=weights, f=faces,
        posedirs=0.005 * rng.normal(size=(N, 3, 9 * (k - 1))),
        shapedirs=0.01 * rng.normal(size=(N, 3, BETAS)),
        J_regressor=sp.csc_matrix(regressor),
        kintree_table=np.array([[2**32 - 1] + PARENTS[1:], list(range(k))], dtype=np.int64),
        J=joints, bs_style="lbs", bs_type="lrotmin")


SMPLX_BODY = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19]
SMPLX_PARENTS = SMPLX_BODY + [15, 15, 15] + [p for wrist, first in ((20, 25), (21, 40))
                                             for c in range(5) for p in (wrist, first + 3 * c, first + 3 * c + 1)]


def smplx_model():
    """Arrays shaped as SMPLX_NEUTRAL.npz (v1.1); up to 8 influences per vertex, as the release has."""
    n, k = 10475, len(SMPLX_PARENTS)
    rng = np.random.default_rng(29)
    joints = np.zeros((k, 3))
    joints[0] = [0.0, 0.9, 0.0]
    for j in range(1, k):
        step = rng.normal(size=3)
        joints[j] = joints[SMPLX_PARENTS[j]] + 0.1 * step / np.linalg.norm(step)
    v_template = joints[np.arange(n) % k] + 0.04 * rng.normal(size=(n, 3))
    dist = np.linalg.norm(v_template[:, None, :] - joints[None, :, :], axis=2)
    weights = np.exp(-((dist / 0.08) ** 2))
    keep = np.argsort(-weights, axis=1)[:, :8]
    mask = np.zeros_like(weights, bool)
    np.put_along_axis(mask, keep, True, axis=1)
    weights = np.where(mask, weights + 1e-9, 0.0)
    weights /= weights.sum(axis=1, keepdims=True)
    regressor = np.zeros((k, n))
    for j in range(k):
        regressor[j, np.argsort(dist[:, j])[:10]] = 0.1
    faces = np.stack([np.arange(20908) % (n - 2), np.arange(20908) % (n - 2) + 1,
                      np.arange(20908) % (n - 2) + 2], 1).astype(np.int64)
    m = dict(v_template=v_template, f=faces, J_regressor=regressor, weights=weights,
             kintree_table=np.array([[2**32 - 1] + SMPLX_PARENTS[1:], list(range(k))], dtype=np.int64),
             shapedirs=0.01 * rng.normal(size=(n, 3, 400)),
             posedirs=0.005 * rng.normal(size=(n, 3, 9 * (k - 1))))
    for side in "lr":
        m["hands_components" + side] = rng.normal(size=(45, 45))
        m["hands_mean" + side] = 0.1 * rng.normal(size=45)
    return m


def smplx_motion(path, seconds=60, fps=120):
    rng = np.random.default_rng(31)
    t = np.arange(int(seconds * fps))[:, None] / fps
    p = 0.4 * np.sin(t * rng.uniform(0.3, 2.0, 165)[None, :] + rng.uniform(0, 6, 165)[None, :])
    trans = np.concatenate([0.5 * t, np.zeros_like(t), 0.9 + 0.02 * np.sin(3 * t)], axis=1)
    np.savez(path, root_orient=p[:, :3], pose_body=p[:, 3:66], pose_jaw=p[:, 66:69], pose_eye=p[:, 69:75],
             pose_hand=p[:, 75:165], trans=trans, betas=np.linspace(0.5, -0.5, 16), gender=np.array("neutral"),
             mocap_frame_rate=np.array(float(fps)))


def write_pickle(path, m):
    w = Py2Writer()
    items = []
    for k, v in m.items():
        if k in ("v_template", "shapedirs"):
            items.append((k, (lambda x: lambda: w.ch(x))(v)))
        elif sp.issparse(v):
            items.append((k, (lambda x: lambda: w.sparse(x))(v)))
        elif isinstance(v, str):
            items.append((k, (lambda x: lambda: w.string(x))(v)))
        else:
            items.append((k, (lambda x: lambda: w.ndarray(x))(v)))
    w.dict_items(items)
    w.out += b"."
    with open(path, "wb") as fh:
        fh.write(w.out)


def long_motion(path, minutes=10, fps=120):
    rng = np.random.default_rng(17)
    t = np.arange(int(minutes * 60 * fps))[:, None] / fps
    poses = 0.3 * np.sin(t * np.linspace(0.5, 3.0, 72)[None, :] + rng.uniform(0, 6, 72)[None, :])
    np.savez(path, poses=poses, trans=np.zeros((len(poses), 3)), betas=np.zeros(BETAS),
             mocap_framerate=np.array(float(fps)), gender=np.array("neutral"))


def main(out):
    os.makedirs(out, exist_ok=True)
    m = model()
    write_pickle(os.path.join(out, "standin_smpl_py2.pkl"), m)
    arrays = {k: (v.toarray() if sp.issparse(v) else v) for k, v in m.items() if not isinstance(v, str)}
    np.savez(os.path.join(out, "standin_smpl_stored.npz"), **arrays)
    np.savez_compressed(os.path.join(out, "standin_smpl_deflated.npz"), **arrays)
    long_motion(os.path.join(out, "standin_motion_10min.npz"))


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--smplx":
        os.makedirs(sys.argv[2], exist_ok=True)
        np.savez(os.path.join(sys.argv[2], "standin_smplx.npz"), **smplx_model())
        smplx_motion(os.path.join(sys.argv[2], "standin_smplx_motion.npz"))
    elif len(sys.argv) == 2:
        main(sys.argv[1])
    else:
        raise SystemExit("usage: make_standin.py OUTDIR | make_standin.py --smplx OUTDIR")
