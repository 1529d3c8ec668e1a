"""The Python corrective core (blender/smpl_correctives/core.py, shared by the
Blender add-on and the Maya package) as a loader of the runtime conformance
kit (docs/conformance.md): every case's sidecar through core.metadata_from_file
and core.checked, the engine's world rotations through core.evaluate, the
features and weights against the kit's tolerance table; every bad sidecar must
be dropped where the kit says (the field the error names).

    /usr/bin/python3 python_core_conformance.py --core core.py --kit KIT_DIR

Prints one line per difference, "<case>: pose <i>: <quantity> differ by <e>
(> <tol>)", and exits 1 if there was any.
"""
import argparse
import importlib.util
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "conformance"))
from kit import Kit, quaternion_matrix  # noqa: E402

core = None


def key_names(sidecar):
    """The mesh's targets as the exporter names them: correctives, then the basis."""
    names = [e["target"] for e in sidecar.get("correctives", [])]
    return names + list((sidecar.get("corrective_basis") or {}).get("targets", []))


def run_case(kit, entry, data, problems):
    base = os.path.join(kit.dir, entry["sidecar"])[: -len(".smpl.json")]
    meta = core.checked(core.metadata_from_file(base))
    names, parents = meta["joint_names"], meta["parents"]
    bone_parent = {n: (names[p] if p >= 0 else None) for n, p in zip(names, parents)}
    keys = key_names(meta)
    plan = core.make_plan(bone_parent, keys, meta)
    order = [names.index(n) for n in plan.driven]
    slot = {n: s for s, n in enumerate(plan.driven)}
    axes = np.asarray(data["axes"], dtype=np.float64).reshape(3, 3)
    rest = np.array([quaternion_matrix(q) for q in data["rest_world"]])
    rest_inv = core.rest_inverse(rest[order])
    for i, pose in enumerate(data["poses"]):
        now = np.array([quaternion_matrix(q) for q in pose["world"]])[order]
        values = core.evaluate(plan, now, rest_inv, axes)
        weights = np.full(len(keys), np.nan)
        weights[plan.all_key_index] = values
        local = core.local_rotations(now, rest_inv, plan.parent_slot, axes)
        features = np.array([local[slot[n]] for n in names[1:]]).reshape(-1)
        for what, got in (("features", features), ("weights", weights)):
            want = np.asarray(pose[what])
            e = np.abs(got - want).max() if got.shape == want.shape else np.inf
            tol = kit.tolerance(what)
            if not e <= tol:  # NaN (an unbound key) fails too
                problems.append(f"{entry['name']}: pose {i}: {what} differ by {e:.3g} (> {tol:g})")


def refused(kit, entry):
    """Whether the core drops what the kit's bad sidecar breaks."""
    path = os.path.join(kit.dir, entry["sidecar"])[: -len(".smpl.json")]
    raw = core.metadata_from_file(path)
    if raw is None:
        return True  # not JSON, or not an object: nothing is trusted
    if entry["error"] == "json":
        return False
    meta = core.checked(raw)
    if entry["error"] in ("joint_names", "parents"):
        return "joint_names" not in meta and "parents" not in meta
    if entry["error"] == "correctives":
        given = raw.get("correctives")
        return "correctives" not in meta or len(core.corrective_table(meta)) < len(given)
    if entry["error"] == "corrective_basis":
        return core.basis_table(meta) is None
    return False


def main():
    global core
    ap = argparse.ArgumentParser()
    ap.add_argument("--core", required=True, help="path of core.py")
    ap.add_argument("--kit", required=True, help="the conformance kit's folder")
    args = ap.parse_args()
    spec = importlib.util.spec_from_file_location("smpl_corrective_core", args.core)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    kit = Kit(args.kit)
    problems, cases = [], 0
    for entry, _, data in kit.cases():
        run_case(kit, entry, data, problems)
        cases += 1
    bad = list(kit.bad())
    for entry, _ in bad:
        if not refused(kit, entry):
            problems.append(f"{entry['sidecar']}: not refused ({entry['what']}; expected '{entry['error']}' dropped)")
    for p in problems:
        print(p)
    print(f"python_core_conformance: {cases} cases, {len(bad)} bad sidecars, {len(problems)} problems")
    return 1 if problems or cases == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
