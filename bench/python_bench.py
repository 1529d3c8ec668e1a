#!/usr/bin/python3
"""The Python module against the tools Python users have today, in one process and one run
(not a timed test: a benchmark; docs/python.md "Speed" quotes its output).

1. model.forward on FRAMES frames of a full-size SMPL-X (10475 vertices, 55 joints, 486 pose
   features; the stand-in of tools/bench/make_standin.py --smplx: the release's array shapes,
   random values) against smplx-style LBS on torch in the same process: the `smplx` package's
   lbs() when it is importable (or --smplx-checkout DIR, a checkout of github.com/vchoutas/smplx),
   else `torch_lbs` below, a line-for-line port of vchoutas/smplx smplx/lbs.py lbs() (commit
   1265df7b: blend_shapes, vertices2joints, batch_rodrigues, batch_rigid_transform, the skinning
   matmuls), float32 on the CPU on every core (torch.set_num_threads: model.forward uses every
   core too), BATCH frames per call, no grad; the two are timed in turn, best of REPEAT.
   Both produce (T,V,3) vertices and (T,K,3) joints in float32; the best of REPEAT runs.
2. se.export against the smpl-export process on the same request (the stand-in and its motion,
   --frames 0:EXPORT_FRAMES, GLB): the CLI's whole-process wall time vs se.load_model +
   se.export (the same work: read the model, read, bake, write) and vs se.export alone on a
   loaded model; the bytes are checked equal.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py --exe build/cli/smpl-export
        [--frames 1000] [--batch 1000] [--export-frames 1000] [--repeat 3] [--smplx-checkout DIR]
Prints one line per row and the ratios (>1: smpl_export is faster / slower as named).
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import torch

HERE = os.path.dirname(os.path.abspath(__file__))


# --- smplx's lbs(), ported from vchoutas/smplx smplx/lbs.py (same operations, same order) ---
def batch_rodrigues(rot_vecs, epsilon=1e-8):
    batch_size = rot_vecs.shape[0]
    device, dtype = rot_vecs.device, rot_vecs.dtype
    angle = torch.norm(rot_vecs + 1e-8, dim=1, keepdim=True)
    rot_dir = rot_vecs / angle
    cos = torch.unsqueeze(torch.cos(angle), dim=1)
    sin = torch.unsqueeze(torch.sin(angle), dim=1)
    rx, ry, rz = torch.split(rot_dir, 1, dim=1)
    zeros = torch.zeros((batch_size, 1), dtype=dtype, device=device)
    K = torch.cat([zeros, -rz, ry, rz, zeros, -rx, -ry, rx, zeros], dim=1).view((batch_size, 3, 3))
    ident = torch.eye(3, dtype=dtype, device=device).unsqueeze(dim=0)
    return ident + sin * K + (1 - cos) * torch.bmm(K, K)


def transform_mat(R, t):
    F = torch.nn.functional
    return torch.cat([F.pad(R, [0, 0, 0, 1]), F.pad(t, [0, 0, 0, 1], value=1)], dim=2)


def batch_rigid_transform(rot_mats, joints, parents, dtype=torch.float32):
    joints = torch.unsqueeze(joints, dim=-1)
    rel_joints = joints.clone()
    rel_joints[:, 1:] -= joints[:, parents[1:]]
    transforms_mat = transform_mat(rot_mats.reshape(-1, 3, 3),
                                   rel_joints.reshape(-1, 3, 1)).reshape(-1, joints.shape[1], 4, 4)
    transform_chain = [transforms_mat[:, 0]]
    for i in range(1, parents.shape[0]):
        transform_chain.append(torch.matmul(transform_chain[parents[i]], transforms_mat[:, i]))
    transforms = torch.stack(transform_chain, dim=1)
    posed_joints = transforms[:, :, :3, 3]
    joints_homogen = torch.nn.functional.pad(joints, [0, 0, 0, 1])
    rel_transforms = transforms - torch.nn.functional.pad(
        torch.matmul(transforms, joints_homogen), [3, 0, 0, 0, 0, 0, 0, 0])
    return posed_joints, rel_transforms


def torch_lbs(betas, pose, v_template, shapedirs, posedirs, J_regressor, parents, lbs_weights):
    batch_size = max(betas.shape[0], pose.shape[0])
    device, dtype = betas.device, betas.dtype
    v_shaped = v_template + torch.einsum("bl,mkl->bmk", [betas, shapedirs])
    J = torch.einsum("bik,ji->bjk", [v_shaped, J_regressor])
    ident = torch.eye(3, dtype=dtype, device=device)
    rot_mats = batch_rodrigues(pose.view(-1, 3)).view([batch_size, -1, 3, 3])
    pose_feature = (rot_mats[:, 1:, :, :] - ident).view([batch_size, -1])
    pose_offsets = torch.matmul(pose_feature, posedirs).view(batch_size, -1, 3)
    v_posed = pose_offsets + v_shaped
    J_transformed, A = batch_rigid_transform(rot_mats, J, parents, dtype=dtype)
    W = lbs_weights.unsqueeze(dim=0).expand([batch_size, -1, -1])
    num_joints = J_regressor.shape[0]
    T = torch.matmul(W, A.view(batch_size, num_joints, 16)).view(batch_size, -1, 4, 4)
    homogen_coord = torch.ones([batch_size, v_posed.shape[1], 1], dtype=dtype, device=device)
    v_posed_homo = torch.cat([v_posed, homogen_coord], dim=2)
    v_homo = torch.matmul(T, torch.unsqueeze(v_posed_homo, dim=-1))
    return v_homo[:, :, :3, 0], J_transformed


def lbs_function(checkout):
    """smplx's own lbs() when importable, else the port above."""
    if checkout:
        sys.path.insert(0, checkout)
    try:
        from smplx.lbs import lbs
        return lbs, "smplx.lbs.lbs (%s)" % os.path.dirname(sys.modules["smplx.lbs"].__file__)
    except ImportError:
        return torch_lbs, "torch_lbs (port of vchoutas/smplx smplx/lbs.py lbs())"


