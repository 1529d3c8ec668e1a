"""The smplCorrectives dependency node: corrective blend shape weights from the
joints' world matrices, evaluated by Maya's dependency graph.

Why a node (and not a scriptJob or expression): the weights then depend on the
joints through ordinary connections (joint.worldMatrix[0] -> inMatrix[slot],
outWeight[t] -> blendShape.weight[i]), so they follow every pose change, time
change, playblast, render and the parallel evaluator, are cached like any other
attribute, and bake to keys with Maya's own Edit > Keys > Bake Simulation
(smpl_maya.bind.bake). A scriptJob would only run in the interactive UI, after
the fact, and not during playblasts or batch renders.

Attributes:
  layout    string   JSON written by smpl_maya.bind: the core plan (which joint
                     slot, matrix element and weight mapping drives each output),
                     C and the rest rotations Q(rest)^-1
  inMatrix  matrix[] world matrix of driven joint slot j (Maya's row-vector layout)
  outWeight double[] weight of bound blend shape target t

The math is core.evaluate (shared with the Blender add-on, tested in CI).
"""
import json

import numpy as np

import maya.api.OpenMaya as om

from . import core

NODE_NAME = "smplCorrectives"
NODE_ID = om.MTypeId(0x0007F5C1)  # 0x0-0x7FFFF: Autodesk's range for local, unregistered plug-ins


def maya_useNewAPI():
    """Tells Maya this plug-in uses maya.api.OpenMaya (API 2.0)."""


def plan_to_json(plan, axes, rest_inv):
    """The node's layout string: a core.Plan with C (3,3) and Q(rest)^-1 (J,3,3)."""
    arrays = ("parent_slot", "key_index", "key_slot", "key_row", "key_col", "scale", "offset",
              "rectified", "basis_key_index", "basis_slots", "basis_matrix", "basis_scale", "basis_offset")
    doc = {name: np.asarray(getattr(plan, name)).tolist() for name in arrays}
    doc["driven"] = list(plan.driven)
    doc["axes"] = np.asarray(axes, dtype=np.float64).tolist()
    doc["rest_inv"] = np.asarray(rest_inv, dtype=np.float64).tolist()
    return json.dumps(doc)


def plan_from_json(text):
    """(plan, axes, rest_inv) from a layout string; ValueError if malformed."""
    try:
        doc = json.loads(text)
        plan = core.Plan()
        plan.driven = [str(n) for n in doc["driven"]]
        for name in ("parent_slot", "key_index", "key_slot", "key_row", "key_col", "basis_key_index", "basis_slots"):
            setattr(plan, name, np.asarray(doc[name], dtype=np.int64).reshape(-1))
        for name in ("scale", "offset", "basis_scale", "basis_offset"):
            setattr(plan, name, np.asarray(doc[name], dtype=np.float64).reshape(-1))
        plan.rectified = np.asarray(doc["rectified"], dtype=bool).reshape(-1)
        basis = np.asarray(doc["basis_matrix"], dtype=np.float64)
        plan.basis_matrix = basis.reshape(len(plan.basis_key_index), -1) if basis.size else np.zeros((0, 0))
        axes = np.asarray(doc["axes"], dtype=np.float64).reshape(3, 3)
        rest_inv = np.asarray(doc["rest_inv"], dtype=np.float64).reshape(len(plan.driven), 3, 3)
    except (KeyError, TypeError, ValueError) as e:
        raise ValueError("smplCorrectives: malformed layout (%s)" % e)
    return plan, axes, rest_inv


def rotation_of(maya_matrix):
    """Q (3,3), column-vector convention, from a Maya 4x4 (row vectors: v' = v M,
    so the rotation is the transpose of the upper-left block)."""
    return np.array([maya_matrix[i] for i in range(16)], dtype=np.float64).reshape(4, 4)[:3, :3].T


class SmplCorrectivesNode(om.MPxNode):
    a_layout = None
    a_matrix = None
    a_weight = None

    def __init__(self):
        om.MPxNode.__init__(self)
        self._cache = (None, None)  # (layout string, parsed)

    def _layout(self, data):
        text = data.inputValue(SmplCorrectivesNode.a_layout).asString()
        if self._cache[0] != text:
            try:
                self._cache = (text, plan_from_json(text) if text else None)
            except ValueError as e:
                om.MGlobal.displayError(str(e))
                self._cache = (text, None)
        return self._cache[1]

    def compute(self, plug, data):
        if plug != SmplCorrectivesNode.a_weight and not (
                plug.isElement and plug.array() == SmplCorrectivesNode.a_weight):
            return None  # unknown plug: Maya's default handling
        parsed = self._layout(data)
        values = np.zeros(0)
        if parsed is not None:
            plan, axes, rest_inv = parsed
            q_now = np.array(rest_inv).transpose(0, 2, 1)  # unconnected slots stay at rest
            matrices = data.inputArrayValue(SmplCorrectivesNode.a_matrix)
            for i in range(len(matrices)):
                matrices.jumpToPhysicalElement(i)
                slot = matrices.elementLogicalIndex()
                if slot < len(q_now):
                    q_now[slot] = rotation_of(matrices.inputValue().asMatrix())
            values = core.evaluate(plan, q_now, rest_inv, axes)
        out = data.outputArrayValue(SmplCorrectivesNode.a_weight)
        builder = out.builder()
        for t, v in enumerate(values):
            builder.addElement(t).setDouble(float(v))
        out.set(builder)
        out.setAllClean()
        data.setClean(plug)
        return self


def _creator():
    return SmplCorrectivesNode()


def _initialize():
    typed, matrix, numeric = om.MFnTypedAttribute(), om.MFnMatrixAttribute(), om.MFnNumericAttribute()
    SmplCorrectivesNode.a_layout = typed.create("layout", "lay", om.MFnData.kString)
    SmplCorrectivesNode.a_matrix = matrix.create("inMatrix", "im", om.MFnMatrixAttribute.kDouble)
    matrix.array = True
    SmplCorrectivesNode.a_weight = numeric.create("outWeight", "ow", om.MFnNumericData.kDouble, 0.0)
    numeric.array = True
    numeric.usesArrayDataBuilder = True
    numeric.writable = False
    numeric.storable = False
    for a in (SmplCorrectivesNode.a_layout, SmplCorrectivesNode.a_matrix, SmplCorrectivesNode.a_weight):
        om.MPxNode.addAttribute(a)
    om.MPxNode.attributeAffects(SmplCorrectivesNode.a_layout, SmplCorrectivesNode.a_weight)
    om.MPxNode.attributeAffects(SmplCorrectivesNode.a_matrix, SmplCorrectivesNode.a_weight)


def initializePlugin(obj):
    om.MFnPlugin(obj, "smpl-export", "0.1.0", "Any").registerNode(NODE_NAME, NODE_ID, _creator, _initialize)


def uninitializePlugin(obj):
    om.MFnPlugin(obj).deregisterNode(NODE_ID)
