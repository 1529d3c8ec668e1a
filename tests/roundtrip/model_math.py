"""The model's math in plain numpy (docs/file-contract.md "The math"), written from the
equations and nothing else, so the round-trip tests can judge both Blender's
output and smpl-reference's without trusting our C++ code.

Also: canonical joint names, model .npz reading, and the smpl-reference
output format (PREFIX.json header + PREFIX.bin little-endian float64 data).
"""
import json

import numpy as np

BODY = ["pelvis", "left_hip", "right_hip", "spine1", "left_knee", "right_knee", "spine2",
        "left_ankle", "right_ankle", "spine3", "left_foot", "right_foot", "neck",
        "left_collar", "right_collar", "head", "left_shoulder", "right_shoulder",
        "left_elbow", "right_elbow", "left_wrist", "right_wrist"]
FINGERS = ["index1", "index2", "index3", "middle1", "middle2", "middle3", "pinky1", "pinky2",
           "pinky3", "ring1", "ring2", "ring3", "thumb1", "thumb2", "thumb3"]


def joint_names(num_joints):
    """Canonical names by joint count (SMPL 24, SMPL-H 52, SMPL-X 55, MANO 16)."""
    left = ["left_" + f for f in FINGERS]
    right = ["right_" + f for f in FINGERS]
    table = {24: BODY + ["left_hand", "right_hand"], 52: BODY + left + right,
             55: BODY + ["jaw", "left_eye_smplhf", "right_eye_smplhf"] + left + right, 16: ["wrist"] + FINGERS}
    if num_joints not in table:
        raise ValueError("no canonical joint names for %d joints" % num_joints)
    return table[num_joints]


def target_names(names):
    """Corrective morph target names in feature order."""
    return ["pose_%s_%d%d" % (names[k], r, c) for k in range(1, len(names))
            for r in range(3) for c in range(3)]


def load_model_npz(path):
    """Model arrays from a public-layout .npz: dict with parents as ints."""
    data = np.load(path, allow_pickle=False)
    model = {k: np.asarray(data[k], dtype=np.float64) for k in
             ("v_template", "shapedirs", "posedirs", "J_regressor", "weights")}
    kintree = np.asarray(data["kintree_table"]).astype(np.int64)
    parents = [int(p) for p in kintree[0]]
    model["parents"] = [-1 if (i == 0 or p < 0 or p >= 2**31) else p for i, p in enumerate(parents)]
    if "exprdirs" in data.files:
        model["exprdirs"] = np.asarray(data["exprdirs"], dtype=np.float64)
    return model


def rodrigues(axis_angle):
    """(..., 3) axis-angle -> (..., 3, 3) rotation matrices."""
    aa = np.asarray(axis_angle, dtype=np.float64)
    angle = np.linalg.norm(aa, axis=-1, keepdims=True)
    axis = aa / np.where(angle > 0, angle, 1.0)
    x, y, z = axis[..., 0], axis[..., 1], axis[..., 2]
    zero = np.zeros_like(x)
    k = np.stack([zero, -z, y, z, zero, -x, -y, x, zero], -1).reshape(aa.shape[:-1] + (3, 3))
    s, c = np.sin(angle)[..., None], np.cos(angle)[..., None]
    return np.eye(3) + s * k + (1 - c) * (k @ k)


def prune(weights, m):
    """Top-m weights per vertex (ties toward the lower joint), renormalised, dense."""
    order = np.argsort(-weights, axis=1, kind="stable")[:, :m]
    kept = np.take_along_axis(weights, order, 1)
    dense = np.zeros_like(weights)
    np.put_along_axis(dense, order, kept / kept.sum(1, keepdims=True), 1)
    return dense


def shape(model, betas, expression=()):
    betas = np.asarray(betas, dtype=np.float64)
    v = model["v_template"] + model["shapedirs"][:, :, :betas.size] @ betas
    expression = np.asarray(expression, dtype=np.float64)
    if expression.size:
        v = v + model["exprdirs"][:, :, :expression.size] @ expression
    return v, model["J_regressor"] @ v


def forward(model, v_shaped, joints, axis_angle, weights):
    """Posed vertices (N,3), posed joints (K,3), features for one pose (K,3)."""
    parents = model["parents"]
    rot = rodrigues(axis_angle)
    features = (rot[1:] - np.eye(3)).reshape(-1)
    v_posed = v_shaped + model["posedirs"] @ features
    k = len(parents)
    world = np.zeros((k, 4, 4))
    for j in range(k):
        local = np.eye(4)
        local[:3, :3] = rot[j]
        local[:3, 3] = joints[j] - (joints[parents[j]] if parents[j] >= 0 else 0)
        world[j] = world[parents[j]] @ local if parents[j] >= 0 else local
    skin = world.copy()
    skin[:, :3, 3] -= np.einsum("kij,kj->ki", world[:, :3, :3], joints)
    blended = np.einsum("nk,kij->nij", weights, skin)
    verts = np.einsum("nij,nj->ni", blended[:, :3, :3], v_posed) + blended[:, :3, 3]
    return verts, world[:, :3, 3], features


def read_reference(prefix):
    """smpl-reference output: header dict and name -> float64 array."""
    with open(prefix + ".json", encoding="utf-8") as f:
        header = json.load(f)
    raw = np.fromfile(prefix + ".bin", dtype="<f8")
    arrays = {}
    for name, spec in header["arrays"].items():
        count = int(np.prod(spec["shape"]))
        arrays[name] = raw[spec["offset"]:spec["offset"] + count].reshape(spec["shape"])
    return header, arrays
