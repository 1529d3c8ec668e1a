"""Headless-Blender check of baked animation: import an animated GLB/FBX
written by `smpl-export --motion`, play it with NO runtime script (the baked
weights channel / DeformPercent curves alone drive the correctives), and
compare the evaluated mesh at chosen frames with numpy's forward pass of the
motion file read here with numpy (AMASS/plain .npz, SMPLCodec .smpl, and
SMPLify-X .pkl fits with PCA hands per the authors' smplx code).

  blender -b --factory-startup --python-exit-code 1 --python blender_animation.py -- \
      --asset walk.glb --model model.npz --motion walk.npz [--fps 30] [--tol 1e-4] \
      [--label smplh] [--subframe-report] [--check-floor]

Reference (independent of the C++ code): joints mapped by canonical name
(model_math.joint_names), betas = the motion's first min(16, B) values, weights
pruned to the asset's max_influences (model_math.prune), output frame i at
source position i * fps_src / fps_out (quaternion slerp, linear trans), vertices
+ trans, then C = Rx(-90 deg) (AMASS files are Z-up; the export is Y-up).

Prints one line per checked frame: "format layout M frame max_err_m".
Each frame is checked twice: as imported, and with the shape key slider
ranges opened to [-10, 10] (what an importer that does not clamp would give),
which separates importer clamping from everything else; both are asserted.
--subframe-report (after widening): also evaluates Blender half-way between
output keys and prints its error against the slerped keys and against the
source motion at that time (the resampling loss), without asserting on them.
--origin floor / --root-bone exports (the sidecar's "origin" and "root_bone"):
the reference moves by the metadata's offset; --check-floor asserts that
numpy's lowest posed vertex over every output frame is at y = 0 (1e-6 m), and
with a root bone, at each checked frame, that Blender's `root` bone is the
ground projection (x, 0, z) of numpy's pelvis joint and the parent of `pelvis`.
Exit status 0 only if every check passes.
"""
import argparse
import os
import sys
import time

import bpy
import numpy as np

sys.dont_write_bytecode = True  # run from the source tree: leave no __pycache__ there
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_harness as harness  # noqa: E402  (numpy patch, checks, exit status)
import blender_roundtrip as rt  # noqa: E402  (import helpers)
import model_math  # noqa: E402

# AMASS world (Z-up) -> exported model axes (Y-up): -90 degrees about X.
Z_UP_TO_Y_UP = np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]])


def parse_args():
    argv = harness.script_args()
    ap = argparse.ArgumentParser()
    ap.add_argument("--asset", required=True)
    ap.add_argument("--model", required=True, help="model .npz (read with numpy)")
    ap.add_argument("--motion", required=True, help="motion .npz (read with numpy)")
    ap.add_argument("--fps", type=float, default=0.0, help="the --fps given to smpl-export")
    ap.add_argument("--tol", type=float, default=1e-4)
    ap.add_argument("--label", default="")
    ap.add_argument("--subframe-report", action="store_true")
    ap.add_argument("--check-floor", action="store_true",
                    help="numpy's lowest posed vertex over the clip must be at y = 0")
    return ap.parse_args(argv)


# --- the motion, read with numpy -------------------------------------------------

def read_codec(data):
    """SMPLCodec .smpl (smplcodec codec.py keys; SMPL-X only here): the same dict as read_motion."""
    body = np.asarray(data["bodyPose"], dtype=np.float64)
    frames = body.shape[0]
    if body.shape[1] == 21:  # no root: globalOrient or rest
        root = data["globalOrient"].reshape(frames, 1, 3) if "globalOrient" in data.files else np.zeros((frames, 1, 3))
        body = np.concatenate([root, body], axis=1)
    zeros = np.zeros((frames, 15, 3))
    parts = [body, data["headPose"] if "headPose" in data.files else np.zeros((frames, 3, 3)),
             data["leftHandPose"] if "leftHandPose" in data.files else zeros,
             data["rightHandPose"] if "rightHandPose" in data.files else zeros]
    poses = np.concatenate([np.asarray(p, dtype=np.float64) for p in parts], axis=1)
    names = model_math.joint_names(55)
    trans = np.asarray(data["bodyTranslation"], np.float64) if "bodyTranslation" in data.files else np.zeros((frames, 3))
    fps = float(data["frameRate"]) if "frameRate" in data.files else 30.0
    return {"rot": {n: poses[:, j] for j, n in enumerate(names)}, "trans": trans, "fps": fps, "frames": frames,
            "betas": np.asarray(data["shapeParameters"], np.float64), "amass": False}


