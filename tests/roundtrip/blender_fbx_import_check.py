# Imports an FBX written by smpl-export into an empty headless Blender scene
# and checks it against expectations given in model axes and metres:
#
#   blender -b --factory-startup --python-exit-code 1 \
#       --python tests/roundtrip/blender_fbx_import_check.py -- FILE.fbx EXPECT.json
#
# EXPECT.json keys (all optional except that at least one check must run):
#   joint_names, parents      armature bones and their hierarchy
#   vertex_count              mesh vertex count
#   bbox_min, bbox_max        rest mesh bounds (model axes, metres): checks
#                             size and that model +Y lands on Blender +Z
#   weights                   per vertex {joint name: weight}
#   morph_targets             [{name, deltas: per vertex [dx,dy,dz]}] ->
#                             shape keys by name, in order, with those deltas
#   animation                 {fps, frames: [{index, joint_world: [[x,y,z]..],
#                             morph_weights: {name: w}}]}, frame i = key i
#   tolerance                 position tolerance (default 1e-4 m)
# The smpl-export sidecar (FILE.smpl.json) also works: it has joint_names and
# parents. Exits 1 with one line per failed check.
import contextlib
import io
import json
import os
import sys

import bpy
from mathutils import Vector

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402  (checks, exit status)

check = harness.check
failures = harness.failures


def to_blender(p):
    # Model axes (+Y up, right-handed) as Blender (+Z up) sees them after the
    # importer's axis conversion: x -> x, y -> z, z -> -y.
    return Vector((p[0], -p[2], p[1]))


def import_fbx(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    log = io.StringIO()
    with contextlib.redirect_stdout(log):
        result = bpy.ops.import_scene.fbx(filepath=path)
    text = log.getvalue()
    sys.stdout.write(text)
    check(result == {'FINISHED'}, "import returned %s" % (result,))
    for line in text.splitlines():
        low = line.lower()
        if "warning" in low or "error" in low or "traceback" in low or "assert" in low:
            failures.append("importer printed: " + line.strip())


def single(kind):
    objs = [o for o in bpy.context.scene.objects if o.type == kind]
    check(len(objs) == 1, "expected 1 %s object, found %d" % (kind, len(objs)))
    return objs[0] if objs else None


def check_bones(arm, exp):
    names = exp["joint_names"]
    bones = arm.data.bones
    check(sorted(b.name for b in bones) == sorted(names),
          "bones %s != joints %s" % (sorted(b.name for b in bones), sorted(names)))
    for k, parent in enumerate(exp.get("parents", [])):
        bone = bones.get(names[k])
        if bone is None:
            continue
        want = None if parent < 0 else names[parent]
        got = bone.parent.name if bone.parent else None
        check(got == want, "bone %s parent %s, expected %s" % (names[k], got, want))


def check_bbox(mesh_obj, exp, tol):
    world = [mesh_obj.matrix_world @ v.co for v in mesh_obj.data.vertices]
    lo = [min(p[i] for p in world) for i in range(3)]
    hi = [max(p[i] for p in world) for i in range(3)]
    a, b = to_blender(exp["bbox_min"]), to_blender(exp["bbox_max"])
    want_lo = [min(a[i], b[i]) for i in range(3)]
    want_hi = [max(a[i], b[i]) for i in range(3)]
    for i in range(3):
        check(abs(lo[i] - want_lo[i]) < tol and abs(hi[i] - want_hi[i]) < tol,
              "bbox axis %d: [%.6f, %.6f], expected [%.6f, %.6f]" % (i, lo[i], hi[i], want_lo[i], want_hi[i]))


def check_weights(mesh_obj, exp):
    groups = {g.index: g.name for g in mesh_obj.vertex_groups}
    bad = 0
    for v, want in zip(mesh_obj.data.vertices, exp["weights"]):
        got = {groups[g.group]: g.weight for g in v.groups if g.weight > 0}
        keys = set(got) | set(want)
        if any(abs(got.get(k, 0.0) - want.get(k, 0.0)) > 1e-5 for k in keys):
            if bad < 3:
                failures.append("vertex %d weights %s, expected %s" % (v.index, got, want))
            bad += 1
    check(bad == 0, "%d vertices with wrong weights" % bad)


def check_shape_keys(mesh_obj, exp):
    targets = exp["morph_targets"]
    keys = mesh_obj.data.shape_keys
    if not check(keys is not None, "mesh has no shape keys"):
        return
    names = [kb.name for kb in keys.key_blocks][1:]
    check(names == [t["name"] for t in targets], "shape keys %s" % names)
    basis = keys.key_blocks[0]
    rot = mesh_obj.matrix_world.to_3x3()
    for t in targets:
        kb = keys.key_blocks.get(t["name"])
        if kb is None:
            continue
        worst = 0.0
        for i, d in enumerate(t["deltas"]):
            got = rot @ (kb.data[i].co - basis.data[i].co)
            worst = max(worst, (got - to_blender(d)).length)
        check(worst < 1e-6, "shape key %s: delta error %.3g" % (t["name"], worst))


def check_animation(arm, mesh_obj, exp, tol):
    anim = exp["animation"]
    scene = bpy.context.scene
    check(abs(scene.render.fps / scene.render.fps_base - anim["fps"]) < 1e-6,
          "scene fps %s, expected %s" % (scene.render.fps, anim["fps"]))
    names = exp.get("joint_names", [])
    for frame in anim["frames"]:
        scene.frame_set(1 + frame["index"])  # the importer starts keys at frame 1
        for k, p in enumerate(frame.get("joint_world", [])):
            pb = arm.pose.bones.get(names[k]) if k < len(names) else None
            if pb is None:
                continue
            got = arm.matrix_world @ pb.head
            check((got - to_blender(p)).length < tol,
                  "frame %d joint %s at %s, expected %s" % (frame["index"], names[k], tuple(got), tuple(to_blender(p))))
        keys = mesh_obj.data.shape_keys
        for name, w in frame.get("morph_weights", {}).items():
            kb = keys.key_blocks.get(name) if keys else None
            if kb is None:
                continue
            want = min(max(w, kb.slider_min), kb.slider_max)  # Blender clamps to the slider range
            check(abs(kb.value - want) < 1e-4,
                  "frame %d shape key %s = %.6f, expected %.6f" % (frame["index"], name, kb.value, want))


def main():
    argv = harness.script_args()
    if len(argv) != 2:
        print("usage: blender -b --python blender_fbx_import_check.py -- FILE.fbx EXPECT.json")
        sys.exit(2)  # harness.run: exit 1
    with open(argv[1]) as f:
        exp = json.load(f)
    tol = exp.get("tolerance", 1e-4)
    import_fbx(argv[0])
    arm, mesh_obj = single('ARMATURE'), single('MESH')
    if arm and "joint_names" in exp:
        check_bones(arm, exp)
    if mesh_obj:
        if "vertex_count" in exp:
            check(len(mesh_obj.data.vertices) == exp["vertex_count"],
                  "vertex count %d, expected %d" % (len(mesh_obj.data.vertices), exp["vertex_count"]))
        if "bbox_min" in exp:
            check_bbox(mesh_obj, exp, tol)
        if "weights" in exp:
            check_weights(mesh_obj, exp)
        if "morph_targets" in exp:
            check_shape_keys(mesh_obj, exp)
    if arm and mesh_obj and "animation" in exp:
        check_animation(arm, mesh_obj, exp, tol)
    harness.finish("OK: %s imports as expected" % argv[0])


harness.run(main)
