"""Headless-Blender check of --skeleton-names mixamo|ue5: Blender's own importers
(FBX, glTF, BVH) read the renamed file, its armature's bones carry the rig's names
and the body moves exactly as the same export with the model's names.

  blender -b --factory-startup --python-exit-code 1 --python blender_skeleton_names.py -- \
      --plain walk.fbx --renamed walk_mixamo.fbx --names mixamo [--tol 1e-5] [--label L]

Checked:
- the renamed armature's bones are exactly the table below applied to the model's
  joints (joint_names of the plain file's sidecar); joints a rig has no bone for
  keep their names; the renamed sidecar records skeleton_names and, per joint,
  the same bone_names;
- FBX and glTF: at the first, middle and last frame of the action, every
  evaluated mesh vertex (world space, armature and shape keys applied) of the
  renamed import equals the plain import's within --tol metres, and the frames
  are posed (some vertex away from the first frame by more than 1 cm);
- BVH (no mesh): the same for every bone's world head, bone by bone through the
  table.
Prints "skeleton_names <label> frame <f> max_err_m <e>" per checked frame.

The table is spelled out here from the rigs' public bone names
(docs/retargeting.md lists the sources), independently of exporter/skeleton_names.cpp.
"""
import argparse
import json
import os
import sys

import bpy
import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402

# model joint -> (Mixamo bone, UE5 Mannequin bone); absent: the rig has no such bone
BODY = {
    "pelvis": ("Hips", "pelvis"), "spine1": ("Spine", "spine_01"), "spine2": ("Spine1", "spine_03"),
    "spine3": ("Spine2", "spine_05"), "neck": ("Neck", "neck_01"), "head": ("Head", "head"),
}
SIDED = {  # per side: Mixamo bone without "Left"/"Right", UE5 bone without "_l"/"_r"
    "hip": ("UpLeg", "thigh"), "knee": ("Leg", "calf"), "ankle": ("Foot", "foot"),
    "foot": ("ToeBase", "ball"), "collar": ("Shoulder", "clavicle"), "shoulder": ("Arm", "upperarm"),
    "elbow": ("ForeArm", "lowerarm"), "wrist": ("Hand", "hand"),
}
FINGERS = ("thumb", "index", "middle", "ring", "pinky")


def expected_bone(joint, names):
    column = 0 if names == "mixamo" else 1
    if joint in BODY:
        bone = BODY[joint][column]
        return "mixamorig:" + bone if column == 0 else bone
    for side, mixamo_side, ue_side in (("left_", "Left", "_l"), ("right_", "Right", "_r")):
        if not joint.startswith(side):
            continue
        part = joint[len(side):]
        if part in SIDED:
            return ("mixamorig:" + mixamo_side + SIDED[part][0]) if column == 0 else SIDED[part][1] + ue_side
        if part[:-1] in FINGERS and part[-1] in "123":
            finger, i = part[:-1], part[-1]
            if column == 0:
                return "mixamorig:%sHand%s%s" % (mixamo_side, finger.capitalize(), i)
            return "%s_0%s%s" % (finger, i, ue_side)
    return joint  # SMPL's left_hand/right_hand, jaw, eyes, --root-bone's root


def parse_args():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plain", required=True, help="the export without --skeleton-names")
    ap.add_argument("--renamed", required=True, help="the same export with --skeleton-names NAMES")
    ap.add_argument("--names", required=True, choices=("mixamo", "ue5"))
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--label", default="")
    return ap.parse_args(harness.script_args())


def patch_bvh_open_mode():
    """Blender 3.4's BVH importer opens with mode 'rU', refused by Debian's Python 3.11
    (see blender_bvh.py): drop the 'U' for that module only."""
    import builtins
    import io_anim_bvh.import_bvh as importer
    importer.open = lambda file, mode="r", *a, **k: builtins.open(file, mode.replace("U", ""), *a, **k)