def read_fit(path, model_path):
    """SMPLify-X style fit (.pkl, batch dim 1) with the authors' hand math (smplx SMPLX.forward):
    hand = coefficients @ hands_components[:C] (C < 45) + hands_mean."""
    import pickle
    with open(path, "rb") as fh:
        fit = {k: np.asarray(v, np.float64) for k, v in pickle.load(fh).items()}
    model = np.load(model_path)
    hands = []
    for side, key in (("l", "left_hand_pose"), ("r", "right_hand_pose")):
        coeffs = fit[key].reshape(-1)
        pose = coeffs if coeffs.size == 45 else coeffs @ model["hands_components" + side][:coeffs.size]
        hands.append((pose + model["hands_mean" + side]).reshape(15, 3))
    pose = np.concatenate([fit["global_orient"].reshape(1, 3), fit["body_pose"].reshape(21, 3),
                           fit["jaw_pose"].reshape(1, 3), fit["leye_pose"].reshape(1, 3),
                           fit["reye_pose"].reshape(1, 3)] + hands)[None]
    names = model_math.joint_names(55)
    return {"rot": {n: pose[:, j] for j, n in enumerate(names)}, "trans": fit["transl"].reshape(1, 3),
            "betas": fit["betas"].reshape(-1), "fps": 30.0, "frames": 1, "amass": False}


def read_motion(path, model_path=None):
    """Joint name -> (T,3) axis-angle, trans (T,3), betas, fps (AMASS SMPL-H / SMPL-X / SMPL,
    SMPLCodec .smpl, SMPLify-X .pkl fits)."""
    if path.endswith(".pkl"):
        return read_fit(path, model_path)
    data = np.load(path, allow_pickle=False)
    if "bodyPose" in data.files:
        return read_codec(data)
    if "root_orient" in data.files:  # AMASS SMPL-X release: split keys
        parts = [data[k] for k in ("root_orient", "pose_body", "pose_jaw", "pose_eye", "pose_hand")]
        poses = np.concatenate(parts, axis=1)
    else:
        poses = np.asarray(data["poses"], dtype=np.float64)
    frames = poses.shape[0]
    poses = poses.reshape(frames, -1, 3)
    names = model_math.joint_names(poses.shape[1])  # SMPL 24, SMPL-H 52, SMPL-X 55
    fps = next(float(data[k]) for k in ("mocap_framerate", "mocap_frame_rate", "fps") if k in data.files)
    trans = np.asarray(data["trans"], dtype=np.float64) if "trans" in data.files else np.zeros((frames, 3))
    betas = np.asarray(data["betas"], dtype=np.float64) if "betas" in data.files else np.zeros(0)
    amass = "mocap_framerate" in data.files or "mocap_frame_rate" in data.files
    return {"rot": {n: poses[:, j] for j, n in enumerate(names)}, "trans": trans, "betas": betas,
            "fps": fps, "frames": frames, "amass": amass}


def quat_from_aa(aa):
    angle = np.linalg.norm(aa)
    axis = aa / angle if angle > 0 else np.zeros(3)
    return np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * axis])


def aa_from_quat(q):
    q = q / np.linalg.norm(q)
    if q[0] < 0:
        q = -q
    s = np.linalg.norm(q[1:])
    return np.zeros(3) if s < 1e-15 else 2 * np.arctan2(s, q[0]) * q[1:] / s


def slerp_aa(a, b, t):
    """Slerp between two axis-angle rotations, returned as axis-angle."""
    qa, qb = quat_from_aa(a), quat_from_aa(b)
    if qa @ qb < 0:
        qb = -qb
    cos = min(1.0, qa @ qb)
    omega = np.arccos(cos)
    if omega < 1e-12:
        return aa_from_quat(qa)
    return aa_from_quat((np.sin((1 - t) * omega) * qa + np.sin(t * omega) * qb) / np.sin(omega))


