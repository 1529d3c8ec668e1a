"""Drive SMPL pose-corrective shape keys from an armature's pose.

The Blender glue of core.py (the math, metadata and weight mapping shared with
the Maya package; no bpy there, tested by CI without Blender). The "robust
runtime formula" of docs/file-contract.md, in Blender terms. For joint k,
with rotations taken in armature space (pose_bone.matrix vs bone.matrix_local):

    D_k = Q_k(now) Q_k(rest)^-1      rotation change since the bind pose
    L_k = D_p(k)^-1 D_k              the joint's own rotation (armature axes)
    R_k = C^-1 L_k C                 back to model axes
    f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc

and shape key `pose_<joint>_<r><c>` gets scale * f + offset (clamped below at
0 for entries marked "rectified", the split encoding's `..._pos`/`..._neg`
keys). An export with
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

Module use (no operator needed), with the add-on enabled; the module is
smpl_correctives.correctives as an add-on (Blender 3.4-4.1) and
bl_ext.<repository>.smpl_correctives.correctives as an extension (4.2+):
    import sys
    correctives = next(m for n, m in sys.modules.items() if n.endswith("smpl_correctives.correctives"))
    correctives.bind(arm, mesh, source_path="body.glb")   # optional: reads metadata
    correctives.apply(arm, mesh)                          # once
    correctives.enable(arm, mesh)                         # every frame / edit
"""
import json

import bpy
import numpy as np
from bpy.app.handlers import persistent
from mathutils import Matrix

from . import core
from .core import metadata_from_file, read_gltf_json  # noqa: F401 (public, used by scripts)

PROP_METADATA = "smpl_metadata"        # JSON text on the armature object
PROP_AXES = "smpl_model_to_armature"   # 9 floats, row-major C, on the armature object
PROP_ENABLED = "smpl_correctives"      # name of the armature, on a driven mesh object
SLIDER_RANGE = (-2.0, 2.0)             # diagonal features reach -2; Blender clamps to [0, 1]


class Binding:
    """Everything apply() needs, resolved once: the core's plan (names ->
    slots, weight mapping, basis), pose bone indices, Q(rest)^-1 and C."""

    def __init__(self):
        self.plan = None         # core.Plan
        self.bone_index = None   # (J,) index into pose.bones of each plan.driven joint
        self.rest_inv = None     # (J,3,3) Q_k(rest)^-1 (armature space)
        self.axes = None         # (3,3) C
        self.signature = None    # detects edits that invalidate the cache


_bindings = {}    # (armature name, mesh name) -> Binding
_enabled = set()  # (armature name, mesh name)
_in_apply = False


# ---------------------------------------------------------------- metadata

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
    to_world = Matrix(core.model_to_world((metadata or {}).get("up_axis", "+Y"), "Z").tolist())
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
    return core.kabsch([joints[n] for n in names],
                       [np.array(armature_obj.data.bones[n].head_local) for n in names])


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
    metadata = core.checked(metadata or metadata_from_file(source_path) or _stored_metadata(armature_obj, mesh_obj))
    if metadata is not None:
        armature_obj[PROP_METADATA] = json.dumps(metadata)
    if source_path or armature_obj.get(PROP_AXES) is None:
        armature_obj[PROP_AXES] = [float(x) for x in _resolve_axes(armature_obj, metadata, source_path).ravel()]
    binding = _build_binding(armature_obj, mesh_obj, metadata)
    _bindings[(armature_obj.name, mesh_obj.name)] = binding
    return len(binding.plan.all_key_index)


def _build_binding(armature_obj, mesh_obj, metadata):
    keys = mesh_obj.data.shape_keys
    blocks = keys.key_blocks if keys else []
    bone_parent = {b.name: (b.parent.name if b.parent else None) for b in armature_obj.data.bones}
    plan = core.make_plan(bone_parent, [block.name for block in blocks], metadata)
    for i in plan.all_key_index:
        blocks[int(i)].slider_min, blocks[int(i)].slider_max = SLIDER_RANGE
    pose_index = {pb.name: i for i, pb in enumerate(armature_obj.pose.bones)}
    b = Binding()
    b.plan = plan
    b.bone_index = np.array([pose_index[n] for n in plan.driven], dtype=np.int64)
    b.rest_inv = core.rest_inverse([np.array(armature_obj.data.bones[n].matrix_local.to_3x3())
                                    for n in plan.driven])
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

def world_rotations(armature_obj, binding, pose_source=None):
    """Q_k(now) of every driven joint, (J,3,3), armature space."""
    bones = (pose_source or armature_obj).pose.bones
    flat = np.empty(len(bones) * 16, dtype=np.float32)
    bones.foreach_get("matrix", flat)
    # foreach_get yields column-major 4x4s: the transpose gives the rotation rows.
    return flat.reshape(-1, 4, 4)[binding.bone_index, :3, :3].transpose(0, 2, 1).astype(np.float64)


def apply(armature_obj, mesh_obj, depsgraph=None):
    """Set every corrective shape key of mesh_obj from armature_obj's pose.

    With a depsgraph, the evaluated pose is read (what handlers should do).
    Returns the key values written (numpy array, binding order).
    """
    binding = _binding(armature_obj, mesh_obj)
    plan = binding.plan
    if plan.all_key_index.size == 0:
        return np.zeros(0)
    source = armature_obj.evaluated_get(depsgraph) if depsgraph is not None else None
    values = core.evaluate(plan, world_rotations(armature_obj, binding, source), binding.rest_inv, binding.axes)
    key = mesh_obj.data.shape_keys
    current = np.empty(len(key.key_blocks), dtype=np.float32)
    key.key_blocks.foreach_get("value", current)
    new = current.copy()
    new[plan.all_key_index] = values
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
