#!/usr/bin/env python3
"""Nothing a motion file carries is dropped silently: the corpus walk.

Every motion fixture the test corpus holds (layouts/video, layouts/generation,
released, motions, ...) that the CLI exports with exit 0 is copied with one more
array, `extra_hand_pose` ((T,45) float32, T the frame count of a sibling pose
array, else (45,)), put in the innermost dict that holds the file's pose
arrays (the top level of a flat npz or pickle; GVHMR's smpl_params_global,
WHAM's per-track dicts, a person of a JSON list). The copy must export with
exit 0 and a note on stderr naming `extra_hand_pose` (core/motions/unread_keys.h).
Files where nothing can be injected (a bare array) are listed with the reason.
Fails when a copy exports silently, or when fewer than --min-layouts layouts
were covered.

  ignored_keys_walk.py --exe smpl-export --fixtures build/fixtures --work DIR
"""
import argparse
import gzip
import json
import os
import pickle
import re
import shutil
import subprocess
import sys
import zlib

import numpy as np

EXTRA = "extra_hand_pose"
FOLDERS = ["layouts/video", "layouts/generation", "released", "motions", "formats", "containers",
           "pickle_cases", "npy_cases", "legacy_torch", "dmpl", "table"]
MOTION_EXT = (".npz", ".smpl", ".pkl", ".joblib", ".pt", ".pth", ".npy", ".json", ".mcs")
MODELS = ["smpl_small.npz", "smplh_small.npz", "smplx_small.npz", "mano_small.npz"]
POSE_WORDS = ("pose", "rot", "theta", "orient")
PER_FOLDER = 2  # files tried per folder: the layouts, not every frame of a sequence


def pose_key(key):
    return isinstance(key, str) and any(w in key.lower() for w in POSE_WORDS)


def frames_of(value):
    shape = getattr(value, "shape", None)
    if shape is None and isinstance(value, list):
        shape = np.asarray(value, dtype=object).shape if value and isinstance(value[0], list) else (len(value),)
    return int(shape[0]) if shape is not None and len(shape) >= 2 else None


def holds_pose(d):
    return any(pose_key(k) and not isinstance(v, (dict, tuple)) and
               not (isinstance(v, list) and v and isinstance(v[0], dict)) for k, v in d.items())


def innermost(tree):
    """(path, dict) of the shallowest dict holding a pose array directly, first in file order
    (GVHMR's smpl_params_global before its net_outputs, WHAM's first track)."""
    level = [((), tree)]
    while level:
        for path, node in level:
            if isinstance(node, dict) and holds_pose(node):
                return path, node
        nxt = []
        for path, node in level:
            items = node.items() if isinstance(node, dict) else \
                enumerate(node) if isinstance(node, (list, tuple)) else ()
            nxt += [(path + (str(k),), v) for k, v in items if isinstance(v, (dict, list, tuple))]
        level = nxt
    return None


def extra_for(d, as_list=False, torch_tensor=False):
    t = next((frames_of(v) for k, v in d.items() if pose_key(k) and frames_of(v)), None)
    a = np.zeros((t, 45) if t else (45,), np.float32)
    if as_list:
        return a.tolist()
    if torch_tensor:
        import torch
        return torch.from_numpy(a)
    return a


def inject_tree(tree, **kw):
    found = innermost(tree)
    if not found:
        return None
    path, d = found
    d[EXTRA] = extra_for(d, **kw)
    return "/".join(path) or "top level"


