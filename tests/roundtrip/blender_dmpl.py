"""Headless-Blender check of baked DMPL soft tissue: import a GLB/FBX
written by `smpl-export --motion M --dmpl B [--dmpl-joints fixed|regressed]`,
play it with NO runtime script, and compare the evaluated mesh at the first,
middle and last frame with an independent numpy implementation of the
published math (AMASS / human_body_prior BodyModel.forward: the DMPL
displacement eigvec @ dmpls is added to the shaped template together with the
betas, the joints are regressed from that displaced template, then pose
correctives and LBS as in model_math.forward).

  blender -b --factory-startup --python-exit-code 1 --python blender_dmpl.py -- \
      --asset a.glb --model smplh.npz --motion m.npz --dmpl basis.npz --joints fixed|regressed [--tol 1e-4]

Joint choice: with --joints regressed the file must match the published math;
with --joints fixed the exporter keeps the betas-only joints, so the file must
match numpy with those joints (same displaced template), and the distance
between the two numpy results (the fixed-joint cost) is printed and must be
non-zero for the fixture (so the test can tell the two choices apart).
Prints one line per frame: "dmpl <fmt> <joints> frame <i> err_m <e> published_err_m <p>".
"""
import argparse
import json
import os
import sys

import numpy as np

np.bool = bool  # Debian numpy vs Blender 3.4's glTF importer
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_animation as ba  # noqa: E402
import blender_roundtrip as rt  # noqa: E402
import model_math  # noqa: E402


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--asset", required=True)
    ap.add_argument("--model", required=True)
    ap.add_argument("--motion", required=True)
    ap.add_argument("--dmpl", required=True, help="DMPL basis .npz (eigvec (N,3,D))")
    ap.add_argument("--joints", choices=("fixed", "regressed"), required=True)
    ap.add_argument("--tol", type=float, default=1e-4)
    return ap.parse_args(argv)


def published(model, motion, eigvec, dmpls, weights, frame, regressed):
    """Vertices (N,3) in exported (Y-up) axes at source frame `frame`."""
    names = model_math.joint_names(len(model["parents"]))
    betas = motion["betas"][:min(16, model["shapedirs"].shape[2])]
    v_shaped, joints = model_math.shape(model, betas)
    v_dyn = v_shaped + eigvec @ dmpls[frame]
    j = model["J_regressor"] @ v_dyn if regressed else joints
    pose, trans = ba.pose_at(motion, names, frame)
    verts = model_math.forward(model, v_dyn, j, pose, weights)[0]
    up = ba.Z_UP_TO_Y_UP if motion["amass"] else np.eye(3)
    return (verts + trans) @ up.T, v_shaped


def main():
    args = parse_args()
    model = model_math.load_model_npz(args.model)
    motion = ba.read_motion(args.motion)
    dmpls = np.load(args.motion)["dmpls"]
    eigvec = np.load(args.dmpl)["eigvec"]
    with open(args.asset + ".smpl.json", encoding="utf-8") as fh:
        meta = json.load(fh)
    dm = meta["dmpl"]
    rt.check(dm["joints"] == args.joints, "metadata dmpl.joints is %s, expected %s" % (dm["joints"], args.joints))
    count = len(dm["targets"])
    eigvec, dmpls = eigvec[:, :, :count], dmpls[:, :count]
    fmt, arm, mesh_obj = ba.import_asset(args.asset, motion["fps"])
    weights = model_math.prune(model["weights"], int(meta["max_influences"]))
    rest_w = {c["target"]: c["offset"] for c in meta.get("correctives", [])}
    rest_w.update({t["target"]: t["offset"] for t in dm["targets"]})
    _, v_shaped = published(model, motion, eigvec, dmpls, weights, 0, False)
    index, _ = rt.vertex_map(mesh_obj, v_shaped, rt.rest_positions(mesh_obj, rest_w))
    offset = 1 if fmt == "fbx" else 0  # Blender's FBX importer starts at frame 1
    regressed = args.joints == "regressed"
    worst = cost = 0.0
    for frame in sorted({0, motion["frames"] // 2, motion["frames"] - 1}):
        ba.evaluate(__import__("bpy").context.scene, frame + offset)
        got = rt.evaluated_vertices(mesh_obj)
        want, _ = published(model, motion, eigvec, dmpls, weights, frame, regressed)
        pub, _ = published(model, motion, eigvec, dmpls, weights, frame, True)
        fixed, _ = published(model, motion, eigvec, dmpls, weights, frame, False)
        err = np.linalg.norm(got - want[index], axis=1).max()
        err_pub = np.linalg.norm(got - pub[index], axis=1).max()
        cost = max(cost, np.linalg.norm(pub - fixed, axis=1).max())
        worst = max(worst, err)
        print("dmpl %s %s frame %d err_m %.3e published_err_m %.3e" % (fmt, args.joints, frame, err, err_pub))
        rt.check(err <= args.tol, "%s %s frame %d: max vertex error %.3g m > %g" % (fmt, args.joints, frame, err, args.tol))
    print("dmpl %s %s max_err_m %.3e fixed_joint_cost_m %.3e (at the checked frames)" % (fmt, args.joints, worst, cost))
    rt.check(cost > 10 * args.tol, "fixture too weak: fixed and regressed joints differ by only %.3g m" % cost)
    if rt.failures:
        print("%d check(s) failed" % len(rt.failures))
        sys.stdout.flush()
        os._exit(1)
    print("OK")
    sys.stdout.flush()
    os._exit(0)


if __name__ == "__main__":
    try:
        main()
    except SystemExit as e:
        print(e)
        sys.stdout.flush()
        os._exit(1)
    except Exception:  # any error must fail the CTest run
        import traceback
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)
