#!/usr/bin/python3
"""The independent side of the MJCF checks (tests/roundtrip/mjcf_check.cpp):
rest joints and the closed rest mesh's volume, in the model's Y-up axes, from
a source other than the MJCF writer.

    mjcf_reference.py --glb ASSET.glb OUT.txt
        joints: the GLB's skin joint nodes, world position = the sum of the
        node translations from the scene root (rest rotations are identity,
        docs/file-contract.md); volume: the GLB mesh's POSITION and indices.
    mjcf_reference.py --model MODEL.npz [--betas v,v,..] OUT.txt
        numpy from the model file alone (model_math.shape: v_shaped and
        J = J_regressor v_shaped; volume from v_shaped and the faces `f`).

Volume: sum over triangles of v0 . (v1 x v2) / 6 (signed tetrahedra from the
origin, divergence theorem), in float64.

OUT.txt: "volume V" then one "joint NAME X Y Z" line per joint (metres).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import model_math  # noqa: E402
import skin_fit_check  # noqa: E402  (read_glb, accessor)


def signed_volume(vertices, faces):
    v = np.asarray(vertices, np.float64)[np.asarray(faces, np.int64)]
    return float(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum() / 6.0)


def from_glb(path):
    doc, blob = skin_fit_check.read_glb(path)
    nodes = doc["nodes"]
    world = {}

    def walk(n, base):
        p = base + np.asarray(nodes[n].get("translation", [0, 0, 0]), np.float64)
        assert "rotation" not in nodes[n] or np.allclose(nodes[n]["rotation"], [0, 0, 0, 1])
        world[n] = p
        for c in nodes[n].get("children", []):
            walk(c, p)

    for root in doc["scenes"][doc.get("scene", 0)]["nodes"]:
        walk(root, np.zeros(3))
    joints = [(nodes[n]["name"], world[n]) for n in doc["skins"][0]["joints"]]
    prim = doc["meshes"][0]["primitives"][0]
    positions = skin_fit_check.accessor(doc, blob, prim["attributes"]["POSITION"])
    a = doc["accessors"][prim["indices"]]
    view = doc["bufferViews"][a["bufferView"]]
    dtype = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32}[a["componentType"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    indices = np.frombuffer(blob, dtype, a["count"], start).reshape(-1, 3)
    return joints, signed_volume(positions, indices)


def from_model(path, betas):
    model = model_math.load_model_npz(path)
    v_shaped, joints = model_math.shape(model, betas)
    names = model_math.joint_names(len(model["parents"]))
    faces = np.load(path)["f"]
    return list(zip(names, joints)), signed_volume(v_shaped, faces)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--glb")
    ap.add_argument("--model")
    ap.add_argument("--betas", default="")
    ap.add_argument("out")
    args = ap.parse_args()
    if args.glb:
        joints, volume = from_glb(args.glb)
    else:
        betas = [float(b) for b in args.betas.split(",")] if args.betas else []
        joints, volume = from_model(args.model, betas)
    with open(args.out, "w") as f:
        f.write("volume %.17g\n" % volume)
        for name, p in joints:
            f.write("joint %s %.17g %.17g %.17g\n" % (name, p[0], p[1], p[2]))
    print("%d joints, volume %.9g m^3" % (len(joints), volume))


if __name__ == "__main__":
    main()
