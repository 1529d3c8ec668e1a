#!/usr/bin/python3
"""numpy check of a static `--origin floor` / `--root-bone` GLB (exporter/placement.h)
against the model's own math (model_math.shape, written from the contract):

  - the stored rest mesh is v_shaped + (0, dy, 0), dy = -min_v v_shaped_y (1e-6 m): the
    lowest rest vertex at y = 0 and the shape otherwise unchanged;
  - the sidecar's "origin" says floor with that offset, its joint_names/parents are the
    model's (no root);
  - the joint nodes: without a root bone the pelvis node at J_0 + (0, dy, 0); with one
    (--root-bone) node `root` at (J_0x, 0, J_0z), parent of `pelvis` at (0, J_0y + dy, 0),
    the skin's first joint, with no skin weight.

    origin_check.py MODEL.npz ASSET.glb [--betas v,v,..] [--root-bone]
Exit status 0 only if every check passes; prints the measured numbers.
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import model_math  # noqa: E402
from skin_fit_check import accessor, read_glb  # noqa: E402

FAILED = []


def check(ok, message):
    if not ok:
        FAILED.append(message)
        print("FAIL: " + message)


def node_named(doc, name):
    hits = [i for i, n in enumerate(doc["nodes"]) if n.get("name") == name]
    check(len(hits) == 1, "expected one node '%s', found %d" % (name, len(hits)))
    return hits[0] if hits else 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("model")
    ap.add_argument("asset")
    ap.add_argument("--betas", default="")
    ap.add_argument("--root-bone", action="store_true")
    args = ap.parse_args()
    model = model_math.load_model_npz(args.model)
    betas = [float(b) for b in args.betas.split(",")] if args.betas else []
    v_shaped, joints = model_math.shape(model, betas)
    names = model_math.joint_names(len(model["parents"]))
    doc, blob = read_glb(args.asset)
    with open(args.asset + ".smpl.json", encoding="utf-8") as fh:
        meta = json.load(fh)
    prim = doc["meshes"][0]["primitives"][0]
    pos = accessor(doc, blob, prim["attributes"]["POSITION"])
    check(pos.shape == v_shaped.shape, "positions %s, model %s" % (pos.shape, v_shaped.shape))
    dy = -v_shaped[:, 1].min()
    got_dy = meta.get("origin", {}).get("offset", [0, 0, 0])[1]
    print("floor offset: numpy %.9f m, metadata %.9f m" % (dy, got_dy))
    check(meta.get("origin", {}).get("mode") == "floor", "metadata origin %s" % meta.get("origin"))
    check(abs(got_dy - dy) <= 1e-6, "metadata offset %.9f, expected %.9f" % (got_dy, dy))
    shape_err = np.abs(pos - (v_shaped + [0, dy, 0])).max()
    print("lowest rest vertex y: %.3e m; rest mesh vs v_shaped + offset: %.3e m" % (pos[:, 1].min(), shape_err))
    check(abs(pos[:, 1].min()) <= 1e-6, "lowest rest vertex at y = %.3g m" % pos[:, 1].min())
    check(shape_err <= 1e-6, "rest mesh differs from v_shaped + offset by %.3g m" % shape_err)
    check(meta["joint_names"] == names, "metadata joint_names are not the model's joints")
    check(meta["parents"] == [int(p) for p in model["parents"]], "metadata parents are not the model's")
    pelvis = doc["nodes"][node_named(doc, "pelvis")]
    j0 = joints[0] + [0, dy, 0]
    if not args.root_bone:
        err = np.abs(np.array(pelvis["translation"]) - j0).max()
        check(err <= 1e-6 and "root_bone" not in meta, "pelvis node off by %.3g m (or a root bone)" % err)
        return
    r = node_named(doc, "root")
    root = doc["nodes"][r]
    want_root, want_pelvis = np.array([j0[0], 0, j0[2]]), np.array([0, j0[1], 0])
    err = max(np.abs(np.array(root["translation"]) - want_root).max(),
              np.abs(np.array(pelvis["translation"]) - want_pelvis).max())
    print("root / pelvis node translations vs (J0x, 0, J0z) / (0, J0y + dy, 0): %.3e m" % err)
    check(err <= 1e-6, "root/pelvis translations off by %.3g m" % err)
    check(root.get("children") == [node_named(doc, "pelvis")], "root's children %s" % root.get("children"))
    check("rotation" not in root, "root has a rest rotation")
    skin = doc["skins"][0]
    check(skin["joints"][0] == r, "the skin's first joint is not root")
    check(r in doc["scenes"][0]["nodes"], "root is not a scene root")
    j = accessor(doc, blob, prim["attributes"]["JOINTS_0"]).astype(int)
    w = accessor(doc, blob, prim["attributes"]["WEIGHTS_0"])
    check(not ((j == 0) & (w > 0)).any(), "root carries skin weight")
    check(meta.get("root_bone", {}).get("name") == "root", "metadata root_bone %s" % meta.get("root_bone"))


if __name__ == "__main__":
    main()
    print("FAILED" if FAILED else "ok")
    sys.exit(1 if FAILED else 0)