def import_file(path):
    """(armature, mesh or None) of `path` imported into an empty scene."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    ext = os.path.splitext(path)[1].lower()
    if ext == ".bvh":
        patch_bvh_open_mode()
        bpy.ops.import_anim.bvh(filepath=path, target="ARMATURE", axis_forward="Y", axis_up="Z",
                                frame_start=1, use_fps_scale=False, update_scene_fps=True,
                                update_scene_duration=True, rotate_mode="NATIVE")
    elif ext in (".glb", ".gltf"):
        bpy.ops.import_scene.gltf(filepath=path)
    else:
        bpy.ops.import_scene.fbx(filepath=path)
    arms = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    if len(arms) != 1 or len(meshes) > 1:
        raise SystemExit("%s: expected 1 armature and at most 1 mesh, found %d and %d" % (path, len(arms), len(meshes)))
    return arms[0], (meshes[0] if meshes else None)


def frames_of(arm):
    ad = arm.animation_data
    if ad is None or ad.action is None:
        raise SystemExit("%s: the armature has no action" % arm.name)
    first, last = (int(round(f)) for f in ad.action.frame_range)
    return [first, (first + last) // 2, last]


def sample(path, bone_order=None):
    """bone names, frames and per frame: (V,3) evaluated vertices or, without a
    mesh, (K,3) world heads of `bone_order` (names) or of every bone."""
    arm, mesh = import_file(path)
    names = [b.name for b in arm.data.bones]
    frames = frames_of(arm)
    out = []
    scene = bpy.context.scene
    for f in frames:
        scene.frame_set(f)
        bpy.context.view_layer.update()
        if mesh is not None:
            ev = mesh.evaluated_get(bpy.context.evaluated_depsgraph_get())
            m = ev.to_mesh()
            co = np.array([(mesh.matrix_world @ v.co)[:] for v in m.vertices])
            ev.to_mesh_clear()
            out.append(co)
        else:
            order = bone_order or names
            out.append(np.array([(arm.matrix_world @ arm.pose.bones[n].head)[:] for n in order]))
    return names, frames, out


def read_sidecar(path):
    with open(path + ".smpl.json", encoding="utf-8") as f:
        return json.load(f)


def main():
    args = parse_args()
    label = args.label or os.path.basename(args.renamed)
    plain_meta, renamed_meta = read_sidecar(args.plain), read_sidecar(args.renamed)
    joints = plain_meta["joint_names"]
    want = [expected_bone(j, args.names) for j in joints]
    harness.check("skeleton_names" not in plain_meta and "bone_names" not in plain_meta,
                  "%s: the plain sidecar names a skeleton" % args.plain)
    harness.check(renamed_meta.get("skeleton_names") == args.names,
                  "%s: sidecar skeleton_names %r, expected %r" % (args.renamed, renamed_meta.get("skeleton_names"), args.names))
    harness.check(renamed_meta.get("joint_names") == joints, "%s: sidecar joint_names differ from the plain export's" % args.renamed)
    harness.check(renamed_meta.get("bone_names") == want,
                  "%s: sidecar bone_names differ from the table: %s" % (
                      args.renamed, [(j, b, w) for j, b, w in zip(joints, renamed_meta.get("bone_names") or [], want) if b != w][:5]))
    renamed_changed = sum(1 for j, w in zip(joints, want) if j != w)
    harness.check(renamed_changed >= 20, "%s: only %d joints renamed" % (args.renamed, renamed_changed))

    bvh = args.renamed.lower().endswith(".bvh")
    plain_names, plain_frames, plain = sample(args.plain, joints if bvh else None)
    got_names, got_frames, got = sample(args.renamed, want if bvh else None)
    extra = set(plain_names) - set(joints)  # e.g. --root-bone's root: not a model joint
    harness.check(set(got_names) == set(want) | extra,
                  "%s: armature bones differ from the table: missing %s, unexpected %s" % (
                      args.renamed, sorted(set(want) - set(got_names))[:5], sorted(set(got_names) - set(want) - extra)[:5]))
    harness.check(set(plain_names) == set(joints) | extra, "%s: the plain armature's bones are not the model's joints" % args.plain)
    harness.check(got_frames == plain_frames, "%s: frames %s, plain %s" % (args.renamed, got_frames, plain_frames))
    moved = max(np.abs(p - plain[0]).max() for p in plain[1:])
    harness.check(moved > 0.01, "%s: the checked frames are not posed (max move %.3g m)" % (args.plain, moved))
    for f, a, b in zip(plain_frames, plain, got):
        if a.shape != b.shape:
            harness.check(False, "%s: frame %d: %s values, plain %s" % (args.renamed, f, b.shape, a.shape))
            continue
        err = float(np.abs(a - b).max())
        print("skeleton_names %s frame %d max_err_m %.3g (%s %d points)" % (label, f, err, "joints" if bvh else "vertices", len(a)))
        harness.check(err <= args.tol, "%s: frame %d differs from the plain export by %.3g m > %g" % (label, f, err, args.tol))


if __name__ == "__main__":
    harness.run(main)
