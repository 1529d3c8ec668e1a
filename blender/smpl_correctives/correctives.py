"""Drive SMPL pose-corrective shape keys from an armature's pose.

The "robust runtime formula" of docs/file-contract.md, in Blender terms. For joint k,
with rotations taken in armature space (pose_bone.matrix vs bone.matrix_local):

    D_k = Q_k(now) Q_k(rest)^-1      rotation change since the bind pose
    L_k = D_p(k)^-1 D_k              the joint's own rotation (armature axes)
    R_k = C^-1 L_k C                 back to model axes
    f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc

and shape key `pose_<joint>_<r><c>` gets scale * f + offset. An export with
`--corrective-basis K` has K keys `pose_basis_<k>` instead, listed in the
metadata's "corrective_basis" (targets, matrix C: K x P row-major over the
whole f, scale, offset): key k gets scale_k * (C f)_k + offset_k. Importers
re-orient bones (the glTF importer rolls them, FBX adds pre-rotations), which
this cancels: only world-space rotation changes are read, never local ones.

C maps model axes (+Y up) to armature axes. Blender's world is +Z up and both
the glTF and the FBX importer convert +Y up to +Z up (x, y, z) -> (x, -z, y),
a +90 degree turn about X. The glTF importer bakes that into the bones
(armature object = identity); the FBX importer puts it on the armature object.
So C = A^-1 * Rx(90), A the armature object's world rotation at bind time.
It is stored on the armature, so moving the character later changes nothing.

Module use (no operator needed):
    from smpl_correctives import correctives
    correctives.bind(arm, mesh, source_path="body.glb")   # optional: reads metadata
    correctives.apply(arm, mesh)                          # once
    correctives.enable(arm, mesh)                         # every frame / edit
"""
import json
import math
import os
import re
import struct

import bpy
import numpy as np
from bpy.app.handlers import persistent
from mathutils import Matrix

PROP_METADATA = "smpl_metadata"        # JSON text on the armature object
PROP_AXES = "smpl_model_to_armature"   # 9 floats, row-major C, on the armature object
PROP_ENABLED = "smpl_correctives"      # name of the armature, on a driven mesh object
SLIDER_RANGE = (-2.0, 2.0)             # diagonal features reach -2; Blender clamps to [0, 1]
_TARGET = re.compile(r"pose_(.+)_([0-2])([0-2])(?:\.\d+)?$")


class Binding:
    """Everything apply() needs, resolved once: bone indices, key indices, C."""

    def __init__(self):
        self.bone_index = None   # (J,) index into pose.bones of each driven joint
        self.parent_slot = None  # (J,) slot of the parent joint in bone_index, -1 = none
        self.rest_inv = None     # (J,3,3) Q_k(rest)^-1 (armature space)
        self.key_index = None    # (T,) index into key_blocks
        self.key_joint = None    # (T,) slot of the joint whose R drives the key
        self.key_row = None      # (T,) r
        self.key_col = None      # (T,) c
        self.scale = None        # (T,)
        self.offset = None       # (T,)
        self.basis_key_index = None  # (B,) index into key_blocks of each basis key
        self.basis_slots = None      # (K-1,) slot of joint k = 1..K-1: f = features[slots]
        self.basis_matrix = None     # (B, 9(K-1)) rows of C for the bound basis keys
        self.basis_scale = None      # (B,)
        self.basis_offset = None     # (B,)
        self.axes = None         # (3,3) C
        self.signature = None    # detects edits that invalidate the cache


_bindings = {}    # (armature name, mesh name) -> Binding
_enabled = set()  # (armature name, mesh name)
_in_apply = False


# ---------------------------------------------------------------- metadata

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