def pose_at(motion, names, position):
    """(K,3) axis-angle for the model's joints and trans at a source position (frames)."""
    last = motion["frames"] - 1
    f0 = min(int(np.floor(position + 1e-9)), last)
    t = max(0.0, position - f0) if f0 < last else 0.0
    f1 = min(f0 + 1, last)
    pose = np.zeros((len(names), 3))
    for k, name in enumerate(names):
        if name in motion["rot"]:  # joints the motion lacks keep the rest rotation
            track = motion["rot"][name]
            pose[k] = track[f0] if t < 1e-12 else slerp_aa(track[f0], track[f1], t)
    trans = (1 - t) * motion["trans"][f0] + t * motion["trans"][f1]
    return pose, trans


class Reference:
    """numpy forward pass of the motion on the model, in exported (Y-up) axes."""

    def __init__(self, model, motion, weights):
        self.model, self.motion, self.weights = model, motion, weights
        self.names = model_math.joint_names(len(model["parents"]))
        b = min(model["shapedirs"].shape[2], 300)  # SMPL-X stores 300 shape + 100 expression columns
        self.betas = motion["betas"][:min(16, b)]
        self.v_shaped, self.joints = model_math.shape(model, self.betas)
        self.up = Z_UP_TO_Y_UP if motion["amass"] else np.eye(3)
        self.shift = np.zeros(3)  # --origin floor: the metadata's offset (file frame)

    def at(self, position, features=None):
        """Vertices (N,3), joints (K,3), features; `features` overrides the corrective weights."""
        pose, trans = pose_at(self.motion, self.names, position)
        v_shaped = self.v_shaped
        if features is not None:  # forward() is linear in v_shaped for fixed joints
            f_model = (model_math.rodrigues(pose)[1:] - np.eye(3)).reshape(-1)
            v_shaped = v_shaped + self.model["posedirs"] @ (features - f_model)
        verts, joints, f = model_math.forward(self.model, v_shaped, self.joints, pose, self.weights)
        return (verts + trans) @ self.up.T + self.shift, (joints + trans) @ self.up.T + self.shift, f


# --- Blender side ----------------------------------------------------------------

def import_asset(path, fps):
    """Import with the scene at the output rate: the glTF importer keys at t * scene fps."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = int(round(fps)), 1.0
    fmt = os.path.splitext(path)[1].lstrip(".").lower()
    if fmt == "glb":
        bpy.ops.import_scene.gltf(filepath=path)
    else:
        bpy.ops.import_scene.fbx(filepath=path)  # sets the scene rate from the file's TimeMode
    arms = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    meshes = [o for o in bpy.data.objects if o.type == "MESH" and o.data.shape_keys]
    if len(arms) != 1 or len(meshes) != 1:
        raise SystemExit("%s: expected 1 armature and 1 mesh with shape keys, found %d and %d"
                         % (path, len(arms), len(meshes)))
    rt.check(abs(scene.render.fps / scene.render.fps_base - fps) < 1e-6,
             "%s: scene rate after import %.4f fps, expected %g" % (path, scene.render.fps / scene.render.fps_base, fps))
    for obj, what in ((arms[0], "armature"), (meshes[0].data.shape_keys, "shape keys")):
        ad = obj.animation_data
        rt.check(ad is not None and ad.action is not None, "%s: no active action on the %s" % (path, what))
    return fmt, arms[0], meshes[0]


def key_blocks(mesh_obj, targets, evaluated=True):
    """Shape key blocks of the corrective entries' targets, in entry order (importers may prefix names)."""
    keys = mesh_obj.data.shape_keys
    if evaluated:
        keys = keys.evaluated_get(bpy.context.evaluated_depsgraph_get())
    table = {}
    for kb in keys.key_blocks:
        table[kb.name] = kb
        table.setdefault(kb.name.rsplit("|", 1)[-1], kb)
    return [table[t] for t in targets]