def best_of(repeat, *works):
    """The best wall time of each of `works` over `repeat` rounds, run in turn within a round so
    that a machine shared with other work loads both sides alike."""
    best = [None] * len(works)
    for _ in range(repeat):
        for i, work in enumerate(works):
            start = time.perf_counter()
            work()
            seconds = time.perf_counter() - start
            best[i] = seconds if best[i] is None else min(best[i], seconds)
    return best


def bench_forward(se, model_path, frames, batch, repeat, checkout):
    data = dict(np.load(model_path))
    model = se.load_model(model_path)
    rng = np.random.default_rng(5)
    k = model.num_joints
    poses = (rng.uniform(-1.0, 1.0, (frames, k, 3)) / np.sqrt(3.0)).astype(np.float32)
    betas = rng.normal(0, 1, 10).astype(np.float32)
    model.forward(betas, poses[:2])  # warm-up (posedirs packed once per model)

    lbs, which = lbs_function(checkout)
    torch.set_num_threads(os.cpu_count() or 1)  # as many as model.forward uses (every core)
    n = data["v_template"].shape[0]
    kintree = data["kintree_table"].astype(np.int64)
    parents = torch.tensor([-1] + list(kintree[0, 1:]), dtype=torch.long)
    f32 = dict(dtype=torch.float32)
    v_template = torch.tensor(data["v_template"], **f32)
    shapedirs = torch.tensor(data["shapedirs"][:, :, :10], **f32)
    posedirs = torch.tensor(data["posedirs"].reshape(n * 3, -1).T, **f32)  # as smplx.SMPL stores it
    j_regressor = torch.tensor(data["J_regressor"], **f32)
    weights = torch.tensor(data["weights"], **f32)
    tposes = torch.from_numpy(poses.reshape(frames, -1))
    tbetas = torch.from_numpy(betas).expand(batch, -1)

    def run_torch():
        with torch.no_grad():
            for b in range(0, frames, batch):
                p = tposes[b:b + batch]
                lbs(tbetas[:p.shape[0]], p, v_template, shapedirs, posedirs, j_regressor, parents, weights)

    run_torch()  # warm-up
    ours, theirs = best_of(repeat, lambda: model.forward(betas, poses), run_torch)
    with torch.no_grad():  # same vertices (float32 both: within float rounding)
        v_t, _ = lbs(tbetas[:4], tposes[:4], v_template, shapedirs, posedirs, j_regressor, parents, weights)
    v_o, _ = model.forward(betas, poses[:4])
    agree = float(np.abs(v_t.numpy() - v_o).max())
    print(f"forward {frames} frames SMPL-X: smpl_export {ours * 1e3:.1f} ms, {which} "
          f"{theirs * 1e3:.1f} ms (batch {batch}, torch {torch.__version__}, "
          f"{torch.get_num_threads()} threads); max |difference| {agree:.2e} m")
    print(f"RATIO forward: smpl_export is {theirs / ours:.1f}x faster than smplx-style torch LBS")


def bench_export(se, exe, model_path, motion_path, frames, repeat, work):
    out = os.path.join(work, "cli.glb")
    args = [exe, "--model", model_path, "--motion", motion_path, "--frames", f"0:{frames}",
            "--out", out, "--quiet"]
    subprocess.run(args, check=True)  # warm-up (page cache)
    expected = open(out, "rb").read()
    got = []
    model = se.load_model(model_path)
    cli, cold, warm = best_of(
        repeat, lambda: subprocess.run(args, check=True),
        lambda: got.append(se.export(se.load_model(model_path), motion=motion_path, frames=f"0:{frames}")),
        lambda: se.export(model, motion=motion_path, frames=f"0:{frames}"))
    assert got[-1] == expected, "se.export and the CLI wrote different bytes"
    print(f"export {frames} frames SMPL-X GLB ({len(expected) / 1e6:.1f} MB): CLI process "
          f"{cli * 1e3:.0f} ms, se.load_model + se.export {cold * 1e3:.0f} ms, se.export on a "
          f"loaded model {warm * 1e3:.0f} ms; same bytes")
    print(f"RATIO export: (load_model + export) / CLI = {cold / cli:.3f}; export / CLI = {warm / cli:.3f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", required=True, help="smpl-export of the same build")
    parser.add_argument("--frames", type=int, default=1000)
    parser.add_argument("--batch", type=int, default=1000, help="frames per torch lbs() call")
    parser.add_argument("--export-frames", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--smplx-checkout", default=None)
    parser.add_argument("--work", default=None, help="folder for the stand-in (default: a temp dir)")
    a = parser.parse_args()
    import smpl_export as se
    work = a.work or tempfile.mkdtemp(prefix="smpl_py_bench_")
    model_path = os.path.join(work, "standin_smplx.npz")
    motion_path = os.path.join(work, "standin_smplx_motion.npz")
    if not os.path.exists(model_path):
        subprocess.run([sys.executable, os.path.join(HERE, "..", "tools", "bench", "make_standin.py"),
                        "--smplx", work], check=True)
    print(f"machine: {os.cpu_count()} cores; load average {os.getloadavg()[0]:.1f}")
    bench_forward(se, model_path, a.frames, a.batch, a.repeat, a.smplx_checkout)
    bench_export(se, a.exe, model_path, motion_path, a.export_frames, a.repeat, work)


if __name__ == "__main__":
    main()
