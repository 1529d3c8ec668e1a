"""The add-on's import options (File > Import > SMPL asset): "Feet on ground"
and "Set timeline to clip", through the registered operator with its
defaults, checked against numpy's forward pass of the model (not against the
add-on's own numbers):

  - animated GLB: the scene rate becomes the clip's, the frame range the
    clip's frames (the factory 1..250 before), and the body is lifted by
    -min over every frame of the model's posed vertices' height (Y-up model
    space = Blender's Z), within --tol; the lift is a pure Z move of the
    top-level objects; at the model's lowest frame Blender's lowest vertex
    is at z = 0 (within --tol);
  - static GLB (no clip): the timeline is left alone and the lift is
    -min(v_shaped y), the rest pose's lowest vertex;
  - feet_on_ground=False: nothing moves.

  blender -b --factory-startup --python-exit-code 1 --python blender_addon_ground.py -- \
      --addon-dir blender --model model.npz --motion walk.npz --asset walk.glb \
      --static body.glb [--fps 30] [--tol 1e-5]
Both assets exported with --max-influences all --skin-weights truncated (the
model's own weights, so numpy's forward pass is the reference as is).
"""
import argparse
import os
import sys

import bpy
import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402  (numpy patch, checks, exit status)
import blender_animation as anim  # noqa: E402  (the motion read with numpy, the reference)
import blender_roundtrip as rt  # noqa: E402
import model_math  # noqa: E402


def parse_args():
    ap = argparse.ArgumentParser()
    ap.add_argument("--addon-dir", required=True)
    ap.add_argument("--model", required=True)
    ap.add_argument("--motion", required=True)
    ap.add_argument("--asset", required=True, help="the model with the motion baked")
    ap.add_argument("--static", required=True, help="the model without a motion")
    ap.add_argument("--fps", type=float, default=0.0, help="the --fps given to smpl-export")
    ap.add_argument("--tol", type=float, default=1e-5)
    return ap.parse_args(harness.script_args())


def fresh_import(path, **options):
    """An empty scene at the factory timeline (24 fps, frames 1..250), then the add-on's import operator."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for action in list(bpy.data.actions):
        bpy.data.actions.remove(action)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = 24, 1.0
    scene.frame_start, scene.frame_end = 1, 250
    scene.frame_set(1)
    before = (scene.render.fps, scene.frame_start, scene.frame_end)
    rt.check(bpy.ops.smpl.import_asset(filepath=os.path.abspath(path), **options) == {"FINISHED"},
             "%s: import failed" % path)
    arms = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    rt.check(len(arms) == 1, "%s: one armature expected" % path)
    return scene, before, arms[0]


def lift_of(arm, roots_before):
    """The world translation the import added to the top-level objects (all must agree)."""
    moves = [np.array(o.matrix_world.translation) - roots_before.get(o.name, np.zeros(3))
             for o in bpy.data.objects if o.parent is None]
    for m in moves[1:]:
        rt.check(np.abs(m - moves[0]).max() < 1e-9, "top-level objects moved differently")
    return moves[0]


def lowest_blender_z(mesh_objs):
    low = np.inf
    for m in mesh_objs:
        low = min(low, rt.evaluated_vertices(m)[:, 1].min())  # model axes: Blender z is model y
    return low


def check_animated(args, model):
    from smpl_correctives import PROP_GROUND_OFFSET
    scene, before, arm = fresh_import(args.asset)
    motion = anim.read_motion(args.motion, args.model)
    fps_out = args.fps or motion["fps"]
    ratio = motion["fps"] / fps_out
    count = int(np.floor((motion["frames"] - 1) / ratio + 1e-9)) + 1
    rate = scene.render.fps / scene.render.fps_base
    print("timeline before %s after fps %.4f frames %d..%d clip frames %d"
          % (before, rate, scene.frame_start, scene.frame_end, count))
    rt.check(abs(rate - fps_out) < 1e-6, "scene rate %.4f, clip %g fps" % (rate, fps_out))
    rt.check(scene.frame_end - scene.frame_start + 1 == count,
             "timeline %d..%d for a %d-frame clip" % (scene.frame_start, scene.frame_end, count))
    first = scene.frame_start

    ref = anim.Reference(model, motion, model["weights"])
    heights = np.array([ref.at(i * ratio)[0][:, 1].min() for i in range(count)])
    lowest_frame = int(heights.argmin())
    want = -heights.min()
    lift = lift_of(arm, {})
    got = float(arm[PROP_GROUND_OFFSET])
    print("feet_on_ground clip lift_m %.6f model_lowest_m %.6f at frame %d error_m %.3e"
          % (got, heights.min(), lowest_frame, abs(got - want)))
    rt.check(abs(got - want) <= args.tol, "clip lift %.6f m, model says %.6f m" % (got, want))
    rt.check(abs(lift[2] - got) < 1e-6 and np.abs(lift[:2]).max() < 1e-9,
             "the lift is not a pure Z move of %.6f m: %s" % (got, lift))
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    scene.frame_set(first + lowest_frame)
    low = lowest_blender_z(meshes)
    print("feet_on_ground lowest_frame blender_min_z_m %.3e" % low)
    rt.check(abs(low) <= args.tol, "lowest vertex at the clip's lowest frame is at z = %.3g m" % low)


def check_static(args, model):
    from smpl_correctives import PROP_GROUND_OFFSET
    scene, before, arm = fresh_import(args.static)
    rt.check((scene.render.fps, scene.frame_start, scene.frame_end) == before,
             "a file without a clip changed the timeline: %s -> %s"
             % (before, (scene.render.fps, scene.frame_start, scene.frame_end)))
    betas = (rt_meta(args.static).get("betas") or [])
    v_shaped, _ = model_math.shape(model, np.array(betas, dtype=float))
    want = -v_shaped[:, 1].min()
    got = float(arm[PROP_GROUND_OFFSET])
    print("feet_on_ground rest lift_m %.6f model_rest_lowest_m %.6f error_m %.3e" % (got, -want, abs(got - want)))
    rt.check(abs(got - want) <= args.tol, "rest lift %.6f m, model says %.6f m" % (got, want))

    scene, _, arm = fresh_import(args.static, feet_on_ground=False)
    lift = lift_of(arm, {})
    rt.check(np.abs(lift).max() < 1e-9 and PROP_GROUND_OFFSET not in arm,
             "feet_on_ground=False moved the body by %s" % lift)


def rt_meta(path):
    from smpl_correctives import correctives
    return correctives.metadata_from_file(path) or {}


def main():
    args = parse_args()
    sys.path.insert(0, os.path.abspath(args.addon_dir))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import smpl_correctives
    smpl_correctives.register()
    model = model_math.load_model_npz(args.model)
    check_animated(args, model)
    check_static(args, model)
    harness.finish()


if __name__ == "__main__":
    harness.run(main)
