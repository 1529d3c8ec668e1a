"""Headless-Blender round trip: import an exported asset, check it against the
model read with numpy, pose it through bone rotations only, drive the
correctives with the add-on and compare the evaluated mesh with the reference
forward pass.

  blender -b --factory-startup --python blender_roundtrip.py -- \
      --asset body.glb --addon-dir blender/ [--model model.npz] \
      [--reference PREFIX] [--betas 0.5,-1] [--poses 20] [--seed 1] \
      [--label NAME] [--tol 1e-5] [--metadata-betas]

--model: the model .npz, read here with numpy (independent of our C++ code);
omitted for the builtin body, whose arrays then come from the reference dump.
--reference: smpl-reference output (poses + C++ forward pass, pruned and
unpruned weights); without it, poses are drawn here and numpy is the reference.
Prints one line per case: "format layout M max_err_m mean_err_m".
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
import model_math  # noqa: E402

# Model axes (+Y up) -> Blender world (+Z up): both importers turn +90 deg about X.
MODEL_TO_WORLD = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])
check = harness.check  # rt.check / rt.failures: the other scripts use these names
failures = harness.failures


def parse_args():
    argv = harness.script_args()
    ap = argparse.ArgumentParser()
    ap.add_argument("--asset", required=True)
    ap.add_argument("--addon-dir", required=True)
    ap.add_argument("--model")
    ap.add_argument("--reference")
    ap.add_argument("--betas", default="")
    ap.add_argument("--metadata-betas", action="store_true",
                    help="take betas from the asset's metadata (synthetic assets)")
    ap.add_argument("--poses", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--label", default="")
    ap.add_argument("--skeleton-names", choices=("mixamo", "ue5"),
                    help="the export's --skeleton-names: the bones are found by the metadata's "
                         "bone_names (checked to differ from the joint names), the add-on binds through them")
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--delta-tol", type=float, default=1e-6,
                    help="max |decoded morph delta - posedirs| (compact encodings add error)")
    ap.add_argument("--import-option", action="append", default=[],
                    help="KEY=VALUE passed to Blender's importer (e.g. automatic_bone_orientation=True)")
    return ap.parse_args(argv)


def import_options(pairs):
    """["automatic_bone_orientation=True", "bone_heuristic=TEMPERANCE"] -> kwargs."""
    out = {}
    for pair in pairs:
        key, value = pair.split("=", 1)
        out[key] = {"True": True, "False": False}.get(value, value)
    return out


def import_asset(path, options=()):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    ext = os.path.splitext(path)[1].lower()
    kwargs = import_options(options)
    if ext in (".glb", ".gltf"):
        bpy.ops.import_scene.gltf(filepath=path, **kwargs)
    elif ext == ".fbx":
        bpy.ops.import_scene.fbx(filepath=path, **kwargs)
    else:
        raise SystemExit("blender_roundtrip: unknown asset type: " + path)
    arms = [o for o in bpy.data.objects if o.type == "ARMATURE"]
    meshes = [o for o in bpy.data.objects if o.type == "MESH" and o.data.shape_keys]
    if len(arms) != 1 or len(meshes) != 1:
        raise SystemExit("%s: expected 1 armature and 1 mesh with shape keys, found %d and %d"
                         % (path, len(arms), len(meshes)))
    return arms[0], meshes[0]


def load_truth(args):
    """Model arrays + subject from numpy (npz) or from the reference dump (builtin)."""
    header, ref = model_math.read_reference(args.reference) if args.reference else (None, {})
    if args.model:
        model = model_math.load_model_npz(args.model)
    else:
        if "posedirs" not in ref:
            raise SystemExit("blender_roundtrip: --model or a reference with --dump-model needed")
        model = {k: ref[k] for k in ("posedirs", "weights")}
        model["parents"] = header["parents"]
    betas = [float(b) for b in args.betas.split(",") if b.strip()]
    if args.metadata_betas:
        from smpl_correctives import correctives
        betas = (correctives.metadata_from_file(args.asset) or {}).get("betas", [])
    if args.model:
        v_shaped, joints = model_math.shape(model, betas)
    else:
        v_shaped, joints = ref["v_shaped"], ref["rest_joints"]
    return model, v_shaped, joints, header, ref


def world_to_model(points_world):
    return points_world @ MODEL_TO_WORLD  # row vectors: (C^T p)^T = p^T C


def basis_positions(mesh_obj):
    """Rest (basis) vertex positions in model axes, metres."""
    n = len(mesh_obj.data.vertices)
    co = np.empty(n * 3, dtype=np.float32)
    mesh_obj.data.shape_keys.reference_key.data.foreach_get("co", co)
    return world_to_model(to_world(mesh_obj, co.reshape(n, 3)))


def to_world(obj, points):
    m = np.array(obj.matrix_world, dtype=np.float64)
    return points.astype(np.float64) @ m[:3, :3].T + m[:3, 3]


def corrective_encoding(asset, count):
    """(scale, offset) per corrective feature from the file's metadata: weight = scale * f + offset."""
    import json
    with open(asset + ".smpl.json") as fh:  # the CLI's sidecar: same content as the file's metadata
        meta = json.load(fh)
    scale, offset = np.ones(count), np.zeros(count)
    for c in meta.get("correctives", []):
        scale[c["feature"]], offset[c["feature"]] = c.get("scale", 1.0), c.get("offset", 0.0)
    return scale, offset


