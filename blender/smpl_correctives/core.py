"""The corrective math shared by the Blender add-on and the Maya package: numpy
only, no bpy, no maya import, so CI tests it with /usr/bin/python3.

This file has one copy in the repository (blender/smpl_correctives/core.py).
The Blender add-on zip ships it beside correctives.py; the build copies it into
the Maya package (<build>/maya/smpl_maya/core.py, maya/CMakeLists.txt).

The "robust runtime formula" of docs/file-contract.md. For joint k, with world
rotations Q (any one common space of the engine):

    D_k = Q_k(now) Q_k(rest)^-1      rotation change since the bind pose
    L_k = D_p(k)^-1 D_k              the joint's own rotation (engine axes)
    R_k = C^-1 L_k C                 back to model axes (C: model -> engine axes)
    f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc

and the weight of target `pose_<joint>_<r><c>[_pos|_neg]` is
scale * f + offset, or max(0, scale * f + offset) for entries with
"rectified": true (the split encoding). An export with --corrective-basis
has targets `pose_basis_<k>` driven by scale_k (M f)_k + offset_k, M the
metadata's "corrective_basis" matrix (K x P row-major over the whole f).

Use: plan = make_plan(bone_names, bone_parent, key_names, metadata) once,
then values = evaluate(plan, q_now, rest_inv, axes) per frame, where q_now
and rest_inv are (J,3,3) for plan.driven (in that order).
"""
import json
import math
import os
import re
import struct

import numpy as np

_TARGET = re.compile(r"pose_(.+)_([0-2])([0-2])(?:_(pos|neg))?(?:\.\d+)?$")
ENCODINGS = ("signed", "unit", "split")


# ---------------------------------------------------------------- metadata files

def read_gltf_json(path):
    """The JSON document of a .gltf or .glb file (None if unreadable)."""
    try:
        with open(path, "rb") as f:
            head = f.read(12)
            if len(head) == 12 and head[:4] == b"glTF":
                length, kind = struct.unpack("<II", f.read(8))
                if kind != 0x4E4F534A:
                    return None
                return json.loads(f.read(length).decode("utf-8"))
            return json.loads((head + f.read()).decode("utf-8"))
    except (OSError, ValueError, UnicodeDecodeError, struct.error):
        return None


def metadata_from_file(path):
    """glTF asset.extras.smpl, else the sidecar <path>.smpl.json, else None."""
    if path and os.path.splitext(path)[1].lower() in (".glb", ".gltf"):
        doc = read_gltf_json(path)
        asset = doc.get("asset") if isinstance(doc, dict) else None
        extras = asset.get("extras") if isinstance(asset, dict) else None
        smpl = extras.get("smpl") if isinstance(extras, dict) else None
        if isinstance(smpl, dict):
            return smpl
    if path and os.path.isfile(path + ".smpl.json"):
        try:
            with open(path + ".smpl.json", encoding="utf-8") as f:
                meta = json.load(f)
            return meta if isinstance(meta, dict) else None
        except (OSError, ValueError):
            return None
    return None


def checked(metadata):
    """Metadata with joint_names/parents dropped unless well formed (a list of
    strings and a list of ints of one length, parents[0] = -1 and
    0 <= parents[k] < k): files are untrusted input."""
    if not isinstance(metadata, dict):
        return None
    names, parents = metadata.get("joint_names"), metadata.get("parents")
    ok = (isinstance(names, list) and isinstance(parents, list) and len(names) == len(parents)
          and all(isinstance(n, str) for n in names) and all(isinstance(p, int) for p in parents)
          and len(parents) > 0 and parents[0] == -1 and all(0 <= p < k for k, p in enumerate(parents) if k))
    if not ok:
        metadata = {k: v for k, v in metadata.items() if k not in ("joint_names", "parents", "bone_names")}
    bones = metadata.get("bone_names")
    if bones is not None and not (isinstance(bones, list) and all(isinstance(b, str) for b in bones)
                                  and len(bones) == len(metadata.get("joint_names", [])) and
                                  len(set(bones)) == len(bones)):
        metadata = {k: v for k, v in metadata.items() if k != "bone_names"}
    if not isinstance(metadata.get("correctives", []), list):
        metadata = {k: v for k, v in metadata.items() if k != "correctives"}
    if not isinstance(metadata.get("corrective_basis", {}), dict) or (
            "corrective_basis" in metadata and "joint_names" not in metadata):
        metadata = {k: v for k, v in metadata.items() if k != "corrective_basis"}
    return metadata