def _checked(metadata):
    """Metadata with joint_names/parents dropped unless well formed (a list of
    strings and a list of ints of one length): files are untrusted input."""
    if not isinstance(metadata, dict):
        return None
    names, parents = metadata.get("joint_names"), metadata.get("parents")
    ok = (isinstance(names, list) and isinstance(parents, list) and len(names) == len(parents)
          and all(isinstance(n, str) for n in names) and all(isinstance(p, int) for p in parents))
    if not ok:
        metadata = {k: v for k, v in metadata.items() if k not in ("joint_names", "parents")}
    if not isinstance(metadata.get("correctives", []), list):
        metadata = {k: v for k, v in metadata.items() if k != "correctives"}
    if not isinstance(metadata.get("corrective_basis", {}), dict) or (
            "corrective_basis" in metadata and "joint_names" not in metadata):
        metadata = {k: v for k, v in metadata.items() if k != "corrective_basis"}
    return metadata


def _stored_metadata(armature_obj, mesh_obj):
    for holder in (armature_obj, mesh_obj, mesh_obj.data, bpy.context.scene):
        value = holder.get(PROP_METADATA) if holder is not None else None
        if value is None and holder is not None:
            value = holder.get("smpl")  # glTF scene/node extras land here
        if isinstance(value, str):
            try:
                value = json.loads(value)
            except ValueError:
                continue
            if isinstance(value, dict):
                return value
        if value is not None and hasattr(value, "to_dict"):
            return value.to_dict()
    return None


# ---------------------------------------------------------------- binding

def _model_to_armature(armature_obj, metadata):
    up = (metadata or {}).get("up_axis", "+Y")
    to_world = Matrix.Rotation(math.radians(90.0), 3, "X") if up == "+Y" else Matrix.Identity(3)
    arm_rot = armature_obj.matrix_world.to_3x3().normalized()
    return np.array(arm_rot.inverted() @ to_world, dtype=np.float64)


def _gltf_rest_joints(doc, names):
    """Rest joint positions (model axes) from a glTF's joint nodes: the
    exporter writes identity rotations, so positions are sums of translations."""
    nodes = (doc or {}).get("nodes") or []
    parent = {c: i for i, n in enumerate(nodes) for c in n.get("children", [])}
    by_name = {n.get("name"): i for i, n in enumerate(nodes)}
    out = {}
    for name in names:
        i, pos, steps = by_name.get(name), np.zeros(3), 0
        while i is not None and steps <= len(nodes):  # a cyclic file must not hang us
            steps += 1
            pos += np.asarray(nodes[i].get("translation", [0.0, 0.0, 0.0]), dtype=np.float64)
            i = parent.get(i)
        if name in by_name:
            out[name] = pos
    return out


def fit_axes(armature_obj, joints):
    """Rotation C with C * (model joint) ~ bone head (armature space), by the
    Kabsch fit, and the RMS residual in armature units (scale removed)."""
    names = [n for n in joints if n in armature_obj.data.bones]
    if len(names) < 3:
        return None, float("inf")
    p = np.array([joints[n] for n in names])
    q = np.array([np.array(armature_obj.data.bones[n].head_local) for n in names])
    p, q = p - p.mean(0), q - q.mean(0)
    u, _, vt = np.linalg.svd(q.T @ p)
    c = u @ np.diag([1.0, 1.0, np.sign(np.linalg.det(u @ vt))]) @ vt
    scale = np.linalg.norm(q) / max(np.linalg.norm(p), 1e-12)
    return c, float(np.sqrt(((p @ c.T * scale - q) ** 2).sum(1).mean()))


def _find_target(name, bone_names):
    """'pose_left_knee_12' (any importer prefix/suffix) -> (joint, r, c) or None."""
    start = name.find("pose_")
    while start >= 0:
        m = _TARGET.match(name, start)
        if m and m.group(1) in bone_names:
            return m.group(1), int(m.group(2)), int(m.group(3))
        start = name.find("pose_", start + 1)
    return None


def _corrective_table(metadata):
    """target name -> (scale, offset) from the metadata (empty: names only)."""
    table = {}
    for entry in (metadata or {}).get("correctives", []):
        try:
            table[str(entry["target"])] = (float(entry.get("scale", 1.0)), float(entry.get("offset", 0.0)))
        except (KeyError, TypeError, ValueError, AttributeError):
            continue  # a malformed entry falls back to names (scale 1, offset 0)
    return table


def _basis_table(metadata):
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