def rest_positions(mesh_obj, offsets):
    """The rest mesh in model axes: the basis plus every shape key at its rest
    weight (non-zero for the unit corrective encoding, whose basis is shifted).
    `offsets` maps shape key name -> rest weight."""
    keys = mesh_obj.data.shape_keys
    n = len(mesh_obj.data.vertices)
    basis = np.empty(n * 3, dtype=np.float32)
    keys.reference_key.data.foreach_get("co", basis)
    rest = basis.astype(np.float64)
    co = np.empty(n * 3, dtype=np.float32)
    for kb in keys.key_blocks[1:]:
        w = offsets.get(kb.name, offsets.get(kb.name.rsplit("|", 1)[-1], 0.0))
        if w:
            kb.data.foreach_get("co", co)
            rest += w * (co.astype(np.float64) - basis)
    return world_to_model(to_world(mesh_obj, rest.reshape(n, 3)))


def vertex_map(mesh_obj, v_shaped, rest=None):
    """Model vertex index of every Blender vertex, matched by rest position
    (`rest` defaults to the basis positions)."""
    from mathutils import Vector
    from mathutils.kdtree import KDTree
    tree = KDTree(len(v_shaped))
    for i, p in enumerate(v_shaped):
        tree.insert(Vector(p), i)
    tree.balance()
    if rest is None:
        rest = basis_positions(mesh_obj)
    found = [tree.find(Vector(p)) for p in rest]
    worst = max(d for _, _, d in found)
    check(worst <= 1e-5, "rest mesh differs from v_shaped by %.3g m" % worst)
    index = np.array([i for _, i, _ in found])
    check(len(set(index)) == len(v_shaped), "%d of %d model vertices present"
          % (len(set(index)), len(v_shaped)))
    return index, rest


def check_metadata(asset, names, parents):
    from smpl_correctives import correctives
    meta = correctives.metadata_from_file(asset)
    check(meta is not None, "%s: no SMPL metadata (asset.extras.smpl or sidecar)" % asset)
    if meta is None:
        return {}
    check(meta.get("joint_names") == names, "metadata joint_names differ from the canonical names")
    check(meta.get("parents") == parents, "metadata parents differ from kintree_table")
    layout = [(c.get("feature"), c.get("target")) for c in meta.get("correctives", [])]
    expect = list(enumerate(model_math.target_names(names)))
    check(layout == expect, "metadata corrective layout is not feature n -> pose_<joint>_<rc>")
    return meta


def check_skeleton(arm, names, parents):
    bones = arm.data.bones
    for k, name in enumerate(names):
        bone = bones.get(name)
        check(bone is not None, "bone %s missing" % name)
        if bone is None:
            continue
        want = names[parents[k]] if parents[k] >= 0 else None
        got = bone.parent.name if bone.parent else None
        check(got == want, "bone %s: parent %s, expected %s" % (name, got, want))
    check(len(bones) == len(names), "%d bones, expected %d" % (len(bones), len(names)))


