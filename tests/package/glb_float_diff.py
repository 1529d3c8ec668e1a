#!/usr/bin/env python3
"""Two GLBs equal but for float rounding: same size, same JSON but for its
numbers (which may differ by at most TOL, relative to max(1, |value|)), same
binary chunk but for float32 words of FLOAT accessors, which may differ by
at most TOL (absolute, metres for positions). Prints how many differ and the
largest difference; exits 1 beyond TOL or on any other difference.
    glb_float_diff.py A.glb B.glb TOL
"""
import json
import struct
import sys

import numpy as np


def load(path):
    b = open(path, "rb").read()
    magic, _, total = struct.unpack("<4sII", b[:12])
    if magic != b"glTF" or total != len(b):
        sys.exit(f"{path}: not a GLB")
    n = struct.unpack("<I", b[12:16])[0]
    return b, json.loads(b[20:20 + n]), b[20 + n + 8:]


def numbers_close(a, b, tol, where):
    if isinstance(a, dict) and isinstance(b, dict) and a.keys() == b.keys():
        return all(numbers_close(a[k], b[k], tol, f"{where}.{k}") for k in a)
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return all(numbers_close(x, y, tol, f"{where}[{i}]") for i, (x, y) in enumerate(zip(a, b)))
    if isinstance(a, float) or isinstance(b, float):
        if isinstance(a, (int, float)) and isinstance(b, (int, float)) and \
                abs(a - b) <= tol * max(1.0, abs(a)):
            return True
    if a == b:
        return True
    print(f"JSON differs at {where}: {a!r} vs {b!r}")
    return False


def main():
    pa, pb, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
    ra, ja, ba = load(pa)
    rb, jb, bb = load(pb)
    if len(ba) != len(bb):
        sys.exit(f"binary chunks differ in size: {len(ba)} vs {len(bb)}")
    if not numbers_close(ja, jb, tol, "$"):
        return 1
    a = np.frombuffer(ba, np.uint8).copy()
    b = np.frombuffer(bb, np.uint8).copy()
    floats, worst, covered = 0, 0.0, np.zeros(len(a), bool)
    for acc in ja.get("accessors", []):
        if acc.get("componentType") != 5126 or "bufferView" not in acc:
            continue
        view = ja["bufferViews"][acc["bufferView"]]
        if "byteStride" in view:
            continue
        comps = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}[acc["type"]]
        off = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        count = acc["count"] * comps
        fa = np.frombuffer(ba, np.float32, count, off).astype(np.float64)
        fb = np.frombuffer(bb, np.float32, count, off).astype(np.float64)
        d = np.abs(fa - fb)
        floats += int((fa != fb).sum())
        worst = max(worst, float(d.max()) if count else 0.0)
        covered[off:off + 4 * count] = True
    other = int((a[~covered] != b[~covered]).sum())
    print(f"{pa}: {floats} float32 values differ, largest difference {worst:.3g}; "
          f"{other} other bytes differ")
    return 0 if worst <= tol and other == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