def _find_basis_keys(blocks, targets):
    """(key index, basis row) of every basis target present (importer prefixes 'Key|' allowed)."""
    row = {t: i for i, t in enumerate(targets)}
    found = []
    for i, block in enumerate(blocks):
        r = row.get(block.name, row.get(block.name.rsplit("|", 1)[-1]))
        if r is not None:
            found.append((i, r))
            block.slider_min, block.slider_max = SLIDER_RANGE
    return found


def _model_parents(metadata, arm_data, joints):
    """Parent joint name per driven joint: metadata first, else the bone tree."""
    names = (metadata or {}).get("joint_names")
    parents = (metadata or {}).get("parents")
    by_name = dict(zip(names, parents)) if names else {}  # well formed: see _checked()
    bones = arm_data.bones
    out = []
    for j in joints:
        if j in by_name:
            p = by_name[j]
            name = names[p] if isinstance(p, int) and 0 <= p < len(names) else None
            out.append(name if name is not None and name in bones else None)
        else:
            parent = arm_data.bones[j].parent
            out.append(parent.name if parent else None)
    return out


def _signature(armature_obj, mesh_obj):
    keys = mesh_obj.data.shape_keys
    return (len(armature_obj.pose.bones), len(keys.key_blocks) if keys else 0,
            armature_obj.get(PROP_AXES) is not None)


def _resolve_axes(armature_obj, metadata, source_path):
    """C by the import convention, checked against the glTF skeleton when the
    file is at hand: an importer option (or a future importer) that orients
    differently must not go unnoticed; the fitted rotation then wins."""
    axes = _model_to_armature(armature_obj, metadata)
    gltf = source_path and source_path.lower().endswith((".glb", ".gltf"))
    doc = read_gltf_json(source_path) if gltf else None
    if doc is None:
        return axes
    fitted, residual = fit_axes(armature_obj, _gltf_rest_joints(doc, armature_obj.data.bones.keys()))
    if fitted is not None and residual < 1e-4 and np.abs(fitted - axes).max() > 1e-4:
        print("smpl_correctives: %s: bones are not oriented by the +Y-up convention; "
              "using the rotation fitted to the skeleton" % source_path)
        return fitted
    return axes


def bind(armature_obj, mesh_obj, source_path=None, metadata=None):
    """Resolve the corrective keys of mesh_obj against armature_obj's bones.

    Metadata: given, else read from source_path (glTF extras / sidecar), else
    stored on the objects by an earlier bind, else names only (scale 1,
    offset 0, parents from the bone tree). Widens every corrective key's
    slider range, stores metadata and C on the armature. Returns the number
    of bound shape keys.
    """
    metadata = _checked(metadata or metadata_from_file(source_path) or _stored_metadata(armature_obj, mesh_obj))
    if metadata is not None:
        armature_obj[PROP_METADATA] = json.dumps(metadata)
    if source_path or armature_obj.get(PROP_AXES) is None:
        armature_obj[PROP_AXES] = [float(x) for x in _resolve_axes(armature_obj, metadata, source_path).ravel()]
    binding = _build_binding(armature_obj, mesh_obj, metadata)
    _bindings[(armature_obj.name, mesh_obj.name)] = binding
    return len(binding.key_index) + len(binding.basis_key_index)


