#!/usr/bin/env python3
"""A tiny SMPL-layout model and a GLB written by hand with numpy, following the
exporter contract (docs/file-contract.md). It lets the Blender add-on be
tested without smpl-export: if the add-on and this independent writer agree
with numpy's forward pass, the add-on's math is right whatever the exporter
does.

    synthetic_asset.py OUTDIR --joints 24|55 [--max-influences M] [--seed S]

writes OUTDIR/synthetic_<K>_m<M>.npz (model arrays as the public files store
them) and OUTDIR/synthetic_<K>_m<M>.glb (+ .smpl.json sidecar); the model
depends on K and the seed only. With --model FILE.npz, writes the GLB of that
model instead: OUTDIR/<stem>_numpy_m<M>.glb.
"""
import argparse
import json
import os
import struct
import sys

import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from model_math import joint_names  # noqa: E402

SMPL_PARENTS = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21]


def skeleton(num_joints):
    """Canonical names and parents for SMPL (24) or SMPL-X (55)."""
    if num_joints not in (24, 55):
        raise ValueError("synthetic_asset: --joints must be 24 or 55")
    if num_joints == 24:
        return joint_names(24), list(SMPL_PARENTS)
    parents = SMPL_PARENTS[:22] + [15, 15, 15]  # jaw, eyes under the head
    for wrist in (20, 21):                    # 5 fingers x 3 joints per hand
        for _ in range(5):
            parents += [wrist, len(parents), len(parents) + 1]
    return joint_names(55), parents


def make_model(num_joints, rng, verts_per_joint=12, betas=10):
    names, parents = skeleton(num_joints)
    k = num_joints
    joints = np.zeros((k, 3))
    for j in range(1, k):
        joints[j] = joints[parents[j]] + rng.normal(0, 0.12, 3)
    owner = np.repeat(np.arange(k), verts_per_joint)
    n = owner.size
    v_template = joints[owner] + rng.normal(0, 0.04, (n, 3))
    regressor = np.zeros((k, n))
    for j in range(k):
        mine = np.flatnonzero(owner == j)[:5]
        regressor[j, mine] = 1.0 / mine.size
    weights = np.zeros((n, k))
    for i in range(n):
        # Six influences: the owner and nearby joints up the chain, unequal weights.
        chain, j = [], owner[i]
        while j >= 0 and len(chain) < 6:
            chain.append(j)
            j = parents[j]
        extra = rng.choice(k, 6 - len(chain), replace=False) if len(chain) < 6 else []
        for j in list(chain) + list(extra):
            weights[i, j] += rng.uniform(0.05, 1.0)
    weights /= weights.sum(1, keepdims=True)
    faces = np.array([[i, i + 1, i + 2] for i in range(0, n - 2, 3)], dtype=np.int64)
    return dict(
        v_template=v_template, shapedirs=rng.normal(0, 0.01, (n, 3, betas)),
        posedirs=rng.normal(0, 0.02, (n, 3, 9 * (k - 1))), J_regressor=regressor,
        weights=weights, f=faces,
        kintree_table=np.array([[2**32 - 1 if p < 0 else p for p in parents], list(range(k))],
                               dtype=np.int64)), names, parents


def prune(weights, m):
    """Top-m per row (ties toward the lower joint index), renormalised."""
    order = np.argsort(-weights, axis=1, kind="stable")[:, :m]
    w = np.take_along_axis(weights, order, 1)
    return order, w / w.sum(1, keepdims=True)


class Buffer:
    def __init__(self):
        self.data, self.views, self.accessors = bytearray(), [], []

    def add(self, array, component, kind, target=None, minmax=False):
        while len(self.data) % 4:
            self.data.append(0)
        raw = np.ascontiguousarray(array).tobytes()
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw)}
        if target:
            view["target"] = target
        self.views.append(view)
        self.data += raw
        acc = {"bufferView": len(self.views) - 1, "componentType": component,
               "count": int(array.shape[0]), "type": kind}
        if minmax:
            acc["min"] = [float(x) for x in array.min(0)]
            acc["max"] = [float(x) for x in array.max(0)]
        self.accessors.append(acc)
        return len(self.accessors) - 1