def file_weights(mesh_obj, names, index, num_vertices, extra=()):
    """The skin weights as Blender imported them from the file: (N,K) per model vertex.
    `extra`: joints of the file that are not model joints (--root-bone's root), which
    must carry no weight."""
    group_joint = {g.index: names.index(g.name) for g in mesh_obj.vertex_groups if g.name in names}
    extra_groups = {g.index for g in mesh_obj.vertex_groups if g.name in extra}
    check(len(group_joint) + len(extra_groups) == len(mesh_obj.vertex_groups),
          "vertex groups not named after joints")
    check(not any(g.group in extra_groups and g.weight > 0 for v in mesh_obj.data.vertices for g in v.groups),
          "a joint that is not a model joint (%s) carries skin weight" % ", ".join(extra))
    got = np.zeros((len(index), len(names)))
    for v in mesh_obj.data.vertices:
        for g in v.groups:
            if g.group in group_joint:
                got[v.index, group_joint[g.group]] = g.weight
    model_w = np.zeros((num_vertices, len(names)))
    model_w[index] = got
    return model_w


def check_weights(got, m, method, model, ref):
    """The file's weights: a skin of at most M influences summing to 1; truncated
    ones equal numpy's pruning, optimized ones smpl-reference's fit (skin_weights)."""
    check(got.min() >= 0 and int((got > 0).sum(1).max()) <= m, "skin: negative weights or more than %d influences" % m)
    check(np.abs(got.sum(1) - 1).max() <= 2e-6, "skin weights do not sum to 1")
    expected = model_math.prune(model["weights"], m) if method == "truncated" else (ref or {}).get("skin_weights")
    if expected is not None:
        err = np.abs(got - expected).max()
        check(err <= 2e-6, "skin weights differ from the %s reference weights by %.3g" % (method, err))
    return expected if expected is not None else got


def check_fit_gain(model, file_model, v_shaped, rest_joints, poses, got, m):
    """Optimized weights and the correctives read from the file: numpy's error
    against the model with all its weights, over these (held-out) poses, is
    below numpy's own truncation's (the model's posedirs)."""
    full = numpy_reference(model, v_shaped, rest_joints, poses, model["weights"])[0]
    errors = {}
    for label, mdl, w in (("file", file_model, got), ("file_skin", model, got),
                          ("truncated", model, model_math.prune(model["weights"], m))):
        dist = np.linalg.norm(numpy_reference(mdl, v_shaped, rest_joints, poses, w)[0] - full, axis=2)
        errors[label] = (dist.mean(), dist.max())
    print("skin_fit m=%d file mean %.4g max %.4g; file skin with posedirs mean %.4g max %.4g; "
          "truncated mean %.4g max %.4g" % ((m,) + errors["file"] + errors["file_skin"]
                                            + errors["truncated"]))
    check(errors["file"][0] < errors["truncated"][0], "optimized weights are not better than truncation")


def key_lookup(mesh_obj):
    """Target name -> key block; importers may add prefixes ('Key|...')."""
    table = {}
    for kb in mesh_obj.data.shape_keys.key_blocks:
        table[kb.name] = kb
        table.setdefault(kb.name.rsplit("|", 1)[-1], kb)
    return table


def check_morph_targets(mesh_obj, names, model, index, scale, tol, got_weights):
    """Every pose_* key's delta, decoded with the file's weight mapping
    (delta * scale: weight = scale * f + offset), equals its posedirs column
    at every vertex whose skin influences were not cut (the file's skin keeps
    all of the model's non-zero weights); at the others --corrective-refit
    (docs/file-contract.md) may have refitted it. Returns the file's deltas
    as (N,3,P) posedirs in model vertex order: the reference poses the file's
    skin with them, as it takes the file's weights (where they equal posedirs,
    posedirs' exact values, so the comparisons with smpl-reference stay at
    double precision there)."""
    posedirs = model["posedirs"]
    keys = key_lookup(mesh_obj)
    n = len(mesh_obj.data.vertices)
    basis = np.empty(n * 3, dtype=np.float32)
    mesh_obj.data.shape_keys.reference_key.data.foreach_get("co", basis)
    linear = np.array(mesh_obj.matrix_world, dtype=np.float64)[:3, :3]
    co = np.empty(n * 3, dtype=np.float32)
    cut = (model["weights"] > 0).sum(1) > (got_weights > 0).sum(1)  # per model vertex
    kept = ~cut[index]
    file_posedirs = posedirs.astype(np.float64).copy()
    worst, refit, missing = 0.0, 0.0, []
    for f, target in enumerate(model_math.target_names(names)):
        kb = keys.get(target)
        if kb is None:
            missing.append(target)
            continue
        kb.data.foreach_get("co", co)
        delta = scale[f] * world_to_model((co.astype(np.float64) - basis).reshape(n, 3) @ linear.T)
        file_posedirs[index[~kept], :, f] = delta[~kept]  # elsewhere checked equal below
        diff = np.abs(delta - posedirs[index, :, f])
        worst = max(worst, diff[kept].max(initial=0.0))
        refit = max(refit, diff[~kept].max(initial=0.0))
    check(not missing, "%d morph targets missing, e.g. %s" % (len(missing), missing[:3]))
    print("morph_delta_err_m %.3e (refitted vertices: %d, max change %.3e m)"
          % (worst, int(cut.sum()), refit))
    check(worst <= tol, "morph target deltas differ from posedirs by %.3g" % worst)
    return file_posedirs