def file_posedirs(mesh_obj, entries, model, index, got_weights):
    """The corrective deltas the file carries, as (N,3,P) posedirs in model
    vertex order: each feature's first entry decoded (posedirs_n = scale x
    delta for every encoding). Where the file's skin keeps all of a vertex's
    model influences they must equal posedirs (1e-6 m, float32 keys);
    elsewhere --corrective-refit may have refitted them
    (docs/file-contract.md), and the reference poses the file's deltas, as
    it takes the file's weights."""
    posedirs = model["posedirs"]
    n = len(mesh_obj.data.vertices)
    first = {}
    for e in entries:
        first.setdefault(e["feature"], e)
    blocks = key_blocks(mesh_obj, [first[f]["target"] for f in sorted(first)], evaluated=False)
    basis = np.empty(n * 3, dtype=np.float32)
    mesh_obj.data.shape_keys.reference_key.data.foreach_get("co", basis)
    linear = np.array(mesh_obj.matrix_world, dtype=np.float64)[:3, :3]
    co = np.empty(n * 3, dtype=np.float32)
    cut = ((model["weights"] > 0).sum(1) > (got_weights > 0).sum(1))[index]
    out = posedirs.astype(np.float64).copy()
    worst = 0.0
    for f, kb in zip(sorted(first), blocks):
        kb.data.foreach_get("co", co)
        delta = first[f].get("scale", 1.0) * rt.world_to_model(
            (co.astype(np.float64) - basis).reshape(n, 3) @ linear.T)
        out[index[cut], :, f] = delta[cut]
        worst = max(worst, np.abs(delta[~cut] - posedirs[index[~cut], :, f]).max(initial=0.0))
    print("morph_delta_err_m %.3e (refitted vertices: %d)" % (worst, int(cut.sum())))
    rt.check(worst <= 1e-6, "morph target deltas differ from posedirs by %.3g" % worst)
    return out


def corrective_entries(asset):
    """The metadata's corrective entries (signed, unit or split: one or two per feature)."""
    import json
    with open(asset + ".smpl.json", encoding="utf-8") as fh:
        meta = json.load(fh)
    return meta["correctives"], meta.get("skin_weights", "truncated")


def decode_features(entries, values, count):
    """Per feature, sum over its entries of (value - offset) / scale: f for every encoding
    (split: the _pos and _neg parts add up to f)."""
    f = np.zeros(count)
    for e, v in zip(entries, values):
        f[e["feature"]] += (v - e.get("offset", 0.0)) / e.get("scale", 1.0)
    return f


def evaluate(scene, frame, subframe=0.0):
    scene.frame_set(frame, subframe=subframe)
    bpy.context.view_layer.update()


def explain_clamping(ctx, position, got, keys, f, lo, hi):
    """Print whether Blender's key values are f clamped to the slider ranges, and
    whether numpy with Blender's key values reproduces Blender's mesh."""
    ref, index = ctx["ref"], ctx["index"]
    explained = np.linalg.norm(got - ref.at(position, keys)[0][index], axis=1).max()
    bad = np.abs(keys - f) > 1e-5
    clamped = np.abs(keys - np.clip(f, lo, hi)).max() <= 1e-5
    print("  %d of %d key values differ from f (worst %.3f); key values == f clamped to the "
          "slider ranges: %s; numpy with Blender's key values: %.3e m"
          % (bad.sum(), f.size, np.abs(keys - f).max(), clamped, explained))
    if bad.any():
        i = np.flatnonzero(bad)[:3]
        print("  e.g. f %s -> key %s, slider_min %s" % (np.round(f[i], 4), np.round(keys[i], 4),
                                                      np.round(lo[i], 4)))


