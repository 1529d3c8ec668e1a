#!/usr/bin/python3
"""Persons and tracks at scale (a benchmark, not a timed test): the smpl-export
process's wall time on
  - one EasyMocap JSON frame of PERSONS persons (`--track longest`: every person
    is decoded and checked for a repeated id, one is exported), and PERSONS / 10;
  - a WHAM results pickle of TRACKS tracks (`--track all`: one GLB per track),
    and TRACKS / 10;
with the ratio of each pair (linear work gives ~10; 100 would be quadratic).
Wall time and the process's CPU time (user + sys, from getrusage) are both
printed: on a loaded machine the wall time of many outputs is mostly waiting,
and the CPU ratio is the one that shows the algorithm.

    /usr/bin/python3 bench/tracks_bench.py --exe build/cli/smpl-export
        --model build/fixtures/models/smpl_small.npz [--persons 100000] [--tracks 1000]
Prints one line per size and one ratio line per case.
"""
import argparse
import json
import os
import resource
import subprocess
import tempfile
import time

import joblib
import numpy as np


def easymocap(path, persons):
    """One EasyMocap frame: a list of {id, Rh (1,3), Th (1,3), poses (1,72), shapes (1,10)}."""
    zero3, pose = [[0.0, 0.0, 0.0]], [[0.0] * 72]
    rows = [{"id": p, "Rh": zero3, "Th": zero3, "poses": pose, "shapes": [[0.0] * 10]}
            for p in range(persons)]
    with open(path, "w") as f:
        json.dump(rows, f)


def wham(path, tracks):
    """WHAM's results dict: id -> {pose (4,72), trans (4,3), betas (4,10), frame_ids (4,)}."""
    results = {t: {"pose": np.zeros((4, 72), np.float32), "trans": np.zeros((4, 3), np.float32),
                   "betas": np.zeros((4, 10), np.float32), "frame_ids": np.arange(4)}
               for t in range(tracks)}
    joblib.dump(results, path)


def timed(argv):
    """(wall seconds, CPU seconds of the child) of one run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run([str(a) for a in argv], check=True, stdout=subprocess.DEVNULL)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--model", required=True)
    ap.add_argument("--persons", type=int, default=100000)
    ap.add_argument("--tracks", type=int, default=1000)
    a = ap.parse_args()
    fast = ["--skin-weights", "truncated", "-q"]
    with tempfile.TemporaryDirectory() as tmp:
        for label, make, big, extra in (("persons", easymocap, a.persons, ["--track", "longest"]),
                                        ("tracks", wham, a.tracks, ["--track", "all"])):
            secs = {}
            for n in (big // 10, big):
                ext = ".json" if make is easymocap else ".pkl"
                motion = os.path.join(tmp, f"{label}{n}_000000{ext}")
                make(motion, n)
                out = os.path.join(tmp, f"out_{label}{n}")
                os.mkdir(out)
                secs[n] = timed([a.exe, "--model", a.model, "--motion", motion, "--out",
                                 os.path.join(out, "body.glb")] + extra + fast)
                print(f"{label} {n}: {secs[n][0]:.2f} s wall, {secs[n][1]:.2f} s CPU", flush=True)
            small = secs[big // 10]
            print(f"{label} ratio {big}/{big // 10}: {secs[big][0] / small[0]:.1f}x wall, "
                  f"{secs[big][1] / small[1]:.1f}x CPU (linear ~10x)", flush=True)


if __name__ == "__main__":
    main()