def check_axes(arm, correctives):
    """The add-on's C (model -> armature axes) against this script's own."""
    arm_rot = np.array(arm.matrix_world.to_3x3().normalized(), dtype=np.float64)
    axes = np.array(arm[correctives.PROP_AXES], dtype=np.float64).reshape(3, 3)
    err = np.abs(axes - arm_rot.T @ MODEL_TO_WORLD).max()
    check(err <= 1e-6, "add-on's model->armature axes off by %.3g" % err)


def pose_armature(arm, names, rotations):
    """Model-space local rotations R_k -> pose bone rotations.

    Bone k's armature-space rotation change must be C G_k C^-1 (G_k the world
    rotation); with Blender's parenting this makes the bone's basis rotation
    B_k^-1 (C R_k C^-1) B_k, B_k the rest (matrix_local) rotation.
    """
    from mathutils import Matrix
    arm_rot = np.array(arm.matrix_world.to_3x3().normalized(), dtype=np.float64)
    c = arm_rot.T @ MODEL_TO_WORLD
    for k, name in enumerate(names):
        pb = arm.pose.bones[name]
        rest = np.array(arm.data.bones[name].matrix_local.to_3x3().normalized(), dtype=np.float64)
        basis = rest.T @ (c @ rotations[k] @ c.T) @ rest
        pb.rotation_mode = "QUATERNION"
        pb.rotation_quaternion = Matrix(basis.tolist()).to_quaternion()
        pb.location = (0.0, 0.0, 0.0)
        pb.scale = (1.0, 1.0, 1.0)


def posed_joints(arm, names):
    heads = np.array([arm.pose.bones[n].head for n in names], dtype=np.float64)
    return world_to_model(to_world(arm, heads))


def evaluated_vertices(mesh_obj):
    dg = bpy.context.evaluated_depsgraph_get()
    ev = mesh_obj.evaluated_get(dg)
    me = ev.to_mesh()
    co = np.empty(len(me.vertices) * 3, dtype=np.float32)
    me.vertices.foreach_get("co", co)
    out = world_to_model(to_world(ev, co.reshape(-1, 3)))
    ev.to_mesh_clear()
    return out


def draw_poses(args, ref, k):
    if "poses" in ref:
        return ref["poses"]
    rng = np.random.default_rng(args.seed)
    return rng.uniform(-0.6, 0.6, (args.poses, k, 3))


def run_poses(arm, mesh_obj, names, poses, index):
    """Pose, drive the correctives, evaluate: (P,V,3) vertices, (P,K,3) joints, apply() seconds."""
    from smpl_correctives import correctives
    verts, joints, cost = [], [], []
    for pose in poses:
        pose_armature(arm, names, model_math.rodrigues(pose))
        bpy.context.view_layer.update()
        start = time.perf_counter()
        correctives.apply(arm, mesh_obj)
        cost.append(time.perf_counter() - start)
        bpy.context.view_layer.update()
        joints.append(posed_joints(arm, names))
        verts.append(evaluated_vertices(mesh_obj))
    return np.array(verts), np.array(joints), np.array(cost)


def numpy_reference(model, v_shaped, rest_joints, poses, weights):
    out = [model_math.forward(model, v_shaped, rest_joints, p, weights) for p in poses]
    return (np.array([o[0] for o in out]), np.array([o[1] for o in out]),
            np.array([o[2] for o in out]))


def compare_reference(ref, name, numpy_value, tol=1e-9):
    """smpl-reference (C++) against numpy: both double precision (tol 1e-9 m),
    unless numpy's side holds values read from the file (refitted deltas)."""
    if name in ref:
        err = np.abs(ref[name] - numpy_value).max()
        print("reference-vs-numpy %s max %.3g" % (name, err))
        check(err <= tol, "smpl-reference %s differs from numpy by %.3g" % (name, err))


