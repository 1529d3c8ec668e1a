"""The add-on as a user gets it: installed from smpl_correctives.zip, its
operators registered, "Import SMPL asset" binding and enabling, the edit
(depsgraph) handler and the frame-change handler driving the keys during
playback of a keyframed action, Disable stopping it, unregister removing
the handlers.

  blender -b --factory-startup --python blender_addon_test.py -- \
      --zip smpl_correctives.zip --asset body.glb --model model.npz
Run with BLENDER_USER_SCRIPTS pointing at a scratch directory (the add-on is
installed there).
"""
import argparse
import os
import sys

import bpy
import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402  (numpy patch, checks, exit status)
import blender_roundtrip as rt  # noqa: E402
import model_math  # noqa: E402


def parse_args():
    ap = argparse.ArgumentParser()
    ap.add_argument("--zip", required=True)
    ap.add_argument("--asset", required=True)
    ap.add_argument("--model", required=True)
    return ap.parse_args(harness.script_args())


def install(zip_path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    bpy.ops.preferences.addon_enable(module="smpl_correctives")
    rt.check(hasattr(bpy.types, "SMPL_PT_panel"), "panel not registered")
    for op in ("import_asset", "enable_correctives", "disable_correctives"):
        rt.check(hasattr(bpy.ops.smpl, op), "operator smpl.%s not registered" % op)


def key_values(mesh_obj, names):
    keys = rt.key_lookup(mesh_obj)
    return np.array([keys[t].value for t in model_math.target_names(names)])


def check_edit_handler(arm, mesh_obj, names, pose, enabled):
    """Posing (no animation) fires depsgraph_update_post: keys follow if enabled."""
    before = key_values(mesh_obj, names)
    rt.pose_armature(arm, names, model_math.rodrigues(pose))
    bpy.context.view_layer.update()
    want = (model_math.rodrigues(pose)[1:] - np.eye(3)).reshape(-1)
    got = key_values(mesh_obj, names)
    if enabled:
        err = np.abs(got - want).max()
        rt.check(err <= 1e-5, "edit handler: key values off by %.3g" % err)
    else:
        rt.check(np.array_equal(got, before), "keys changed after Disable")


def check_names_only(arm, mesh_obj, names, pose):
    """Without any metadata (an FBX with no sidecar), names alone must bind
    every key and give the same values."""
    from smpl_correctives import correctives
    del arm[correctives.PROP_METADATA]
    bound = correctives.bind(arm, mesh_obj)
    rt.check(bound == 9 * (len(names) - 1), "names-only bind found %d keys" % bound)
    rt.pose_armature(arm, names, model_math.rodrigues(pose))
    bpy.context.view_layer.update()
    correctives.apply(arm, mesh_obj)
    want = (model_math.rodrigues(pose)[1:] - np.eye(3)).reshape(-1)
    err = np.abs(key_values(mesh_obj, names) - want).max()
    rt.check(err <= 1e-5, "names-only bind: key values off by %.3g" % err)


def check_playback(arm, mesh_obj, model, names, poses, weights, v_shaped, joints, index):
    """Keyframe the poses on frames 1..P, play them back through frame_set."""
    arm.animation_data_create()
    for frame, pose in enumerate(poses, start=1):
        rt.pose_armature(arm, names, model_math.rodrigues(pose))
        for n in names:
            arm.pose.bones[n].keyframe_insert("rotation_quaternion", frame=frame)
    worst = 0.0
    for frame, pose in enumerate(poses, start=1):
        bpy.context.scene.frame_set(frame)
        got = rt.evaluated_vertices(mesh_obj)
        want = model_math.forward(model, v_shaped, joints, pose, weights)[0]
        worst = max(worst, np.linalg.norm(got - want[index], axis=1).max())
    print("playback frames=%d max_err_m %.3e" % (len(poses), worst))
    rt.check(worst <= 1e-5, "frame-change handler: vertex error %.3g m" % worst)


README = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "engines.md")


def readme_import_line():
    """The one-line import (docs/engines.md) of the add-on's module (Blender add-on section)."""
    with open(README, encoding="utf-8") as f:
        lines = [l.strip() for l in f if l.startswith("    import sys; correctives = ")]
    rt.check(len(lines) == 1, "docs/engines.md: expected one '    import sys; correctives = ...' line, got %d" % len(lines))
    return lines[0] if lines else "correctives = None"


