#!/usr/bin/python3
"""The model authors' PyTorch forward pass (smplx.SMPL), for smpl-bench --compare.

Run: /usr/bin/python3 smplx_forward_time.py SMPLX_CHECKOUT MODEL.npz FRAMES BATCH
SMPLX_CHECKOUT is a checkout of github.com/vchoutas/smplx (not part of this
repository); MODEL.npz holds the model's arrays (smpl-bench writes the same
stand-in as .pkl and .npz; the .npz is read here so no chumpy is needed).
Poses: FRAMES seeded random axis-angle vectors (|angle| <= 1 rad per joint),
evaluated BATCH at a time with torch on one thread (float32, CPU), as smplx
does. Time is process CPU time (one thread: robust to other load on the
machine). Prints one line: SMPLX_FORWARD <CPU ms per frame> <torch version> <threads>
"""
import sys
import time

import numpy as np


def main():
    if len(sys.argv) != 5:
        raise SystemExit("usage: smplx_forward_time.py SMPLX_CHECKOUT MODEL.npz FRAMES BATCH")
    checkout, model_path, frames, batch = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    sys.path.insert(0, checkout)
    import torch
    import smplx
    from smplx.utils import Struct

    torch.set_num_threads(1)
    data = dict(np.load(model_path))
    model = smplx.SMPL(model_path, data_struct=Struct(**data), batch_size=batch, num_betas=10)
    rng = np.random.default_rng(5)
    poses = torch.tensor(rng.uniform(-1.0, 1.0, size=(frames, 72)) / np.sqrt(3.0), dtype=torch.float32)
    betas = torch.zeros((batch, 10))
    with torch.no_grad():
        model(betas=betas, global_orient=poses[:batch, :3], body_pose=poses[:batch, 3:])  # warm-up
        best = None
        for _ in range(3):  # best of 3 passes over all frames
            start = time.process_time()
            for b in range(0, frames - batch + 1, batch):
                model(betas=betas, global_orient=poses[b:b + batch, :3], body_pose=poses[b:b + batch, 3:])
            seconds = time.process_time() - start
            best = seconds if best is None else min(best, seconds)
    done = (frames // batch) * batch
    print("SMPLX_FORWARD %.4f %s %d" % (1e3 * best / done, torch.__version__, torch.get_num_threads()))


main()