def main():
    args = parse_args()
    sys.path.insert(0, os.path.abspath(args.addon_dir))
    from smpl_correctives import correctives
    model, v_shaped, rest_joints, header, ref = load_truth(args)
    k = len(model["parents"])
    names, parents = model_math.joint_names(k), list(model["parents"])
    arm, mesh_obj = import_asset(args.asset, args.import_option)
    meta = check_metadata(args.asset, names, parents)
    m = int(meta.get("max_influences", header["max_influences"] if header else 4))
    bones = names  # the bone of each joint: the joint's name, or with --skeleton-names bone_names
    if args.skeleton_names:
        bones = list(meta.get("bone_names") or [])
        check(meta.get("skeleton_names") == args.skeleton_names and len(bones) == len(names),
              "metadata skeleton_names %r / %d bone_names, expected %r / %d"
              % (meta.get("skeleton_names"), len(bones), args.skeleton_names, len(names)))
        check(sum(b != n for b, n in zip(bones, names)) >= 20, "bone_names hardly differ from joint_names")
        if len(bones) != len(names):
            bones = names
    check_skeleton(arm, bones, parents)
    targets = model_math.target_names(names)
    scale, offset = corrective_encoding(args.asset, len(targets))
    rest = rest_positions(mesh_obj, dict(zip(targets, offset))) if offset.any() else None
    index, _ = vertex_map(mesh_obj, v_shaped, rest)
    method = meta.get("skin_weights", "truncated")
    got_weights = file_weights(mesh_obj, bones, index, len(v_shaped))
    pruned = check_weights(got_weights, m, method, model, ref)
    file_model = dict(model, posedirs=check_morph_targets(
        mesh_obj, names, model, index, scale, args.delta_tol, got_weights))
    correctives.bind(arm, mesh_obj, source_path=args.asset)
    check_axes(arm, correctives)

    poses = draw_poses(args, ref, k)
    got, got_joints, cost = run_poses(arm, mesh_obj, bones, poses, index)
    want, want_joints, features = numpy_reference(file_model, v_shaped, rest_joints, poses, pruned)
    want_full = numpy_reference(model, v_shaped, rest_joints, poses, model["weights"])[0]
    compare_reference(ref, "features", features)
    compare_reference(ref, "joints", want_joints)
    # Refitted deltas come from the file: float32, read back through Blender's
    # float32 key coordinates (each within --delta-tol), summed over a vertex's
    # features with |f| <= 2: 20 x delta-tol bounds that, far below the mm
    # the refit changes.
    refitted = bool(((model["weights"] > 0).sum(1) > (got_weights > 0).sum(1)).any())
    compare_reference(ref, "vertices_pruned", want, 20 * args.delta_tol if refitted else 1e-9)
    compare_reference(ref, "vertices_full", want_full)
    lossy = int((model["weights"] > 0).sum(1).max()) > m
    if method == "optimized" and lossy:
        check_fit_gain(model, file_model, v_shaped, rest_joints, poses, got_weights, m)
    err = np.abs(got_joints - want_joints).max()
    check(err <= args.tol, "posed joints differ by %.3g m: bone rotation conversion is wrong" % err)

    fmt = os.path.splitext(args.asset)[1].lstrip(".").lower()
    label = args.label or os.path.basename(args.asset)
    target = ref.get("vertices_pruned", want)
    lossless = int((model["weights"] > 0).sum(1).max()) <= m  # pruning to M dropped nothing
    for layout, reference in (("pruned", target), ("unpruned", ref.get("vertices_full", want_full))):
        dist = np.linalg.norm(got - reference[:, index], axis=2)
        print("%s %s:%s %d %.3e %.3e" % (fmt, label, layout, m, dist.max(), dist.mean()))
        if layout == "pruned" or lossless:
            check(dist.max() <= args.tol, "%s %s: max vertex error %.3g m > %g"
                  % (label, layout, dist.max(), args.tol))
    print("apply_cost K=%d keys=%d median_ms %.3f mean_ms %.3f max_ms %.3f" % (
        k, len(model_math.target_names(names)), 1e3 * np.median(cost), 1e3 * cost.mean(), 1e3 * cost.max()))
    harness.finish()


if __name__ == "__main__":
    harness.run(main)
