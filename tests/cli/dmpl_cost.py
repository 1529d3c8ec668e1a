#!/usr/bin/env python3
"""Fixed-joint cost of DMPL in numpy: max over every frame of the
motion of the vertex distance between the published math (joints regressed
from the displaced template, AMASS BodyModel) and the exporter's default
(betas-only joints), same displaced template, weights pruned to M.
Written from the equations (tests/roundtrip/model_math.py), not from the C++.

  dmpl_cost.py MODEL.npz MOTION.npz BASIS.npz M   -> prints "<cost in mm>"
The motion must be on the model's own joint layout (AMASS SMPL-H on SMPL-H).
"""
import os
import sys

import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "roundtrip"))
import model_math  # noqa: E402


def main(model_path, motion_path, basis_path, m):
    model = model_math.load_model_npz(model_path)
    motion = np.load(motion_path)
    eigvec = np.load(basis_path)["eigvec"]
    poses = motion["poses"].reshape(len(motion["poses"]), -1, 3)
    betas = motion["betas"][:model["shapedirs"].shape[2]]
    weights = model_math.prune(model["weights"], m)
    v_shaped, joints = model_math.shape(model, betas)
    cost = 0.0
    for pose, c in zip(poses, motion["dmpls"]):
        v_dyn = v_shaped + eigvec @ c
        regressed = model_math.forward(model, v_dyn, model["J_regressor"] @ v_dyn, pose, weights)[0]
        fixed = model_math.forward(model, v_dyn, joints, pose, weights)[0]
        cost = max(cost, np.linalg.norm(regressed - fixed, axis=1).max())
    print("%.3f" % (cost * 1000))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]))