def check_frame(ctx, out_frame, position, tol, tag):
    """Blender at output key `out_frame` vs numpy at source `position`; returns the error."""
    evaluate(bpy.context.scene, out_frame + ctx["offset"])
    ref, index = ctx["ref"], ctx["index"]
    got = rt.evaluated_vertices(ctx["mesh"])
    want, want_joints, f = ref.at(position)
    err = np.linalg.norm(got - want[index], axis=1).max()
    joint_err = np.abs(rt.posed_joints(ctx["arm"], ref.names) - want_joints).max()
    entries = ctx["entries"]
    blocks = key_blocks(ctx["mesh"], [e["target"] for e in entries])
    # Key values decoded to features: weight = scale * f + offset (file metadata).
    keys = decode_features(entries, [kb.value for kb in blocks], f.size)
    lo = decode_features(entries, [kb.slider_min for kb in blocks], f.size)
    hi = decode_features(entries, [kb.slider_max for kb in blocks], f.size)
    print("%s %s%s %d %d %.3e" % (ctx["fmt"], ctx["label"], tag, ctx["m"], out_frame, err))
    print("  joints_err_m %.3e key_value_err %.3e (f in [%.3f, %.3f])"
          % (joint_err, np.abs(keys - f).max(), f.min(), f.max()))
    if abs(position - round(position)) > 1e-9:  # a key between source frames
        near = [np.linalg.norm(got - ref.at(p)[0][index], axis=1).max()
                for p in (np.floor(position), np.ceil(position))]
        print("  key at source frame %.2f: vs source frame %d %.3e m, vs source frame %d %.3e m"
              % (position, np.floor(position), near[0], np.ceil(position), near[1]))
    if err > tol:
        explain_clamping(ctx, position, got, keys, f, lo, hi)
    rt.check(joint_err <= tol, "frame %d: posed joints off by %.3g m" % (out_frame, joint_err))
    if ctx["root_bone"]:
        check_root_bone(ctx, out_frame, want_joints[0], tol)
    rt.check(err <= tol, "%s%s frame %d: max vertex error %.3g m > %g"
             % (ctx["fmt"], tag, out_frame, err, tol))
    return err


def check_root_bone(ctx, out_frame, pelvis, tol):
    """--root-bone: Blender's root bone at the pelvis' ground projection, parent of pelvis."""
    arm = ctx["arm"]
    root = rt.posed_joints(arm, ["root"])[0]
    err = np.abs(root - [pelvis[0], 0.0, pelvis[2]]).max()
    print("  root_bone_vs_pelvis_ground_projection_m %.3e" % err)
    rt.check(err <= tol, "frame %d: root bone off the pelvis' ground projection by %.3g m" % (out_frame, err))
    parent = arm.pose.bones["pelvis"].parent
    rt.check(parent is not None and parent.name == "root", "pelvis' parent is %s, not root"
             % (parent.name if parent else None))


def disconnect_pelvis(arm):
    """Blender's FBX importer connects a bone to its parent when the child's head lies on
    the parent's tail, which it puts along the parent's +Y at the mean child distance: so
    `pelvis`, right above `root`, is connected and its animated height is ignored. The
    documented import step (README "In a game engine"): untick Connected on `pelvis`."""
    bpy.context.view_layer.objects.active = arm
    bpy.ops.object.mode_set(mode="EDIT")
    bone = arm.data.edit_bones["pelvis"]
    print("fbx import: pelvis connected to root: %s (disconnected for playback)" % bone.use_connect)
    bone.use_connect = False
    bpy.ops.object.mode_set(mode="OBJECT")


def check_floor(ref, ratio, count):
    """numpy's lowest posed vertex over every output frame (the shifted reference) is at y = 0."""
    lowest = min(ref.at(i * ratio)[0][:, 1].min() for i in range(count))
    print("floor lowest_posed_vertex_y_m %.3e over %d frames (offset %.6f m)" % (lowest, count, ref.shift[1]))
    rt.check(abs(lowest) <= 1e-6, "lowest posed vertex over the clip at y = %.3g m, not 0" % lowest)