def corrective_table(metadata):
    """target name -> (scale, offset, rectified) from the metadata's
    "correctives" (empty: names only). A malformed entry is skipped, and so is
    one whose "feature" is not an index 0 <= n < 9 (joints - 1) when the
    metadata has its joints (the target's name says the feature; a wrong index
    means the file is not what it claims)."""
    table = {}
    names = (metadata or {}).get("joint_names")
    features = 9 * (len(names) - 1) if isinstance(names, list) else None
    for entry in (metadata or {}).get("correctives", []):
        try:
            n = entry.get("feature", 0)
            if features is not None and not (type(n) is int and 0 <= n < features):
                continue
            s, o = float(entry.get("scale", 1.0)), float(entry.get("offset", 0.0))
            if math.isfinite(s) and math.isfinite(o):
                table[str(entry["target"])] = (s, o, entry.get("rectified") is True)
        except (KeyError, TypeError, ValueError, AttributeError):
            continue
    return table


def default_mapping(name):
    """(scale, offset, rectified) of a target when the metadata has no entry for
    it: signed for `pose_<joint>_<rc>`, the split halves for `..._pos`/`..._neg`."""
    m = _TARGET.search(name)
    half = m.group(4) if m else None
    if half == "pos":
        return 1.0, 0.0, True
    if half == "neg":
        return -1.0, 0.0, True
    return 1.0, 0.0, False


def basis_table(metadata):
    """The "corrective_basis" object validated (untrusted input): (targets,
    matrix (K,P), scale (K,), offset (K,)) with P = 9 (joints - 1), else None."""
    basis = (metadata or {}).get("corrective_basis")
    names = (metadata or {}).get("joint_names")
    if basis is None:
        return None
    try:
        targets = [str(t) for t in basis["targets"]]
        p = 9 * (len(names) - 1)
        matrix = np.asarray(basis["matrix"], dtype=np.float64).reshape(len(targets), p)
        scale = np.asarray(basis["scale"], dtype=np.float64).reshape(len(targets))
        offset = np.asarray(basis["offset"], dtype=np.float64).reshape(len(targets))
    except (KeyError, TypeError, ValueError, AttributeError):
        print("smpl_correctives: malformed corrective_basis in the metadata; basis keys not driven")
        return None
    if not (np.isfinite(matrix).all() and np.isfinite(scale).all() and np.isfinite(offset).all()):
        print("smpl_correctives: corrective_basis holds non-finite numbers; basis keys not driven")
        return None
    return targets, matrix, scale, offset


def find_target(name, bone_names):
    """'pose_left_knee_12' or '..._12_pos' (any importer prefix, a '.001'
    suffix) -> (joint, r, c, target name as the exporter wrote it) or None."""
    start = name.find("pose_")
    while start >= 0:
        m = _TARGET.match(name, start)
        if m and m.group(1) in bone_names:
            target = "pose_%s_%s%s" % m.group(1, 2, 3) + ("_" + m.group(4) if m.group(4) else "")
            return m.group(1), int(m.group(2)), int(m.group(3)), target
        start = name.find("pose_", start + 1)
    return None


# ---------------------------------------------------------------- axes

def rotation_x(degrees):
    a = math.radians(degrees)
    return np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])


def model_to_world(up_axis, world_up):
    """C for an engine whose world is `world_up` ('Y' or 'Z') importing a file in
    model axes with `up_axis` ('+Y' as smpl-export writes; '+Z' already Z-up).
    Y-up -> Z-up is the importers' (x, y, z) -> (x, -z, y), +90 degrees about X."""
    if (up_axis or "+Y") == "+Y" and world_up == "Z":
        return rotation_x(90.0)
    if up_axis == "+Z" and world_up == "Y":
        return rotation_x(-90.0)
    return np.eye(3)


def kabsch(model_points, engine_points):
    """Rotation C with C * model ~ engine (Kabsch fit; uniform scale allowed)
    and the RMS residual in engine units with the scale removed; (None, inf)
    with fewer than 3 points. Points: (n,3)."""
    p = np.asarray(model_points, dtype=np.float64).reshape(-1, 3)
    q = np.asarray(engine_points, dtype=np.float64).reshape(-1, 3)
    if len(p) < 3:
        return None, float("inf")
    p, q = p - p.mean(0), q - q.mean(0)
    u, _, vt = np.linalg.svd(q.T @ p)
    c = u @ np.diag([1.0, 1.0, np.sign(np.linalg.det(u @ vt))]) @ vt
    scale = np.linalg.norm(q) / max(np.linalg.norm(p), 1e-12)
    return c, float(np.sqrt(((p @ c.T * scale - q) ** 2).sum(1).mean()))


