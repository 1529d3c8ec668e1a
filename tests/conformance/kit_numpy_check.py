"""The conformance kit's expected values, checked independently of
core/math and of every runtime: numpy/scipy recompute, for every case and
pose, from the model-space axis-angle pose alone,

  - R_k = Rodrigues(theta_k) and f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc
    (docs/file-contract.md, "The body model");
  - the engine's world rotations W_k = C G_k C^T B_k (G_k = G_p(k) R_k, B_k the
    rest world rotations) and the importer's local ones W_p^-1 W_k;
  - the weights from the case's sidecar: scale f[feature] + offset, clamped
    at 0 where "rectified", then scale_k (M f)_k + offset_k of the basis,

and compare with the kit's numbers (1e-12). Exit 1 with one line per problem.

    /usr/bin/python3 kit_numpy_check.py KIT_DIR
"""
import sys

import numpy as np
from scipy.spatial.transform import Rotation

from kit import Kit

TOL = 1e-12


def quats(q):
    return Rotation.from_quat(np.asarray(q, dtype=np.float64)).as_matrix()


def expected_weights(sidecar, f):
    w = []
    for e in sidecar.get("correctives", []):
        v = e["scale"] * f[e["feature"]] + e["offset"]
        w.append(max(0.0, v) if e.get("rectified") is True else v)
    basis = sidecar.get("corrective_basis")
    if basis:
        m = np.asarray(basis["matrix"], dtype=np.float64).reshape(len(basis["targets"]), -1)
        w += list(np.asarray(basis["scale"]) * (m @ f) + np.asarray(basis["offset"]))
    return np.asarray(w)


def check_case(entry, sidecar, data, problems):
    parents = sidecar["parents"]
    c = np.asarray(data["axes"], dtype=np.float64).reshape(3, 3)
    rest = quats(data["rest_world"])
    rest_local = quats(data["rest_local"])
    worst = {"features": 0.0, "weights": 0.0, "world": 0.0, "local": 0.0}
    for i, pose in enumerate(data["poses"]):
        r = Rotation.from_rotvec(np.asarray(pose["axis_angle"]).reshape(-1, 3)).as_matrix()
        f = (r[1:] - np.eye(3)).reshape(-1)
        g = np.empty_like(r)
        for k, p in enumerate(parents):
            g[k] = r[k] if p < 0 else g[p] @ r[k]
        world = c @ g @ c.T @ rest
        local = np.array([world[k] if p < 0 else world[p].T @ world[k] for k, p in enumerate(parents)])
        worst["features"] = max(worst["features"], np.abs(f - pose["features"]).max())
        worst["world"] = max(worst["world"], np.abs(world - quats(pose["world"])).max())
        worst["local"] = max(worst["local"], np.abs(local - quats(pose["local"])).max())
        w = expected_weights(sidecar, f)
        if len(w) != len(pose["weights"]):
            problems.append(f"{entry['data']}: pose {i}: {len(pose['weights'])} weights, sidecar gives {len(w)}")
            continue
        worst["weights"] = max(worst["weights"], np.abs(w - pose["weights"]).max())
    rest_local_expected = np.array([rest[k] if p < 0 else rest[p].T @ rest[k] for k, p in enumerate(parents)])
    worst["local"] = max(worst["local"], np.abs(rest_local - rest_local_expected).max())
    for what, e in worst.items():
        if not e <= TOL:
            problems.append(f"{entry['data']}: {what} differ from numpy by {e:.3g} (> {TOL:g})")
    return worst


def main(argv):
    if len(argv) != 1:
        print("usage: kit_numpy_check.py KIT_DIR", file=sys.stderr)
        return 2
    kit = Kit(argv[0])
    problems, count = [], 0
    overall = {}
    for entry, sidecar, data in kit.cases():
        worst = check_case(entry, sidecar, data, problems)
        overall = {k: max(overall.get(k, 0.0), v) for k, v in worst.items()}
        count += 1
    if count < 1 or count != len(kit.manifest["cases"]):
        problems.append(f"{argv[0]}: {count} cases read")
    for p in problems:
        print(p)
    print(f"kit_numpy_check: {count} cases; worst " + ", ".join(f"{k} {v:.3g}" for k, v in overall.items()))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