def _build_binding(armature_obj, mesh_obj, metadata):
    keys = mesh_obj.data.shape_keys
    blocks = keys.key_blocks if keys else []
    bone_names = {b.name for b in armature_obj.data.bones}
    table = _corrective_table(metadata)
    found = []
    for i, block in enumerate(blocks):
        hit = _find_target(block.name, bone_names)
        if hit:
            found.append((i, block, hit))
            block.slider_min, block.slider_max = SLIDER_RANGE
    basis = _basis_table(metadata)
    basis_found = _find_basis_keys(blocks, basis[0]) if basis else []
    basis_joints = list((metadata or {}).get("joint_names", []))[1:] if basis_found else []
    if any(j not in bone_names for j in basis_joints):
        print("smpl_correctives: a joint of the metadata has no bone; basis keys not driven")
        basis_found, basis_joints = [], []
    joints = sorted({hit[0] for _, _, hit in found} | set(basis_joints))
    parents = _model_parents(metadata, armature_obj.data, joints)
    driven = list(joints) + [p for p in parents if p and p not in joints]
    slot = {name: s for s, name in enumerate(driven)}
    pose_index = {pb.name: i for i, pb in enumerate(armature_obj.pose.bones)}
    b = Binding()
    b.bone_index = np.array([pose_index[n] for n in driven], dtype=np.int64)
    b.parent_slot = np.array([slot[p] if p else -1 for p in parents] + [-1] * (len(driven) - len(joints)),
                             dtype=np.int64)
    rest = np.array([np.array(armature_obj.data.bones[n].matrix_local.to_3x3().normalized()) for n in driven])
    b.rest_inv = np.transpose(rest.reshape(-1, 3, 3), (0, 2, 1))
    b.key_index = np.array([i for i, _, _ in found], dtype=np.int64)
    b.key_joint = np.array([slot[hit[0]] for _, _, hit in found], dtype=np.int64)
    b.key_row = np.array([hit[1] for _, _, hit in found], dtype=np.int64)
    b.key_col = np.array([hit[2] for _, _, hit in found], dtype=np.int64)
    scale_offset = [table.get(block.name, table.get("pose_%s_%d%d" % hit, (1.0, 0.0)))
                    for _, block, hit in found]
    b.scale = np.array([s for s, _ in scale_offset], dtype=np.float64)
    b.offset = np.array([o for _, o in scale_offset], dtype=np.float64)
    rows = np.array([r for _, r in basis_found], dtype=np.int64)
    b.basis_key_index = np.array([i for i, _ in basis_found], dtype=np.int64)
    b.basis_slots = np.array([slot[j] for j in basis_joints], dtype=np.int64)
    b.basis_matrix = basis[1][rows] if basis_found else np.zeros((0, 0))
    b.basis_scale = basis[2][rows] if basis_found else np.zeros(0)
    b.basis_offset = basis[3][rows] if basis_found else np.zeros(0)
    b.axes = np.array(armature_obj.get(PROP_AXES), dtype=np.float64).reshape(3, 3)
    b.signature = _signature(armature_obj, mesh_obj)
    return b


def _binding(armature_obj, mesh_obj):
    b = _bindings.get((armature_obj.name, mesh_obj.name))
    if b is None or b.signature != _signature(armature_obj, mesh_obj):
        bind(armature_obj, mesh_obj)
        b = _bindings[(armature_obj.name, mesh_obj.name)]
    return b


# ---------------------------------------------------------------- per frame

def pose_features(armature_obj, binding, pose_source=None):
    """R_k - I for every driven joint slot, (J,3,3), model axes."""
    bones = (pose_source or armature_obj).pose.bones
    flat = np.empty(len(bones) * 16, dtype=np.float32)
    bones.foreach_get("matrix", flat)
    # foreach_get yields column-major 4x4s: the transpose gives the rotation rows.
    q_now = flat.reshape(-1, 4, 4)[binding.bone_index, :3, :3].transpose(0, 2, 1).astype(np.float64)
    q_now /= np.linalg.norm(q_now, axis=1, keepdims=True)  # drop pose scale (unit columns)
    d = q_now @ binding.rest_inv
    parent = np.where(binding.parent_slot >= 0, binding.parent_slot, 0)
    d_parent = np.where((binding.parent_slot >= 0)[:, None, None], d[parent], np.eye(3))
    local = np.transpose(d_parent, (0, 2, 1)) @ d
    c = binding.axes
    return c.T @ local @ c - np.eye(3)


