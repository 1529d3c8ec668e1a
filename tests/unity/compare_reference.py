#!/usr/bin/env python3
"""Checks that the C++ reference data shipped in the Unity package is current.

unity/Tests/Data/csharp_reference_smpl.json is what Unity's Test Runner
compares the runtime with (Unity cannot run the C++ reference). It is the
output of smpl-csharp-reference (tests/unity/csharp_reference.cpp) for the
synthetic fixture models/smpl_small.npz (tests/fixtures/make_models.py, fixed
seeds). This test regenerates it and compares: same structure and strings,
numbers within 1e-12 (absolute), ignoring "exporter_version" inside the
embedded basis sidecar (it changes with every release, not the math).

    compare_reference.py FRESH.json SHIPPED.json [--update]

--update copies FRESH over SHIPPED. Exit 1 (one line per difference, at most
10) if they differ.
"""
import json
import math
import shutil
import sys

TOLERANCE = 1e-12


def diff(a, b, where, out):
    if len(out) >= 10:
        return
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k == "exporter_version":
                continue
            if k not in a or k not in b:
                out.append(f"{where}.{k}: present in only one file")
            else:
                diff(a[k], b[k], f"{where}.{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.append(f"{where}: {len(a)} entries, shipped {len(b)}")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            diff(x, y, f"{where}[{i}]", out)
    elif isinstance(a, str) and isinstance(b, str) and a.startswith("{") and b.startswith("{"):
        diff(json.loads(a), json.loads(b), where + "(json)", out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if not (math.isfinite(a) and math.isfinite(b) and abs(a - b) <= TOLERANCE):
            out.append(f"{where}: {a!r}, shipped {b!r}")
    elif a != b:
        out.append(f"{where}: {a!r}, shipped {b!r}")


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--update"):
        print("usage: compare_reference.py FRESH.json SHIPPED.json [--update]", file=sys.stderr)
        return 2
    fresh, shipped = argv[0], argv[1]
    if len(argv) == 3:
        shutil.copyfile(fresh, shipped)
        print(f"compare_reference: updated {shipped}")
        return 0
    with open(fresh, encoding="utf-8") as f:
        a = json.load(f)
    with open(shipped, encoding="utf-8") as f:
        b = json.load(f)
    out = []
    diff(a, b, "$", out)
    for line in out:
        print(f"{shipped}: {line} (regenerate: see tests/unity/tests.cmake)")
    print(f"compare_reference: {len(out)} differences")
    return 1 if out else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