def run_line(line):
    scope = {}
    try:
        exec(line, scope)
    except Exception as e:  # noqa: BLE001  (reported as a check failure)
        rt.check(False, "docs/engines.md import line failed: %s: %s" % (type(e).__name__, e))
    return scope.get("correctives")


def check_readme_import():
    """The README's import line finds the module as a legacy add-on (this
    Blender) and as a Blender 4.2+ extension: the installed package loaded
    under bl_ext.user_default.smpl_correctives, with the legacy names hidden."""
    import importlib.util
    import types
    from smpl_correctives import correctives as legacy
    line = readme_import_line()
    rt.check(run_line(line) is legacy, "README import line: not smpl_correctives.correctives")
    pkg_dir = os.path.dirname(legacy.__file__)
    hidden = {n: sys.modules.pop(n) for n in list(sys.modules) if n.split(".")[0] == "smpl_correctives"}
    try:
        for name in ("bl_ext", "bl_ext.user_default"):
            parent = types.ModuleType(name)
            parent.__path__ = []
            sys.modules[name] = parent
        name = "bl_ext.user_default.smpl_correctives"
        spec = importlib.util.spec_from_file_location(name, os.path.join(pkg_dir, "__init__.py"),
                                                      submodule_search_locations=[pkg_dir])
        ext = importlib.util.module_from_spec(spec)
        sys.modules[name] = ext
        spec.loader.exec_module(ext)
        found = run_line(line)
        rt.check(found is not None and found.__name__ == name + ".correctives" and hasattr(found, "apply"),
                 "README import line as an extension: got %r" % found)
    finally:
        for n in [n for n in sys.modules if n.split(".")[0] == "bl_ext"]:
            del sys.modules[n]
        sys.modules.update(hidden)


def main():
    args = parse_args()
    install(args.zip)
    check_readme_import()
    from smpl_correctives import correctives
    bpy.ops.smpl.import_asset(filepath=os.path.abspath(args.asset), feet_on_ground=False)  # world positions as exported
    arms = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    meshes = [o for o in bpy.data.objects if o.type == "MESH" and o.data.shape_keys]
    rt.check(len(arms) == 1 and len(meshes) == 1, "import: expected one armature and one mesh")
    arm, mesh_obj = arms[0], meshes[0]
    rt.check(correctives.is_enabled(arm, mesh_obj), "import did not enable the correctives")
    meta = correctives.metadata_from_file(args.asset)
    model = model_math.load_model_npz(args.model)
    names = model_math.joint_names(len(model["parents"]))
    keys = rt.key_lookup(mesh_obj)
    ranges = {(keys[t].slider_min, keys[t].slider_max) for t in model_math.target_names(names)}
    rt.check(ranges == {(-2.0, 2.0)}, "slider ranges not widened: %s" % sorted(ranges)[:3])

    v_shaped, joints = model_math.shape(model, meta["betas"])
    index, _ = rt.vertex_map(mesh_obj, v_shaped)
    weights = model_math.prune(model["weights"], int(meta["max_influences"]))
    poses = np.random.default_rng(3).uniform(-0.6, 0.6, (6, len(names), 3))
    check_edit_handler(arm, mesh_obj, names, poses[0], True)
    check_playback(arm, mesh_obj, model, names, poses[1:], weights, v_shaped, joints, index)

    bpy.context.view_layer.objects.active = arm
    arm.select_set(True)
    bpy.ops.smpl.disable_correctives()
    arm.animation_data.action = None
    check_edit_handler(arm, mesh_obj, names, poses[0] * 0.5, False)
    check_names_only(arm, mesh_obj, names, poses[2])
    bpy.ops.preferences.addon_disable(module="smpl_correctives")
    leftover = [h for h in bpy.app.handlers.frame_change_post + bpy.app.handlers.depsgraph_update_post
                if getattr(h, "__module__", "").startswith("smpl_correctives")]
    rt.check(not leftover, "handlers left after unregister: %s" % leftover)
    harness.finish()


if __name__ == "__main__":
    harness.run(main)