# ---------------------------------------------------------------- the plan

class Plan:
    """What evaluate() needs, resolved once from names (no engine objects).

    driven: joint names whose world rotation is read, in slot order (J,)
    parent_slot: (J,) slot of each driven joint's parent, -1 = none
    key_index: (T,) index into key_names of each bound corrective target
    key_slot, key_row, key_col: (T,) joint slot, r, c of the feature driving it
    scale, offset: (T,) float; rectified: (T,) bool
    basis_key_index: (B,) index into key_names; basis_slots: (K-1,) slots of
    joints 1..K-1 (f order); basis_matrix (B,P), basis_scale, basis_offset (B,)
    """

    def __init__(self):
        self.driven = []
        self.parent_slot = np.zeros(0, dtype=np.int64)
        self.key_index = self.key_slot = self.key_row = self.key_col = np.zeros(0, dtype=np.int64)
        self.scale = self.offset = np.zeros(0)
        self.rectified = np.zeros(0, dtype=bool)
        self.basis_key_index = self.basis_slots = np.zeros(0, dtype=np.int64)
        self.basis_matrix = np.zeros((0, 0))
        self.basis_scale = self.basis_offset = np.zeros(0)

    @property
    def all_key_index(self):
        return np.concatenate([self.key_index, self.basis_key_index])


def _model_parents(metadata, bone_parent, joints):
    """Parent joint name per driven joint: metadata first, else the engine tree."""
    names = (metadata or {}).get("joint_names")
    parents = (metadata or {}).get("parents")
    by_name = dict(zip(names, parents)) if names else {}  # well formed: see checked()
    out = []
    for j in joints:
        if j in by_name:
            p = by_name[j]
            name = names[p] if isinstance(p, int) and 0 <= p < len(names) else None
            out.append(name if name is not None and name in bone_parent else None)
        else:
            out.append(bone_parent.get(j))
    return out


def _find_basis_keys(key_names, targets):
    """(key index, basis row) of every basis target present (prefix 'Key|' allowed)."""
    row = {t: i for i, t in enumerate(targets)}
    found = []
    for i, name in enumerate(key_names):
        r = row.get(name, row.get(name.rsplit("|", 1)[-1]))
        if r is not None:
            found.append((i, r))
    return found


def bone_of_joint(metadata):
    """Model joint name -> the bone's name in the file, from the metadata's
    "bone_names" (an export with --skeleton-names mixamo|ue5: the bones are
    renamed, the targets pose_<joint>_<rc> keep the model's joint names);
    empty when the bones carry the joint names."""
    names, bones = (metadata or {}).get("joint_names"), (metadata or {}).get("bone_names")
    if not isinstance(names, list) or not isinstance(bones, list) or len(names) != len(bones):
        return {}
    return {j: b for j, b in zip(names, bones) if j != b}


def make_plan(bone_parent, key_names, metadata):
    """Bind target names to joints. bone_parent: engine joint name -> parent
    joint name or None (every joint of the engine skeleton); key_names: the
    mesh's blend shape / shape key names in engine order; metadata: checked()
    dict or None (names only: scale 1, offset 0, parents from the tree).
    With the metadata's "bone_names" the engine's bones are matched through
    them; plan.driven names the engine's bones either way."""
    to_bone = bone_of_joint(metadata)
    if to_bone:  # the plan is made in the model's joint names, then named by the bones
        to_joint = {b: j for j, b in to_bone.items()}
        named = {to_joint.get(b, b): (to_joint.get(p, p) if p else p) for b, p in bone_parent.items()}
        plan = _make_plan(named, key_names, metadata)
        plan.driven = [to_bone.get(j, j) for j in plan.driven]
        return plan
    return _make_plan(bone_parent, key_names, metadata)


