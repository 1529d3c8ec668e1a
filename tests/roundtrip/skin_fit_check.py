#!/usr/bin/python3
"""Independent numpy check of fitted skin weights: read the skin
(JOINTS_n / WEIGHTS_n) from an exported GLB, pose the model with numpy
(model_math.forward, written from the contract) over held-out random poses
(numpy's own generator: never the exporter's training poses), and compare the
error against the model with all its weights with that of numpy's own
truncation to M influences.

    skin_fit_check.py MODEL.npz ASSET.glb --betas v,v,.. --expect optimized|truncated
        [--min-gain 0.3]

optimized: mean error <= (1 - min_gain) x truncated mean, max error <= truncated max.
truncated: the file's weights equal numpy's truncation (2e-6).
"""
import argparse
import json
import os
import struct
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import model_math  # noqa: E402

COMPONENTS = {5121: np.uint8, 5123: np.uint16, 5126: np.float32}


def read_glb(path):
    data = open(path, "rb").read()
    magic, _, _ = struct.unpack_from("<III", data, 0)
    assert magic == 0x46546C67, "not a GLB"
    length, kind = struct.unpack_from("<II", data, 12)
    doc = json.loads(data[20:20 + length])
    blen, bkind = struct.unpack_from("<II", data, 20 + length)
    return doc, data[28 + length:28 + length + blen]


def accessor(doc, blob, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    dtype = np.dtype(COMPONENTS[a["componentType"]])
    count, width = a["count"], {"VEC4": 4, "VEC3": 3, "SCALAR": 1}[a["type"]]
    stride = view.get("byteStride", dtype.itemsize * width)
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    rows = [np.frombuffer(blob, dtype, width, start + i * stride) for i in range(count)]
    return np.array(rows, dtype=np.float64)


def file_skin(path, num_joints):
    doc, blob = read_glb(path)
    prim = doc["meshes"][0]["primitives"][0]
    skin_joints = doc["skins"][0]["joints"]
    node_names = [doc["nodes"][n]["name"] for n in skin_joints]
    attrs = prim["attributes"]
    sets = sorted(int(k.split("_")[1]) for k in attrs if k.startswith("WEIGHTS_"))
    dense = None
    for s in sets:
        j = accessor(doc, blob, attrs["JOINTS_%d" % s]).astype(int)
        w = accessor(doc, blob, attrs["WEIGHTS_%d" % s])
        if dense is None:
            dense = np.zeros((len(w), num_joints))
        for c in range(4):
            np.add.at(dense, (np.arange(len(w)), j[:, c]), w[:, c])
    return dense, node_names, len(sets)


def errors(model, v_shaped, joints, poses, weights, full):
    dist = np.stack([np.linalg.norm(model_math.forward(model, v_shaped, joints, p, weights)[0] - f, axis=1)
                     for p, f in zip(poses, full)])
    return dist.mean(), dist.max()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("model")
    ap.add_argument("asset")
    ap.add_argument("--betas", default="")
    ap.add_argument("--expect", choices=("optimized", "truncated"), required=True)
    ap.add_argument("--min-gain", type=float, default=0.3)
    args = ap.parse_args()
    model = model_math.load_model_npz(args.model)
    k = len(model["parents"])
    betas = [float(b) for b in args.betas.split(",")] if args.betas else []
    v_shaped, joints = model_math.shape(model, betas)
    weights, names, sets = file_skin(args.asset, k)
    meta = json.load(open(args.asset + ".smpl.json"))
    m = meta["max_influences"]
    assert weights.shape[0] == v_shaped.shape[0], "the check needs an asset without UV seams"
    assert names == model_math.joint_names(k), "skin joints are not the model's joints in order"
    assert meta["skin_weights"] == args.expect, "metadata skin_weights %s" % meta["skin_weights"]
    assert int((weights > 0).sum(1).max()) <= m and np.abs(weights.sum(1) - 1).max() < 2e-6
    truncated = model_math.prune(model["weights"], m)
    if args.expect == "truncated":
        err = np.abs(weights - truncated).max()
        print("truncated weights vs numpy: %.3g" % err)
        return 0 if err <= 2e-6 else 1
    rng = np.random.default_rng(424242)
    poses = rng.uniform(-0.6, 0.6, size=(32, k, 3))
    full = [model_math.forward(model, v_shaped, joints, p, model["weights"])[0] for p in poses]
    f_mean, f_max = errors(model, v_shaped, joints, poses, weights, full)
    t_mean, t_max = errors(model, v_shaped, joints, poses, truncated, full)
    print("M=%d (%d sets) held-out mm: file mean %.4f max %.4f; numpy truncation mean %.4f max %.4f; gain %.0f%%"
          % (m, sets, 1e3 * f_mean, 1e3 * f_max, 1e3 * t_mean, 1e3 * t_max, 100 * (1 - f_mean / t_mean)))
    ok = f_mean <= (1 - args.min_gain) * t_mean and f_max <= t_max
    print("OK" if ok else "FAIL: the fitted weights do not beat truncation by %.0f%% (mean) / on the max" %
          (100 * args.min_gain))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
