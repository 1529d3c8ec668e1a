"""What the runtime tests share: smpl-reference's output (read by
tests/roundtrip/model_math.read_reference) and the world rotations of its
poses, computed here independently of the cores under test."""
import os
import sys

import numpy as np
from scipy.spatial.transform import Rotation

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "roundtrip"))
from model_math import read_reference as load_reference  # noqa: E402,F401  (re-exported)


def world_rotations(poses, parents):
    """G_k rotations (model axes) from axis-angle poses (K,3)."""
    local = Rotation.from_rotvec(poses).as_matrix()
    world = np.empty_like(local)
    for k, p in enumerate(parents):
        world[k] = local[k] if p < 0 else world[p] @ local[k]
    return world