def inject(src, dst):
    """Writes dst; returns (where, None) or (None, reason)."""
    ext = os.path.splitext(src)[1].lower()
    raw = open(src, "rb").read()
    if ext in (".npz", ".smpl") or raw[:4] == b"PK\x03\x04" and ext not in (".pt", ".pth"):
        with np.load(src, allow_pickle=True) as z:
            members = {k: z[k] for k in z.files}
        members[EXTRA] = extra_for(members)
        with open(dst, "wb") as f:
            np.savez(f, **members)
        return "top level", None
    if ext in (".json", ".mcs"):
        tree = json.loads(raw)
        where = inject_tree(tree, as_list=True)
        if not where:
            return None, "no dict holds a pose key"
        open(dst, "w").write(json.dumps(tree))
        return where, None
    if ext in (".pt", ".pth"):
        import torch
        tree = torch.load(src, weights_only=False)
        where = inject_tree(tree, torch_tensor=True) if isinstance(tree, (dict, list)) else None
        if not where:
            return None, "not a dict of tensors"
        torch.save(tree, dst)
        return where, None
    if ext == ".npy":
        a = np.load(src, allow_pickle=True)
        if a.dtype != object:
            return None, "a bare array %s" % (a.shape,)
        tree = a.item() if a.shape == () else a
        where = inject_tree(tree if a.shape == () else list(a))
        if not where:
            return None, "no dict holds a pose key"
        np.save(dst, tree if a.shape == () else a, allow_pickle=True)
        return where, None
    # pickle or joblib (plain, zlib, gzip): the synthetic fixtures this corpus generated
    import joblib
    compressed = raw[:1] == b"\x78" or raw[:2] == b"\x1f\x8b"
    try:
        tree, writer = pickle.loads(raw), "pickle"
    except Exception:
        tree, writer = joblib.load(src), "joblib"
    if isinstance(tree, np.ndarray) and tree.dtype != object:
        return None, "a bare array %s" % (tree.shape,)
    where = inject_tree(tree)
    if not where:
        return None, "no dict holds a pose key"
    if writer == "pickle" and not compressed:
        proto = raw[1] if raw[:1] == b"\x80" else 0
        with open(dst, "wb") as f:
            pickle.dump(tree, f, protocol=max(proto, 2))
    else:
        joblib.dump(tree, dst, compress=3 if compressed else 0)
    return where, None


def export(exe, model, motion, out):
    return subprocess.run([exe, "--model", model, "--motion", motion, "--out", out],
                          capture_output=True, text=True, timeout=120)


def motion_files(fixtures):
    for folder in FOLDERS:
        base = os.path.join(fixtures, folder)
        for root, dirs, files in os.walk(base):
            dirs[:] = sorted(d for d in dirs if d not in ("expected", "layouts"))
            picked = [f for f in sorted(files) if f.lower().endswith(MOTION_EXT)
                      and not f.endswith(".smpl.json")][:PER_FOLDER]
            for f in picked:
                yield os.path.join(root, f)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--fixtures", required=True)
    ap.add_argument("--work", required=True)
    # 22 rows: 3 refuse (MHR, joint positions, VPoser latents), Motion-X is a bare array and
    # SMPLer-X's exact ten keys become the fit row's with one more: 17 can be covered.
    ap.add_argument("--min-layouts", type=int, default=17)
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    out = os.path.join(args.work, "out.glb")
    rows, skipped, failures, layouts = [], [], [], set()
    walked = 0
    for i, path in enumerate(motion_files(args.fixtures)):
        walked += 1
        rel = os.path.relpath(path, args.fixtures)
        model = next((m for m in MODELS if export(args.exe, os.path.join(args.fixtures, "models", m),
                                                   path, out).returncode == 0), None)
        if not model:
            continue  # a refusal or a file of another kind: not a layout the CLI exports
        dst = os.path.join(args.work, "%03d_%s" % (i, os.path.basename(path)))
        try:
            where, reason = inject(path, dst)
        except Exception as e:  # an object the test's own loaders cannot rebuild
            where, reason = None, "cannot load: %s" % str(e).splitlines()[0][:80]
        if not where:
            skipped.append((rel, reason))
            continue
        run = export(args.exe, os.path.join(args.fixtures, "models", model), dst, out)
        note = next((l for l in run.stderr.splitlines() if "note:" in l and EXTRA in l), "")
        m = re.search(r"arrays the (\S+) reader does not read", note)
        # a decoder's own "ignored:" note (PromptHMR's): the layout is the fixture's folder
        layout = m.group(1) if m else os.path.basename(os.path.dirname(path))
        ok = run.returncode == 0 and note
        if ok:
            layouts.add(layout)
        rows.append((rel, where, "yes (%s)" % layout if ok else "NO"))
        if not ok:
            failures.append("%s: exit %d, no note naming %s; stderr: %s"
                            % (rel, run.returncode, EXTRA, run.stderr.strip()[-300:]))
    width = max([len(r[0]) for r in rows] + [10])
    print("%-*s  %-40s  %s" % (width, "file", "injected at", "note found"))
    for rel, where, found in rows:
        print("%-*s  %-40s  %s" % (width, rel, where[:40], found))
    for rel, reason in skipped:
        print("not injected: %s: %s" % (rel, reason))
    print("walked %d files, injected %d, noted %d, skipped %d; layouts noted: %d (%s)"
          % (walked, len(rows), len(rows) - len(failures), len(skipped), len(layouts),
             ", ".join(sorted(layouts))))
    for f in failures:
        print("FAIL " + f)
    if len(layouts) < args.min_layouts:
        print("FAIL only %d layouts covered, expected at least %d" % (len(layouts), args.min_layouts))
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
