"""Headless-Blender check of a --scene GLB or FBX (docs/file-contract.md "Scene files"): Blender's own
glTF (or FBX) importer loads every body (one armature named after the body and one skinned mesh
<body>_mesh each),
plays the one animation, and the evaluated mesh of each body is compared with numpy's forward pass
(written by tests/cli/scene_check.py --expected-out: per body the scene frames checked, the
expected vertices where the body is present, "hidden" where it is absent, its rest mesh for the
vertex map).

  blender -b --factory-startup --python-exit-code 1 --python blender_scene.py -- \
      --asset scene.glb --expected scene.glb.expected.json [--tol 1e-5]

Present: max vertex error <= tol. Hidden: the body's vertices on one point (spread <= 1e-6 m),
which is what scale 0 on the body node (the armature object) gives in Blender. The camera: its
world position, view direction and up at the checked frames (and its vertical field of view
against the file's). FBX only, sensitivity (each must be >= 1 mm / 1e-3 away, so the checks can
fail): every present body read one frame later (a start off by a frame), and the camera read
without the FBX camera axis correction (FBX cameras look down +X: io_scene_fbx MAT_CONVERT_CAMERA).
Exit status 0 only if every check passes.
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
import blender_roundtrip as rt  # noqa: E402  (world_to_model, evaluated_vertices, vertex_map)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--asset", required=True)
    ap.add_argument("--expected", required=True)
    ap.add_argument("--tol", type=float, default=1e-5)
    args = ap.parse_args(harness.script_args())
    with open(args.expected, encoding="utf-8") as fh:
        ref = json.load(fh)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = int(round(ref["fps"])), 1.0
    fbx = args.asset.lower().endswith(".fbx")
    if fbx:
        bpy.ops.import_scene.fbx(filepath=args.asset)
    else:
        bpy.ops.import_scene.gltf(filepath=args.asset)
    # The glTF importer keys time t at frame t * fps, the FBX importer at 1 + t * fps (its
    # anim_offset default).
    offset = 1 - ref["first_frame"] if fbx else -ref["first_frame"]
    arms = sorted(o.name for o in bpy.data.objects if o.type == "ARMATURE")
    meshes = {o.name: o for o in bpy.data.objects if o.type == "MESH"}
    harness.check(arms == sorted(ref["bodies"]), "armatures %s for bodies %s" % (arms, sorted(ref["bodies"])))
    cameras = [o for o in bpy.data.objects if o.type == "CAMERA"]
    harness.check(len(cameras) == (1 if ref.get("camera") else 0), "%d cameras" % len(cameras))
    worst = 0.0
    for name, body in sorted(ref["bodies"].items()):
        obj = meshes.get(name + "_mesh")
        if not harness.check(obj is not None, "no mesh object %s (have %s)" % (name, sorted(meshes))):
            continue
        # The map reads the rest mesh through the object's world matrix, which the armature's
        # scale 0 collapses while the body is hidden: take it at a frame where it is shown.
        shown = [f for f, v in zip(body["frames"], body["vertices"]) if v != "hidden"]
        scene.frame_set(shown[0] + offset)
        index, _ = rt.vertex_map(obj, np.array(body["rest"]))
        shifted = np.inf
        for frame, want in zip(body["frames"], body["vertices"]):
            scene.frame_set(frame + offset)
            bpy.context.view_layer.update()
            got = rt.evaluated_vertices(obj)
            if want == "hidden":
                spread = float(np.ptp(got, axis=0).max())
                print("blender %s frame %d hidden spread_m %.3e" % (name, frame, spread))
                harness.check(spread <= 1e-6, "%s frame %d: not hidden (spread %.3g m)" % (name, frame, spread))
                continue
            err = float(np.abs(got - np.array(want)[index]).max())
            worst = max(worst, err)
            print("blender %s frame %d max_err_m %.3e" % (name, frame, err))
            harness.check(err <= args.tol, "%s frame %d: max vertex error %.3g m > %g" % (name, frame, err, args.tol))
            if fbx and frame + 1 < ref["end_frame"]:
                scene.frame_set(frame + offset + 1)
                bpy.context.view_layer.update()
                shifted = min(shifted, float(np.abs(rt.evaluated_vertices(obj) - np.array(want)[index]).max()))
        if fbx:
            print("blender %s: read one frame later >= %.3e m away" % (name, shifted))
            harness.check(shifted >= 1e-3, "%s: one frame later only %.3g m away" % (name, shifted))
    if ref.get("camera") and cameras:
        check_camera(scene, cameras[0], ref, offset, fbx)
    print("blender scene worst max_err_m %.3e" % worst)


def check_camera(scene, camera, ref, offset, fbx):
    """The camera object at each expected frame: its world position, view direction (Blender's
    cameras look down local -z, as glTF's) and up (+y), brought to the file's axes, against numpy's;
    its vertical field of view against the file's. FBX: the same read without the importer's
    camera correction (the FBX node's own axes, +X forward) must be far off."""
    want = ref["camera"]
    # io_scene_fbx import_fbx.py: a camera node's matrix is post-multiplied by MAT_CONVERT_CAMERA
    # = Ry(+90 deg) inverted; undoing it gives the FBX node's own matrix.
    undo = np.array([[0.0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 1]])  # Ry(+90 deg)
    wrong = 0.0 if fbx else np.inf
    for i, frame in enumerate(want["frames"]):
        scene.frame_set(frame + offset)
        bpy.context.view_layer.update()
        mw = np.array(camera.matrix_world)
        err = camera_error(mw, want, i)
        print("blender camera frame %d max_err %.3e" % (frame, err))
        harness.check(err <= 1e-5, "camera frame %d: position/direction/up off by %.3g" % (frame, err))
        if fbx:
            wrong = max(wrong, camera_error(mw @ undo, want, i))
    if fbx:
        print("blender camera without the +X/-Z axis correction: %.3e away" % wrong)
        harness.check(wrong >= 1e-3, "camera: the uncorrected reading only %.3g away" % wrong)
    if "yfov" in want:
        yfov = float(camera.data.angle_y)
        print("blender camera yfov %.7f, file %.7f, error %.3e rad" % (yfov, want["yfov"], abs(yfov - want["yfov"])))
        harness.check(abs(yfov - want["yfov"]) <= 1e-5, "camera yfov %.7f, expected %.7f" % (yfov, want["yfov"]))


def camera_error(mw, want, i):
    got = [mw[:3, 3], -mw[:3, 2] / np.linalg.norm(mw[:3, 2]), mw[:3, 1] / np.linalg.norm(mw[:3, 1])]
    return max(float(np.abs(rt.world_to_model(g[None, :])[0] - np.array(w[i])).max())
               for g, w in zip(got, [want["position"], want["direction"], want["up"]]))


if __name__ == "__main__":
    harness.run(main)