def subframe_report(ctx, ratio, count):
    """Half-way between output keys: vs the slerped keys and vs the source motion there."""
    ref, index = ctx["ref"], ctx["index"]
    for i in (0, count // 2, count - 2):
        evaluate(bpy.context.scene, i + ctx["offset"], 0.5)
        got = rt.evaluated_vertices(ctx["mesh"])
        pos0, pos1 = i * ratio, (i + 1) * ratio
        # The pose an engine that slerps between the two output keys would show.
        pa, ta = pose_at(ref.motion, ref.names, pos0)
        pb, tb = pose_at(ref.motion, ref.names, pos1)
        mid = np.array([slerp_aa(a, b, 0.5) for a, b in zip(pa, pb)])
        verts = model_math.forward(ref.model, ref.v_shaped, ref.joints, mid, ref.weights)[0]
        slerped = (verts + 0.5 * (ta + tb)) @ ref.up.T
        source = ref.at(0.5 * (pos0 + pos1))[0]  # the source motion at that time
        e_slerp = np.linalg.norm(got - slerped[index], axis=1).max()
        e_source = np.linalg.norm(got - source[index], axis=1).max()
        e_keys = np.linalg.norm(slerped - source, axis=1).max()
        nearest = ref.at(np.round(0.5 * (pos0 + pos1)))[0]
        e_near = np.linalg.norm(got - nearest[index], axis=1).max()
        print("resample %s %s %d frame %.1f source_frame %.2f blender_vs_slerped_keys_m %.3e "
              "blender_vs_source_m %.3e blender_vs_nearest_source_frame_m %.3e slerped_keys_vs_source_m %.3e"
              % (ctx["fmt"], ctx["label"], ctx["m"], i + 0.5, 0.5 * (pos0 + pos1), e_slerp, e_source,
                 e_near, e_keys))


def widen_sliders(mesh_obj):
    """What a non-clamping importer would give: slider ranges opened to [-10, 10]."""
    for kb in mesh_obj.data.shape_keys.key_blocks:
        kb.slider_min, kb.slider_max = -10.0, 10.0


def main():
    args = parse_args()
    start = time.perf_counter()
    model = model_math.load_model_npz(args.model)
    motion = read_motion(args.motion, args.model)
    fps_out = args.fps or motion["fps"]
    fmt, arm, mesh_obj = import_asset(args.asset, fps_out)
    m = read_max_influences(args.asset)
    ref = Reference(model, motion, model_math.prune(model["weights"], m))
    meta = read_metadata(args.asset)
    ref.shift = np.array(meta.get("origin", {}).get("offset", [0.0, 0.0, 0.0]), dtype=np.float64)
    root_bone = "root_bone" in meta
    if root_bone and fmt == "fbx":
        disconnect_pelvis(arm)
    entries, skin_method = corrective_entries(args.asset)
    rest_weights = {e["target"]: e.get("offset", 0.0) for e in entries}
    index, _ = rt.vertex_map(mesh_obj, ref.v_shaped + ref.shift, rt.rest_positions(mesh_obj, rest_weights))
    # The skin as the file carries it (optimized weights are fitted, not a truncation).
    got_weights = rt.file_weights(mesh_obj, ref.names, index, len(ref.v_shaped),
                                  extra=("root",) if root_bone else ())
    ref.weights = rt.check_weights(got_weights, m, skin_method, model, None)
    ref.model = dict(model, posedirs=file_posedirs(mesh_obj, entries, model, index, got_weights))
    ratio = motion["fps"] / fps_out  # source frames per output frame
    count = int(np.floor((motion["frames"] - 1) / ratio + 1e-9)) + 1
    ctx = {"fmt": fmt, "arm": arm, "mesh": mesh_obj, "ref": ref, "index": index, "m": m,
           "entries": entries, "root_bone": root_bone,
           "label": args.label or os.path.splitext(os.path.basename(args.model))[0],
           "offset": 1 if fmt == "fbx" else 0}  # Blender's FBX importer starts at frame 1
    frames = sorted({0, count // 2, count - 1})
    if args.check_floor:
        rt.check(meta.get("origin", {}).get("mode") == "floor", "--check-floor: the metadata's origin is %s"
                 % meta.get("origin"))
        check_floor(ref, ratio, count)
    worst = max(check_frame(ctx, i, i * ratio, args.tol, "") for i in frames)
    seconds = time.perf_counter() - start
    # The same frames with the slider ranges opened: isolates importer clamping
    # from everything else the file carries (still asserted).
    widen_sliders(mesh_obj)
    widened = max(check_frame(ctx, i, i * ratio, args.tol, ":widened") for i in frames)
    if args.subframe_report:  # after widening: measures interpolation, not clamping
        subframe_report(ctx, ratio, count)
    print("blender_time_s %s %s %d %.2f max_err_m %.3e widened_max_err_m %.3e frames %s of %d"
          % (fmt, ctx["label"], m, seconds, worst, widened, frames, count))
    harness.finish()


def read_max_influences(asset):
    """M from the sidecar written next to the asset (docs/file-contract.md metadata)."""
    import json
    with open(asset + ".smpl.json", encoding="utf-8") as fh:
        return int(json.load(fh)["max_influences"])


def read_metadata(asset):
    """The sidecar written next to the asset (docs/file-contract.md metadata)."""
    import json
    with open(asset + ".smpl.json", encoding="utf-8") as fh:
        return json.load(fh)


if __name__ == "__main__":
    harness.run(main)
