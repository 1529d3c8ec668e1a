#!/usr/bin/python3
"""Batch throughput: a folder of motions of one subject through batch mode.

Writes, under --work (default: a temporary folder, removed at the end), the
full-size SMPL stand-in (tools/bench/make_standin.py: 6890 vertices, 207 pose
features; random values, timing only) and --motions AMASS-style SMPL motions
of one subject (poses (T, 72), trans, the same betas, mocap_framerate), each
--seconds long at --fps, smooth sines with their own phases. Then runs

    smpl-export --model standin.npz --motion-dir motions --out-dir out --format F

(default options: the skin fitted once and reused, every core), reads its
throughput line (motions per second, time in read / fit / bake / write) and
measures the baseline: the same input files read and the same output bytes
written, each as batch mode writes its files (a temporary file, fsync,
rename). Prints a Markdown table (scripts/record-bench.py records it): the
whole process's wall time and motions per second, the shares of the export
work in read / fit / bake / write, the baseline's time and the ratio of the
two. A benchmark, not a test: it prints, it does not judge.

Usage: bench/batch_bench.py [--exe build/cli/smpl-export] [--motions 100]
       [--seconds 10] [--fps 60] [--format glb] [--work DIR]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np
import scipy.sparse as sp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools", "bench"))
import make_standin  # noqa: E402  (the full-size SMPL stand-in)

THROUGHPUT = re.compile(r"^batch: (\d+) motions? in ([\d.]+) s \(([\d.]+) motions/s\); time in read (\d+)%, "
                        r"fit (\d+)%, bake (\d+)%, write (\d+)%$", re.M)


def write_model(path):
    arrays = {k: (v.toarray() if sp.issparse(v) else v)
              for k, v in make_standin.model().items() if not isinstance(v, str)}
    np.savez(path, **arrays)


def write_motions(folder, count, seconds, fps):
    """`count` motions of one subject (the same betas), each its own phases."""
    os.makedirs(folder, exist_ok=True)
    t = np.arange(int(seconds * fps))[:, None] / fps
    betas = np.linspace(-1.0, 1.0, make_standin.BETAS)
    for i in range(count):
        rng = np.random.default_rng(1000 + i)
        poses = 0.3 * np.sin(t * np.linspace(0.5, 3.0, 72)[None, :] + rng.uniform(0, 6, 72)[None, :])
        trans = np.concatenate([0.5 * np.sin(t), np.zeros_like(t), 0.3 * t], axis=1)
        np.savez(os.path.join(folder, "walk_%03d.npz" % i), poses=poses, trans=trans, betas=betas,
                 mocap_framerate=np.array(float(fps)), gender=np.array("neutral"))


def files_alone(inputs, outputs, folder):
    """Seconds to read every input and write every output's bytes (temporary file, fsync, rename)."""
    contents = []
    for path in outputs:
        with open(path, "rb") as f:
            contents.append((os.path.basename(path), f.read()))
    os.makedirs(folder, exist_ok=True)
    start = time.perf_counter()
    for path in inputs:
        with open(path, "rb") as f:
            f.read()
    for name, data in contents:
        tmp = os.path.join(folder, "." + name + ".tmp")
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.rename(tmp, os.path.join(folder, name))
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(HERE, "..", "build", "cli", "smpl-export"))
    ap.add_argument("--motions", type=int, default=100)
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--fps", type=float, default=60.0)
    ap.add_argument("--format", default="glb")
    ap.add_argument("--work")
    a = ap.parse_args()
    work = a.work or tempfile.mkdtemp(prefix="batch_bench_")
    os.makedirs(work, exist_ok=True)
    try:
        model = os.path.join(work, "standin_smpl.npz")
        if not os.path.exists(model):
            write_model(model)
        motions, out = os.path.join(work, "motions"), os.path.join(work, "out")
        shutil.rmtree(motions, ignore_errors=True)
        shutil.rmtree(out, ignore_errors=True)
        shutil.rmtree(os.path.join(work, "alone"), ignore_errors=True)
        write_motions(motions, a.motions, a.seconds, a.fps)
        cmd = [a.exe, "--model", model, "--motion-dir", motions, "--out-dir", out, "--format", a.format]
        start = time.perf_counter()
        run = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.perf_counter() - start
        if run.returncode != 0:
            sys.exit("batch failed (exit %d): %s" % (run.returncode, run.stderr.strip()[-400:]))
        m = THROUGHPUT.search(run.stdout)
        if not m:
            sys.exit("no throughput line in the batch's output:\n" + run.stdout[-600:])
        inputs = sorted(os.path.join(motions, n) for n in os.listdir(motions))
        outputs = sorted(os.path.join(out, n) for n in os.listdir(out) if not n.startswith("."))
        alone = files_alone(inputs, outputs, os.path.join(work, "alone"))
        exported = [p for p in outputs if not p.endswith(".smpl.json")]  # without the sidecars
        per_motion = sum(os.path.getsize(p) for p in exported) / len(exported)
        print("| batch (%d cores) | motions | frames each | file per motion | whole process | motions/s "
              "| read | fit | bake | write | files alone | batch / files alone |" % os.cpu_count())
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        print("| SMPL stand-in, %s | %d | %d | %.1f MB | %.2f s | %.2f | %s%% | %s%% | %s%% | %s%% "
              "| %.2f s | %.2fx |" % (a.format, a.motions, int(a.seconds * a.fps), per_motion / 1e6,
                                      wall, a.motions / wall, *m.group(4, 5, 6, 7), alone, wall / alone))
    finally:
        if not a.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
