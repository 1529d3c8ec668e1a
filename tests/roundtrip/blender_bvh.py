"""Headless-Blender check of BVH output: import a `smpl-export --motion ... --out x.bvh`
file with Blender's own BVH importer (io_anim_bvh, bpy.ops.import_anim.bvh) and
compare the armature with numpy's forward pass of the motion file (model_math;
the motion read as blender_animation.py reads it, independent of the C++ code).

  blender -b --factory-startup --python-exit-code 1 --python blender_bvh.py -- \
      --bvh walk.bvh --model model.npz --motion walk.npz [--units m|cm] [--fps 30] [--tol 1e-5]

Import options, chosen so the comparison needs no conversion of ours:
  axis_forward='Y', axis_up='Z'  the importer's axis conversion is then the identity, so
                                 Blender's world axes are the file's (Y up, as the model);
                                 the default (-Z, Y) would turn the armature Z-up
  global_scale 1 (m) or 0.01 (cm) the file's units back to metres
  frame_start=1, use_fps_scale=False  BVH frame i at Blender frame 1 + i
  update_scene_fps=True, update_scene_duration=True  the scene takes the file's rate and length
  rotate_mode='NATIVE'            pose bones keep the file's Euler order (ZXY)

Checked: the bones are the model's joints by their authors' names with the
model's parents; each bone's rest head is J(beta) (betas: the motion's first
min(16, B), as smpl-export uses them); the scene rate is the export rate and
the action holds every frame; at the first, middle and last frame every
joint's world position is the model's posed joint (J(beta) posed by the
motion, plus trans, AMASS Z-up turned Y-up) within --tol metres.
Prints "bvh <label> frame <i> max_joint_err_m <e>" per checked frame.
"""
import argparse
import json
import os
import sys

import bpy
import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402  (numpy patch, checks, exit status)
import blender_animation as anim  # noqa: E402  (the motion read with numpy, Reference)
import model_math  # noqa: E402


def parse_args():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bvh", required=True)
    ap.add_argument("--model", required=True, help="model .npz (read with numpy)")
    ap.add_argument("--motion", required=True, help="motion .npz (read with numpy)")
    ap.add_argument("--units", choices=("m", "cm"), default="m", help="the --bvh-units given")
    ap.add_argument("--fps", type=float, default=0.0, help="the --fps given to smpl-export")
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--label", default="")
    ap.add_argument("--placed", action="store_true",
                    help="--origin floor / --root-bone export: read the offset and the root bone from "
                         "the sidecar (BVH.smpl.json); expected joints move by the offset, 'root' is "
                         "the pelvis' ground projection")
    ap.add_argument("--rest-pose", choices=("t", "a"), default="t",
                    help="the --rest-pose given: with a, the rest heads are numpy's A pose (the "
                         "shoulders turned 45 degrees down about z), the sidecar says so, and the "
                         "posed joints must still be the model's")
    return ap.parse_args(harness.script_args())


def patch_open_mode():
    """Blender 3.4's importer opens the file with mode 'rU', which Python 3.11 (Debian 12's
    Blender runs on the system Python) refuses ("invalid mode: 'rU'"); Blender's own builds
    bundle Python 3.10, where 'U' is ignored. Drop the 'U' for that module only."""
    import builtins
    import io_anim_bvh.import_bvh as importer
    importer.open = lambda file, mode="r", *a, **k: builtins.open(file, mode.replace("U", ""), *a, **k)


def import_bvh(path, units):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    patch_open_mode()
    bpy.ops.import_anim.bvh(filepath=path, target="ARMATURE", axis_forward="Y", axis_up="Z",
                            global_scale=1.0 if units == "m" else 0.01, frame_start=1,
                            use_fps_scale=False, update_scene_fps=True, update_scene_duration=True,
                            rotate_mode="NATIVE")
    arms = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    if len(arms) != 1:
        raise SystemExit("%s: expected 1 armature, found %d" % (path, len(arms)))
    return arms[0]


def world_heads(arm, names, rest=False):
    """(K,3) bone heads in world space (metres): rest (armature space) or posed."""
    m = np.array(arm.matrix_world, dtype=np.float64)
    if rest:
        heads = [arm.data.bones[n].head_local for n in names]
    else:
        heads = [arm.pose.bones[n].head for n in names]
    return np.array(heads, dtype=np.float64) @ m[:3, :3].T + m[:3, 3]


def placement(args):
    """(dy, root): the sidecar's origin offset (metres, y of the Y-up file) and the added root
    bone's name (None without --root-bone); (0, None) unless --placed."""
    if not args.placed:
        return 0.0, None
    with open(args.bvh + ".smpl.json") as f:
        meta = json.load(f)
    harness.check(meta.get("origin", {}).get("mode") == "floor", "sidecar origin %r" % meta.get("origin"))
    dy = float(meta["origin"]["offset"][1])
    root = meta.get("root_bone", {}).get("name")
    return dy, root


