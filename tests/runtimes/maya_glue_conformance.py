"""The Maya package's glue (maya/scripts/smpl_maya, the smplCorrectives node,
with the shared core.py) as a loader of the runtime conformance kit
(docs/conformance.md), against the stand-in Maya API (tests/runtimes/fake_maya).
Per case of a frame Maya delivers (identity_rest and fbx_rotated in a Y-up
scene, z_up in a Z-up scene; Maya has no left-handed import), the joints'
world matrices are the kit's world rotations in Maya's row-vector layout (cm),
their bindPreMatrix the inverse of the rest ones, the blendShape's targets the
sidecar's; smpl_maya.bind reads the case's sidecar and the blend shape
weights after each frame are compared with the kit's (tolerance table).

    /usr/bin/python3 maya_glue_conformance.py --package <build>/maya_stage/maya --kit KIT_DIR
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "conformance"))
from kit import Kit, quaternion_matrix  # noqa: E402

SCENE_UP = {"identity_rest": "y", "fbx_rotated": "y", "z_up": "z"}


def maya_matrix(rotation, translation):
    """Maya's 16 values (row vectors, v' = v M): the transpose of [R | t]."""
    m = np.eye(4)
    m[:3, :3] = rotation.T
    m[3, :3] = translation
    return m.ravel().tolist()


def run_case(cmds, kit, entry, sidecar, data, problems):
    import smpl_maya.bind as sb
    s = cmds.reset()
    s.up = SCENE_UP[entry["frame"]]
    names, parents = sidecar["joint_names"], sidecar["parents"]
    for k, name in enumerate(names):
        s.add("body:" + name, "joint", parent=("body:" + names[parents[k]]) if parents[k] >= 0 else None)
    s.add("body:mesh", "mesh")
    s.add("skinCluster1", "skinCluster")
    s.add("blendShape1", "blendShape")
    s.history["body:mesh"] = ["skinCluster1", "blendShape1"]
    offset = [np.array([0.1 * k, 0.05 * k, -0.02 * k]) for k in range(len(names))]  # cm, any
    for k, name in enumerate(names):
        s.connections["skinCluster1.matrix[%d]" % k] = "body:" + name + ".worldMatrix[0]"
        rest = np.array(maya_matrix(100.0 * np.array(quaternion_matrix(data["rest_world"][k])), offset[k]))
        s.nodes["skinCluster1"]["attrs"]["bindPreMatrix[%d]" % k] = np.linalg.inv(rest.reshape(4, 4)).ravel().tolist()
    targets = [e["target"] for e in sidecar["correctives"]]
    targets += list((sidecar.get("corrective_basis") or {}).get("targets", []))
    alias = []
    for i, t in enumerate(targets):
        alias += [t, "weight[%d]" % i]
    s.aliases["blendShape1"] = alias

    def pose(frame):
        p = data["poses"][int(frame) % len(data["poses"])]
        for k, name in enumerate(names):
            world = 100.0 * np.array(quaternion_matrix(p["world"][k]))
            s.nodes["body:" + name]["world"] = maya_matrix(world, offset[k] + 3.0)

    s.on_time = pose
    pose(0)
    metadata_path = os.path.join(kit.dir, entry["sidecar"])[: -len(".smpl.json")]
    sb.bind("body:mesh", metadata_path=metadata_path)
    tol = kit.tolerance("weights")
    for i, p in enumerate(data["poses"]):
        cmds.currentTime(i)
        got = np.array([cmds.getAttr("blendShape1.weight[%d]" % n) for n in range(len(targets))])
        e = np.abs(got - np.asarray(p["weights"])).max() if len(got) == len(p["weights"]) else np.inf
        if not e <= tol:
            problems.append(f"{entry['name']}: pose {i}: weights differ by {e:.3g} (> {tol:g})")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--package", required=True, help="the Maya package folder (with scripts/, plug-ins/)")
    ap.add_argument("--kit", required=True, help="the conformance kit's folder")
    args = ap.parse_args()
    sys.path[:0] = [os.path.join(HERE, "fake_maya"), os.path.join(args.package, "scripts")]
    os.environ["MAYA_PLUG_IN_PATH"] = os.path.join(args.package, "plug-ins")
    from maya import cmds
    kit = Kit(args.kit)
    problems, cases = [], 0
    for entry, sidecar, data in kit.cases():
        if entry["frame"] in SCENE_UP:
            run_case(cmds, kit, entry, sidecar, data, problems)
            cases += 1
    for p in problems:
        print(p)
    print(f"maya_glue_conformance: {cases} cases, {len(problems)} problems")
    return 1 if problems or cases == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