def gltf_document(model, names, parents, betas, m):
    v_shaped = model["v_template"] + model["shapedirs"][:, :, :betas.size] @ betas
    joints = model["J_regressor"] @ v_shaped
    k = len(names)
    buf = Buffer()
    pos = buf.add(v_shaped.astype(np.float32), 5126, "VEC3", 34962, True)
    idx = buf.add(model["f"].astype(np.uint32).reshape(-1), 5125, "SCALAR", 34963)
    order, w = prune(model["weights"], m)
    sets = (m + 3) // 4
    order = np.pad(order, ((0, 0), (0, 4 * sets - m)))
    w = np.pad(w, ((0, 0), (0, 4 * sets - m)))
    attributes = {"POSITION": pos}
    for s in range(sets):
        attributes["JOINTS_%d" % s] = buf.add(order[:, 4 * s:4 * s + 4].astype(np.uint16), 5123, "VEC4", 34962)
        attributes["WEIGHTS_%d" % s] = buf.add(w[:, 4 * s:4 * s + 4].astype(np.float32), 5126, "VEC4", 34962)
    posedirs = model["posedirs"]
    targets, target_names, correctives = [], [], []
    for n in range(posedirs.shape[2]):
        j, rc = n // 9 + 1, n % 9
        name = "pose_%s_%d%d" % (names[j], rc // 3, rc % 3)
        targets.append({"POSITION": buf.add(posedirs[:, :, n].astype(np.float32), 5126, "VEC3", None, True)})
        target_names.append(name)
        correctives.append({"feature": n, "target": name, "scale": 1, "offset": 0})
    ibm = np.tile(np.eye(4), (k, 1, 1))
    ibm[:, 3, :3] = -joints  # column-major storage: translation in the last column
    ibm_acc = buf.add(ibm.astype(np.float32).reshape(k, 16), 5126, "MAT4")
    nodes = []
    for j in range(k):
        local = joints[j] - (joints[parents[j]] if parents[j] >= 0 else 0)
        node = {"name": names[j], "translation": [float(x) for x in local]}
        kids = [c for c in range(k) if parents[c] == j]
        if kids:
            node["children"] = kids
        nodes.append(node)
    nodes.append({"name": "body", "mesh": 0, "skin": 0})
    meta = {"model_kind": "smpl" if k == 24 else "smplx", "model_name": "synthetic",
            "exporter_version": "synthetic", "joint_names": names, "parents": parents,
            "betas": [float(b) for b in betas], "expression": [], "max_influences": m,
            "units": "meters", "up_axis": "+Y", "correctives": correctives}
    doc = {
        "asset": {"version": "2.0", "generator": "synthetic_asset.py", "extras": {"smpl": meta}},
        "scene": 0, "scenes": [{"nodes": [0, k]}], "nodes": nodes,
        "meshes": [{"name": "body", "primitives": [{"attributes": attributes, "indices": idx,
                                                     "targets": targets}],
                    "weights": [0.0] * len(targets), "extras": {"targetNames": target_names}}],
        "skins": [{"joints": list(range(k)), "skeleton": 0, "inverseBindMatrices": ibm_acc}],
        "buffers": [{"byteLength": len(buf.data)}], "bufferViews": buf.views,
        "accessors": buf.accessors}
    return doc, bytes(buf.data), meta


def write_glb(path, doc, blob):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    blob += b"\0" * (-len(blob) % 4)
    total = 12 + 8 + len(text) + 8 + len(blob)
    with open(path, "wb") as out:
        out.write(struct.pack("<III", 0x46546C67, 2, total))
        out.write(struct.pack("<II", len(text), 0x4E4F534A) + text)
        out.write(struct.pack("<II", len(blob), 0x004E4942) + blob)


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("outdir")
    ap.add_argument("--joints", type=int, default=24)
    ap.add_argument("--max-influences", type=int, default=4)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--model", help="write the GLB of this model .npz instead of a random one")
    args = ap.parse_args(argv)
    os.makedirs(args.outdir, exist_ok=True)
    rng = np.random.default_rng(args.seed + args.joints)
    if args.model:
        model = dict(np.load(args.model))
        parents = [-1] + [int(p) for p in model["kintree_table"][0, 1:]]
        names = joint_names(len(parents))
        stem = os.path.join(args.outdir, "%s_numpy_m%d" % (
            os.path.splitext(os.path.basename(args.model))[0], args.max_influences))
    else:
        model, names, parents = make_model(args.joints, rng)
        stem = os.path.join(args.outdir, "synthetic_%d_m%d" % (args.joints, args.max_influences))
        np.savez(stem + ".npz", **model)
    betas = rng.normal(0, 1, 4)
    doc, blob, meta = gltf_document(model, names, parents, betas, args.max_influences)
    glb = stem + ".glb"
    write_glb(glb, doc, blob)
    with open(glb + ".smpl.json", "w") as out:
        json.dump(meta, out)
    print(glb)


if __name__ == "__main__":
    main(sys.argv[1:])
