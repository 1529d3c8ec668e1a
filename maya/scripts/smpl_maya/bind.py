"""Bind an imported smpl-export FBX in Maya: find its joints (by name), its
blend shape targets (by target name) and the sidecar metadata, create one
smplCorrectives node and connect it (joint.worldMatrix[0] -> node.inMatrix[slot],
node.outWeight[t] -> blendShape.weight[i]). Also: bake the driven weights to
keys over a frame range, and unbind.

    import smpl_maya.bind as sb
    node = sb.bind("body_mesh", metadata_path="body.fbx.smpl.json")
    sb.bake(node, 1, 120)

Only maya.cmds is used here (tests/runtimes/fake_maya stands in for it in CI).
"""
import json
import os

import numpy as np

from maya import cmds

from . import core
from .node import NODE_NAME, plan_to_json, rotation_of

PLUGIN = "smpl_correctives_node"


def short_name(node):
    """'|grp|ns:pelvis' -> 'pelvis': FBX imports may add namespaces and paths."""
    return node.rsplit("|", 1)[-1].rsplit(":", 1)[-1]


def read_metadata(path):
    """The sidecar JSON (core.checked), or None when absent or unreadable."""
    if not path:
        return None
    if not path.endswith(".smpl.json") and os.path.isfile(path + ".smpl.json"):
        path += ".smpl.json"
    try:
        with open(path, encoding="utf-8") as f:
            return core.checked(json.load(f))
    except (OSError, ValueError):
        cmds.warning("smpl_maya: %s: cannot read the metadata; binding by names only" % path)
        return None


def _history(mesh, node_type):
    return cmds.ls(cmds.listHistory(mesh) or [], type=node_type) or []


def _skin_joints(skin):
    """{short joint name: (joint node, rest world matrix as Maya's 16 values)}:
    the rest pose is the inverse of the skinCluster's bindPreMatrix, so binding
    works whatever pose the scene is in."""
    out = {}
    for index in cmds.getAttr(skin + ".matrix", multiIndices=True) or []:
        source = cmds.connectionInfo("%s.matrix[%d]" % (skin, index), sourceFromDestination=True)
        if not source:
            continue
        joint = source.split(".")[0]
        pre = np.array(cmds.getAttr("%s.bindPreMatrix[%d]" % (skin, index)), dtype=np.float64).reshape(4, 4)
        out[short_name(joint)] = (joint, np.linalg.inv(pre).ravel())
    return out


def _bone_parents(joints):
    """{short name: short name of the parent joint or None}."""
    out = {}
    for name, (node, _) in joints.items():
        parent = cmds.listRelatives(node, parent=True, type="joint")
        out[name] = short_name(parent[0]) if parent else None
    return out


def _target_names(blend_shape):
    """[(weight index, target name)] from the blend shape's aliases."""
    alias = cmds.aliasAttr(blend_shape, query=True) or []
    pairs = []
    for name, attr in zip(alias[0::2], alias[1::2]):
        if attr.startswith("weight[") and attr.endswith("]"):
            pairs.append((int(attr[7:-1]), name))
    return sorted(pairs)


def scene_axes(metadata):
    """C: model axes (the metadata's up_axis, +Y) -> Maya world axes. The FBX
    importer converts the file's +Y up to a Z-up scene by turning the content."""
    up = (cmds.upAxis(query=True, axis=True) or "y").upper()
    return core.model_to_world((metadata or {}).get("up_axis", "+Y"), up)


def bind(mesh, metadata_path=None, name=None):
    """Create and connect a smplCorrectives node for `mesh` (transform or shape
    with a skinCluster and a blendShape). Returns the node's name. Raises
    RuntimeError with one line naming the problem."""
    if not cmds.pluginInfo(PLUGIN, query=True, loaded=True):
        cmds.loadPlugin(PLUGIN + ".py", quiet=True)
    skins, shapes = _history(mesh, "skinCluster"), _history(mesh, "blendShape")
    if not skins or not shapes:
        raise RuntimeError("%s: no skinCluster and blendShape in its history; import an smpl-export FBX "
                           "with Animation > Deformed Models > Skins and Blend Shapes on" % mesh)
    metadata = read_metadata(metadata_path)
    joints = _skin_joints(skins[0])
    targets = _target_names(shapes[0])
    plan = core.make_plan(_bone_parents(joints), [t for _, t in targets], metadata)
    if plan.all_key_index.size == 0:
        raise RuntimeError("%s: no blend shape target is named pose_<joint>_<r><c> (or pose_basis_<k> "
                           "with metadata)" % shapes[0])
    rest = np.array([rotation_of(joints[j][1]) for j in plan.driven])
    node = cmds.createNode(NODE_NAME, name=name or short_name(mesh) + "_smplCorrectives")
    cmds.setAttr(node + ".layout", plan_to_json(plan, scene_axes(metadata), core.rest_inverse(rest)), type="string")
    for slot, j in enumerate(plan.driven):
        cmds.connectAttr(joints[j][0] + ".worldMatrix[0]", "%s.inMatrix[%d]" % (node, slot), force=True)
    for t, key in enumerate(plan.all_key_index):
        cmds.connectAttr("%s.outWeight[%d]" % (node, t), "%s.weight[%d]" % (shapes[0], targets[int(key)][0]),
                         force=True)
    return node


def driven_weights(node):
    """The blendShape weight plugs a smplCorrectives node drives."""
    return cmds.listConnections(node + ".outWeight", source=False, destination=True, plugs=True) or []


def bake(node, start, end):
    """Key every driven blend shape weight on each whole frame of [start, end]
    (read through the graph, so exactly what the node computes), then delete
    the node: the keys play with no plug-in, like an exported bake. Returns
    the baked plugs."""
    plugs = driven_weights(node)
    if not plugs:
        raise RuntimeError("%s: drives no blend shape weight" % node)
    frames = list(range(int(round(start)), int(round(end)) + 1))
    now = cmds.currentTime(query=True)
    values = {p: [] for p in plugs}
    for frame in frames:
        cmds.currentTime(frame, update=True)
        for p in plugs:
            values[p].append(cmds.getAttr(p))
    cmds.delete(node)  # frees the weights for keys
    for p in plugs:
        for frame, value in zip(frames, values[p]):
            cmds.setKeyframe(p, time=frame, value=value)
    cmds.currentTime(now, update=True)
    return plugs


def unbind(node):
    """Delete the node; the weights keep their last values."""
    cmds.delete(node)