def _make_plan(bone_parent, key_names, metadata):
    table = corrective_table(metadata)
    found = [(i, name, find_target(name, bone_parent)) for i, name in enumerate(key_names)]
    found = [(i, name, hit) for i, name, hit in found if hit]
    basis = basis_table(metadata)
    basis_found = _find_basis_keys(key_names, basis[0]) if basis else []
    basis_joints = list((metadata or {}).get("joint_names", []))[1:] if basis_found else []
    if any(j not in bone_parent for j in basis_joints):
        print("smpl_correctives: a joint of the metadata has no bone; basis keys not driven")
        basis_found, basis_joints = [], []
    joints = sorted({hit[0] for _, _, hit in found} | set(basis_joints))
    parents = _model_parents(metadata, bone_parent, joints)
    driven = list(dict.fromkeys(list(joints) + [p for p in parents if p]))  # each joint once
    slot = {name: s for s, name in enumerate(driven)}
    plan = Plan()
    plan.driven = driven
    plan.parent_slot = np.array([slot[p] if p else -1 for p in parents] + [-1] * (len(driven) - len(joints)),
                                dtype=np.int64)
    plan.key_index = np.array([i for i, _, _ in found], dtype=np.int64)
    plan.key_slot = np.array([slot[hit[0]] for _, _, hit in found], dtype=np.int64)
    plan.key_row = np.array([hit[1] for _, _, hit in found], dtype=np.int64)
    plan.key_col = np.array([hit[2] for _, _, hit in found], dtype=np.int64)
    mapping = [table.get(name, table.get(hit[3])) or default_mapping(hit[3]) for _, name, hit in found]
    plan.scale = np.array([m[0] for m in mapping], dtype=np.float64)
    plan.offset = np.array([m[1] for m in mapping], dtype=np.float64)
    plan.rectified = np.array([m[2] for m in mapping], dtype=bool)
    rows = np.array([r for _, r in basis_found], dtype=np.int64)
    plan.basis_key_index = np.array([i for i, _ in basis_found], dtype=np.int64)
    plan.basis_slots = np.array([slot[j] for j in basis_joints], dtype=np.int64)
    if basis_found:
        plan.basis_matrix, plan.basis_scale, plan.basis_offset = basis[1][rows], basis[2][rows], basis[3][rows]
    return plan


# ---------------------------------------------------------------- per frame

def local_rotations(q_now, rest_inv, parent_slot, axes):
    """R_k - I for every driven slot, (J,3,3), model axes. q_now: (J,3,3) world
    rotations now (columns may carry scale: normalised here); rest_inv: (J,3,3)
    Q_k(rest)^-1; axes: C (3,3), model -> engine axes."""
    q = np.asarray(q_now, dtype=np.float64)
    q = q / np.linalg.norm(q, axis=1, keepdims=True)  # drop pose scale (unit columns)
    d = q @ rest_inv
    parent = np.where(parent_slot >= 0, parent_slot, 0)
    d_parent = np.where((parent_slot >= 0)[:, None, None], d[parent], np.eye(3))
    local = np.transpose(d_parent, (0, 2, 1)) @ d
    c = np.asarray(axes, dtype=np.float64)
    return np.linalg.inv(c) @ local @ c - np.eye(3)


def weights(features, scale, offset, rectified):
    """The weight mapping of docs/file-contract.md: scale f + offset, clamped
    below at 0 where rectified (the split encoding)."""
    w = np.asarray(scale) * np.asarray(features) + np.asarray(offset)
    return np.where(rectified, np.maximum(w, 0.0), w)


def evaluate(plan, q_now, rest_inv, axes):
    """Weights of every bound key, in plan.all_key_index order."""
    if plan.key_index.size == 0 and plan.basis_key_index.size == 0:
        return np.zeros(0)
    feats = local_rotations(q_now, rest_inv, plan.parent_slot, axes)
    values = weights(feats[plan.key_slot, plan.key_row, plan.key_col], plan.scale, plan.offset, plan.rectified)
    if plan.basis_key_index.size:  # f in docs/file-contract.md order: joint k's R - I row-major
        f = feats[plan.basis_slots].reshape(-1)
        values = np.concatenate([values, plan.basis_scale * (plan.basis_matrix @ f) + plan.basis_offset])
    return values


def rest_inverse(rest):
    """(J,3,3) Q(rest)^-1 from rest world matrices (columns may carry scale)."""
    r = np.asarray(rest, dtype=np.float64).reshape(-1, 3, 3)
    r = r / np.linalg.norm(r, axis=1, keepdims=True)
    return np.transpose(r, (0, 2, 1))