def with_root(joints, root):
    """(K,3) model joints, with the root bone's head first when there is one: the pelvis' (joint
    0) ground projection (x, 0, z) in the Y-up file (docs/file-contract.md)."""
    if root is None:
        return joints
    return np.vstack([[joints[0, 0], 0.0, joints[0, 2]], joints])


def a_pose_joints(ref):
    """(K,3) the rest joints at the A pose of --rest-pose a, by numpy's forward pass: the
    model's joints with left_shoulder turned -45 degrees and right_shoulder +45 degrees about
    z (the arms down; +x is the body's left), docs/retargeting.md "A-pose rest"."""
    names = list(ref.names)
    pose = np.zeros((len(names), 3))
    pose[names.index("left_shoulder")] = [0.0, 0.0, -np.pi / 4]
    pose[names.index("right_shoulder")] = [0.0, 0.0, np.pi / 4]
    _, joints, _ = model_math.forward(ref.model, ref.v_shaped, ref.joints, pose, ref.weights)
    return joints


def check_skeleton(arm, ref, tol, dy=0.0, root=None, rest_pose="t"):
    names, parents = list(ref.names), list(ref.model["parents"])
    if root is not None:  # the added bone: parent of the model's root joint
        names = [root] + names
        parents = [-1] + [p + 1 if p >= 0 else 0 for p in parents]
    bones = arm.data.bones
    harness.check(sorted(b.name for b in bones) == sorted(names),
                  "bones %s, expected %s" % ([b.name for b in bones], names))
    for k, name in enumerate(names):
        bone = bones.get(name)
        if bone is None:
            continue
        want = names[parents[k]] if parents[k] >= 0 else None
        got = bone.parent.name if bone.parent else None
        harness.check(got == want, "bone %s: parent %s, expected %s" % (name, got, want))
    if all(bones.get(n) for n in names):
        rest = a_pose_joints(ref) if rest_pose == "a" else ref.joints
        want = with_root(rest + np.array([0.0, dy, 0.0]), root)
        heads = world_heads(arm, names, rest=True)
        err = np.abs(heads - want).max()
        what = "the A pose of J(beta)" if rest_pose == "a" else "J(beta)"
        print("bvh rest joints vs %s: %.3e m" % (what, err))
        harness.check(err <= tol, "rest heads off %s by %.3g m" % (what, err))
        if rest_pose == "a":  # the A rest is not the T rest: the check above can tell
            t_err = np.abs(heads - with_root(ref.joints + np.array([0.0, dy, 0.0]), root)).max()
            print("bvh rest joints vs J(beta) (the T rest): %.3e m (must exceed 1e-2)" % t_err)
            harness.check(t_err > 1e-2, "the A rest heads equal the T rest's (%.3g m)" % t_err)


def check_timing(arm, fps_out, count):
    scene = bpy.context.scene
    rate = scene.render.fps / scene.render.fps_base
    harness.check(abs(rate - fps_out) < 1e-3, "scene rate %.6f fps, expected %g" % (rate, fps_out))
    keys = {len(fc.keyframe_points) for fc in arm.animation_data.action.fcurves}
    harness.check(keys == {count}, "keys per curve %s, expected %d" % (sorted(keys), count))
    harness.check(scene.frame_end >= count, "scene ends at %d, before %d frames" % (scene.frame_end, count))


def main():
    args = parse_args()
    model = model_math.load_model_npz(args.model)
    motion = anim.read_motion(args.motion, args.model)
    fps_out = args.fps or motion["fps"]
    arm = import_bvh(args.bvh, args.units)
    ref = anim.Reference(model, motion, model["weights"])
    label = args.label or os.path.splitext(os.path.basename(args.bvh))[0]
    dy, root = placement(args)
    if args.placed:
        print("bvh %s origin offset %+.6f m, root bone %s" % (label, dy, root))
    if args.rest_pose == "a":
        with open(args.bvh + ".smpl.json") as f:
            harness.check(json.load(f).get("rest_pose") == "a", "the sidecar lacks rest_pose a")
    check_skeleton(arm, ref, args.tol, dy, root, args.rest_pose)
    names = ([root] if root else []) + list(ref.names)
    ratio = motion["fps"] / fps_out  # source frames per output frame
    count = int(np.floor((motion["frames"] - 1) / ratio + 1e-9)) + 1
    check_timing(arm, fps_out, count)
    worst = 0.0
    for i in sorted({0, count // 2, count - 1}):
        bpy.context.scene.frame_set(1 + i)
        got = world_heads(arm, names)
        want = with_root(ref.at(i * ratio)[1] + np.array([0.0, dy, 0.0]), root)
        err = np.abs(got - want).max()
        worst = max(worst, err)
        print("bvh %s frame %d max_joint_err_m %.3e" % (label, i, err))
        harness.check(err <= args.tol, "frame %d: joints off by %.3g m > %g" % (i, err, args.tol))
    print("bvh %s units %s frames %d fps %g max_joint_err_m %.3e" % (label, args.units, count, fps_out, worst))
    harness.finish()


if __name__ == "__main__":
    harness.run(main)
