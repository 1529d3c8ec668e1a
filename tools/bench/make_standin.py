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
    main(sys.argv[1])