def apply(armature_obj, mesh_obj, depsgraph=None):
    """Set every corrective shape key of mesh_obj from armature_obj's pose.

    With a depsgraph, the evaluated pose is read (what handlers should do).
    Returns the key values written (numpy array, binding order).
    """
    binding = _binding(armature_obj, mesh_obj)
    if binding.key_index.size == 0 and binding.basis_key_index.size == 0:
        return np.zeros(0)
    source = armature_obj.evaluated_get(depsgraph) if depsgraph is not None else None
    features = pose_features(armature_obj, binding, source)
    values = binding.scale * features[binding.key_joint, binding.key_row, binding.key_col] + binding.offset
    if binding.basis_key_index.size:  # f in docs/file-contract.md order: joint k's R - I row-major
        f = features[binding.basis_slots].reshape(-1)
        values = np.concatenate([values, binding.basis_scale * (binding.basis_matrix @ f) + binding.basis_offset])
    key = mesh_obj.data.shape_keys
    current = np.empty(len(key.key_blocks), dtype=np.float32)
    key.key_blocks.foreach_get("value", current)
    new = current.copy()
    new[np.concatenate([binding.key_index, binding.basis_key_index])] = values
    if not np.array_equal(new, current):  # writing tags a depsgraph update: only on change
        key.key_blocks.foreach_set("value", new)
        key.update_tag()
    return values


# ---------------------------------------------------------------- handlers

def _run_enabled(scene, depsgraph=None):
    global _in_apply
    if _in_apply:
        return
    _in_apply = True
    try:
        for arm_name, mesh_name in list(_enabled):
            arm, mesh = bpy.data.objects.get(arm_name), bpy.data.objects.get(mesh_name)
            # Objects may be gone, renamed or data-less while a file or the
            # factory settings load: forget them instead of raising.
            if (arm is None or mesh is None or mesh.type != "MESH" or mesh.data is None
                    or mesh.data.shape_keys is None):
                _enabled.discard((arm_name, mesh_name))
                continue
            apply(arm, mesh, depsgraph)
    finally:
        _in_apply = False


@persistent
def _on_frame_change(scene, depsgraph=None):
    _run_enabled(scene, depsgraph)


@persistent
def _on_depsgraph_update(scene, depsgraph=None):
    _run_enabled(scene, depsgraph)


@persistent
def _on_load(*_args):
    """Re-enable meshes that were driven when the file was saved."""
    _enabled.clear()
    _bindings.clear()
    for obj in bpy.data.objects:
        arm = bpy.data.objects.get(obj.get(PROP_ENABLED, "")) if obj.type == "MESH" else None
        if arm is not None:
            _enabled.add((arm.name, obj.name))
    _install_handlers(bool(_enabled))


def _install_handlers(on):
    for handlers, fn in ((bpy.app.handlers.frame_change_post, _on_frame_change),
                         (bpy.app.handlers.depsgraph_update_post, _on_depsgraph_update)):
        while fn in handlers:
            handlers.remove(fn)
        if on:
            handlers.append(fn)


def enable(armature_obj, mesh_obj):
    """Drive mesh_obj's correctives on every frame change and edit."""
    _binding(armature_obj, mesh_obj)
    mesh_obj[PROP_ENABLED] = armature_obj.name
    _enabled.add((armature_obj.name, mesh_obj.name))
    _install_handlers(True)
    apply(armature_obj, mesh_obj)


def disable(armature_obj, mesh_obj):
    """Stop driving mesh_obj (its key values stay as they are)."""
    if PROP_ENABLED in mesh_obj:
        del mesh_obj[PROP_ENABLED]
    _enabled.discard((armature_obj.name, mesh_obj.name))
    _install_handlers(bool(_enabled))


def is_enabled(armature_obj, mesh_obj):
    return (armature_obj.name, mesh_obj.name) in _enabled


def register_load_handler(on):
    handlers = bpy.app.handlers.load_post
    while _on_load in handlers:
        handlers.remove(_on_load)
    if on:
        handlers.append(_on_load)
    else:
        _install_handlers(False)


# ---------------------------------------------------------------- discovery

def skinned_meshes(armature_obj):
    """Mesh objects deformed by armature_obj through an Armature modifier."""
    return [o for o in bpy.data.objects if o.type == "MESH" and any(
        m.type == "ARMATURE" and m.object == armature_obj for m in o.modifiers)]


def armature_of(mesh_obj):
    for m in mesh_obj.modifiers:
        if m.type == "ARMATURE" and m.object is not None:
            return m.object
    return mesh_obj.parent if mesh_obj.parent and mesh_obj.parent.type == "ARMATURE" else None
