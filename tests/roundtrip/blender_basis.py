"""Headless-Blender round trip of a `--corrective-basis K` export: import it,
check the basis keys against numpy's own SVD of posedirs, pose it through
bone rotations, drive the keys with the add-on (smpl_correctives.apply) and
compare the evaluated mesh with numpy's forward pass
  - with posedirs truncated to numpy's K leading singular vectors (always, --tol),
  - with the full posedirs (printed; checked against --tol when K = P).

  blender -b --factory-startup --python blender_basis.py -- \
      --asset body.glb --addon-dir blender/ --reference PREFIX [--model model.npz] \
      [--betas 0.5,-1] [--label NAME] [--tol 1e-5]
Prints "basis <fmt> <label> K=<k>/<P> truncated max_err_m .. full max_err_m .. mean_err_m ..".
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
    ap.add_argument("--asset", required=True)
    ap.add_argument("--addon-dir", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--model")
    ap.add_argument("--betas", default="")
    ap.add_argument("--label", default="")
    ap.add_argument("--tol", type=float, default=1e-5)
    args = ap.parse_args(harness.script_args())
    args.metadata_betas = False  # what rt.load_truth reads besides these
    return args


def check_layout(meta, names, p):
    """The metadata names K targets pose_basis_<k> and a K x P matrix; no per-feature layout."""
    basis = meta.get("corrective_basis") or {}
    targets = basis.get("targets", [])
    k = len(targets)
    rt.check(k > 0, "metadata has no corrective_basis")
    rt.check(targets == ["pose_basis_%d" % i for i in range(k)], "basis targets not pose_basis_<k>")
    rt.check(meta.get("correctives") == [], "per-feature correctives listed next to the basis")
    rt.check(basis.get("features") == p == 9 * (len(names) - 1), "corrective_basis.features != 9(K-1)")
    matrix = np.asarray(basis.get("matrix", []), dtype=np.float64)
    rt.check(matrix.size == k * p, "matrix has %d numbers, expected %d x %d" % (matrix.size, k, p))
    return (targets, matrix.reshape(k, p), np.asarray(basis["scale"], dtype=np.float64),
            np.asarray(basis["offset"], dtype=np.float64))


def key_deltas(mesh_obj, targets):
    """(K, V, 3) shape key deltas in model axes, Blender vertex order."""
    keys = rt.key_lookup(mesh_obj)
    n = len(mesh_obj.data.vertices)
    basis = np.empty(n * 3, dtype=np.float32)
    mesh_obj.data.shape_keys.reference_key.data.foreach_get("co", basis)
    linear = np.array(mesh_obj.matrix_world, dtype=np.float64)[:3, :3]
    co = np.empty(n * 3, dtype=np.float32)
    out = []
    for t in targets:
        keys[t].data.foreach_get("co", co)
        out.append(rt.world_to_model((co.astype(np.float64) - basis).reshape(n, 3) @ linear.T))
    return np.array(out)


def check_basis(deltas, scale, matrix, truncated, index):
    """File deltas * scale = B with B C = numpy's rank-K posedirs, in metres. (B^T B = I
    is not checked here: Blender stores keys as absolute float32 positions, whose
    rounding, times the large scale of a small component, swamps it; the unit
    tests check it in double.)"""
    b = (deltas * scale[:, None, None]).reshape(len(scale), -1).T  # (3V, K)
    recon = (b @ matrix).reshape(-1, 3, matrix.shape[1])
    err = np.abs(recon - truncated[index]).max()
    print("basis-vs-numpy-svd max %.3g" % err)
    rt.check(err <= 1e-5, "B C differs from numpy's rank-K posedirs by %.3g" % err)


def main():
    args = parse_args()
    sys.path.insert(0, os.path.abspath(args.addon_dir))
    from smpl_correctives import correctives
    model, v_shaped, rest_joints, header, ref = rt.load_truth(args)
    names = model_math.joint_names(len(model["parents"]))
    posedirs = model["posedirs"]
    n, _, p = posedirs.shape
    arm, mesh_obj = rt.import_asset(args.asset)
    meta = correctives.metadata_from_file(args.asset) or {}
    targets, matrix, scale, offset = check_layout(meta, names, p)
    k = len(targets)
    u = np.linalg.svd(posedirs.reshape(3 * n, p), full_matrices=False)[0][:, :k]
    truncated = (u @ (u.T @ posedirs.reshape(3 * n, p))).reshape(n, 3, p)
    rest = rt.rest_positions(mesh_obj, dict(zip(targets, offset)))
    index, _ = rt.vertex_map(mesh_obj, v_shaped, rest)
    check_basis(key_deltas(mesh_obj, targets), scale, matrix, truncated, index)
    bound = correctives.bind(arm, mesh_obj, source_path=args.asset)
    rt.check(bound == k, "bind found %d of %d basis keys" % (bound, k))

    m = int(meta.get("max_influences", 4))
    # The skin as the file carries it (optimized weights are fitted, not a truncation).
    got_weights = rt.file_weights(mesh_obj, names, index, n)
    pruned = rt.check_weights(got_weights, m, meta.get("skin_weights", "truncated"), model, ref)
    poses = ref["poses"]
    got = rt.run_poses(arm, mesh_obj, names, poses, index)[0]
    want_trunc = rt.numpy_reference(dict(model, posedirs=truncated), v_shaped, rest_joints, poses, pruned)[0]
    want_full = rt.numpy_reference(model, v_shaped, rest_joints, poses, pruned)[0]
    trunc = np.linalg.norm(got - want_trunc[:, index], axis=2)
    full = np.linalg.norm(got - want_full[:, index], axis=2)
    fmt = os.path.splitext(args.asset)[1].lstrip(".").lower()
    print("basis %s %s K=%d/%d truncated max_err_m %.3e full max_err_m %.3e mean_err_m %.3e"
          % (fmt, args.label, k, p, trunc.max(), full.max(), full.mean()))
    rt.check(trunc.max() <= args.tol, "vs numpy rank-%d model: max vertex error %.3g m" % (k, trunc.max()))
    if k == p:
        rt.check(full.max() <= args.tol, "K = P: max vertex error %.3g m vs the full model" % full.max())
    harness.finish()


if __name__ == "__main__":
    harness.run(main)
