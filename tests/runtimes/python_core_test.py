"""The shared Python corrective core (blender/smpl_correctives/core.py, also
shipped in the Maya package) against the C++ reference forward pass, with
Debian's numpy/scipy and no Blender or Maya:

  /usr/bin/python3 python_core_test.py --core blender/smpl_correctives/core.py \
      --reference PREFIX      (PREFIX.json/.bin from smpl-reference --dump-model)

- features and weights of every importer frame and encoding: the
  conformance kit (python_core_conformance.py, docs/conformance.md); here,
  that without the axis conversion the features are wrong;
- vertices rebuilt from morph targets of each encoding (signed, unit, split) with the core's weights and linear blend skinning equal the
  reference's `vertices_full` to 1e-9 m;
- target names (importer prefixes/suffixes, _pos/_neg) bind to the right joint
  and metadata entry; malformed metadata is dropped, not trusted.
"""
import argparse
import importlib.util
import sys
import unittest

import numpy as np
from scipy.spatial.transform import Rotation

from reference_poses import load_reference, world_rotations

ARGS = None
core = None


def skin(v_posed, world, rest_joints, posed_joints, weights):
    """v' = sum_k w_ik (G_k (v - J_k) + j_k) (docs/file-contract.md)."""
    out = np.zeros_like(v_posed)
    for k in range(len(world)):
        out += weights[:, k:k + 1] * ((v_posed - rest_joints[k]) @ world[k].T + posed_joints[k])
    return out


def engine_view(world, axes, orient):
    """World rotations as an engine reports them: (C G_k C^-1) O_k, scaled by 100."""
    c_inv = np.linalg.inv(axes)
    return 100.0 * np.einsum("ij,kjl,lm,kmn->kin", axes, world, c_inv, orient)


def blender_axes(seed):
    """C = A^-1 Rx(90): Blender's Y-up -> Z-up import, armature object turned by A."""
    a = Rotation.random(random_state=seed).as_matrix()
    return np.linalg.inv(a) @ core.model_to_world("+Y", "Z")


def diagonal(n):
    return (n % 9) % 4 == 0


def encode(posedirs, v_shaped, encoding):
    """(base mesh (N,3), deltas (T,N,3), correctives entries) of one encoding."""
    base, deltas, entries = v_shaped.copy(), [], []
    for n in range(posedirs.shape[2]):
        p = posedirs[:, :, n]
        name = "pose_j_%d" % n
        if encoding == "signed":
            entries.append({"feature": n, "target": name, "scale": 1.0, "offset": 0.0})
            deltas.append(p)
        elif encoding == "unit":
            off = 1.0 if diagonal(n) else 0.5
            entries.append({"feature": n, "target": name, "scale": 0.5, "offset": off})
            deltas.append(p / 0.5)
            base = base - 2 * off * p
        elif diagonal(n):
            entries.append({"feature": n, "target": name, "scale": -0.5, "offset": 0.0})
            deltas.append(-2 * p)
        else:
            entries.append({"feature": n, "target": name + "_pos", "scale": 1.0, "offset": 0.0, "rectified": True})
            entries.append({"feature": n, "target": name + "_neg", "scale": -1.0, "offset": 0.0, "rectified": True})
            deltas += [p, -p]
    return base, np.array(deltas), entries


class Fixture:
    def __init__(self):
        self.header, self.a = load_reference(ARGS.reference)
        self.names = self.header["joint_names"]
        self.parents = self.header["parents"]
        self.bone_parent = {n: (self.names[p] if p >= 0 else None) for n, p in zip(self.names, self.parents)}
        rng = np.random.default_rng(11)
        self.orient = Rotation.random(len(self.names), random_state=rng.integers(1 << 30)).as_matrix()

    def key_names(self):
        """Target names as the exporter writes them: pose_<joint>_<r><c>."""
        return ["pose_%s_%d%d" % (self.names[n // 9 + 1], (n % 9) // 3, n % 3)
                for n in range(9 * (len(self.names) - 1))]

    def metadata(self, entries, bones=None):
        meta = {"joint_names": self.names, "parents": self.parents, "correctives": entries}
        if bones:
            meta.update(skeleton_names="mixamo", bone_names=bones)
        return core.checked(meta)

    def mixamo_bones(self):
        """Bone names as --skeleton-names mixamo gives them (a colon, as the rig's)."""
        return ["mixamorig:" + "".join(w.capitalize() for w in n.split("_")) for n in self.names]


class FeatureTest(unittest.TestCase):
    def test_without_the_axis_conversion_the_features_are_wrong(self):
        fx = Fixture()
        plan = core.make_plan(fx.bone_parent, fx.key_names(), fx.metadata([]))
        order = [fx.names.index(n) for n in plan.driven]
        axes = blender_axes(3)
        rest = engine_view(np.tile(np.eye(3), (len(fx.names), 1, 1)), axes, fx.orient)
        now = engine_view(world_rotations(fx.a["poses"][0], fx.parents), axes, fx.orient)
        values = core.evaluate(plan, now[order], core.rest_inverse(rest[order]), np.eye(3))
        self.assertGreater(np.abs(values - fx.a["features"][0]).max(), 0.05)


class VertexTest(unittest.TestCase):
    def check_encoding(self, encoding, renamed_bones=False):
        fx = Fixture()
        # --skeleton-names: the engine's bones carry other names than the targets' joints
        bones = fx.mixamo_bones() if renamed_bones else fx.names
        bone_parent = {b: (bones[p] if p >= 0 else None) for b, p in zip(bones, fx.parents)}
        base, deltas, entries = encode(fx.a["posedirs"], fx.a["v_shaped"], encoding)
        rng = np.random.default_rng(5)
        orient = Rotation.random(len(fx.names), random_state=rng.integers(1 << 30)).as_matrix()
        axes = blender_axes(9)
        # Targets named by the exporter's scheme; keys carry an importer prefix.
        renamed = []
        for e in entries:
            n = e["feature"]
            suffix = e["target"][len("pose_j_%d" % n):]
            renamed.append(dict(e, target="pose_%s_%d%d%s" % (fx.names[n // 9 + 1], (n % 9) // 3, n % 3, suffix)))
        meta = fx.metadata(renamed, bones if renamed_bones else None)
        keys = ["Key|" + e["target"] for e in renamed]
        plan = core.make_plan(bone_parent, keys, meta)
        self.assertEqual(len(plan.key_index), len(keys))
        order = [bones.index(n) for n in plan.driven]
        rest = engine_view(np.tile(np.eye(3), (len(fx.names), 1, 1)), axes, orient)
        worst = 0.0
        for i in range(fx.a["poses"].shape[0]):
            world = world_rotations(fx.a["poses"][i], fx.parents)
            values = core.evaluate(plan, engine_view(world, axes, orient)[order], core.rest_inverse(rest[order]), axes)
            w = np.zeros(len(keys))
            w[plan.key_index] = values
            if encoding == "split":
                self.assertTrue((w >= 0).all() and (w <= 1 + 1e-12).all())
            v_posed = base + np.tensordot(w, deltas, axes=1)
            v = skin(v_posed, world, fx.a["rest_joints"], fx.a["joints"][i], fx.a["weights"])
            worst = max(worst, np.abs(v - fx.a["vertices_full"][i]).max())
        self.assertLess(worst, 1e-9)

    def test_signed(self):
        self.check_encoding("signed")

    def test_unit(self):
        self.check_encoding("unit")

    def test_split(self):
        self.check_encoding("split")

    def test_split_with_renamed_bones(self):
        """--skeleton-names: the metadata's bone_names lead the core to the bones."""
        self.check_encoding("split", renamed_bones=True)

    def test_renamed_bones_without_bone_names_bind_nothing(self):
        fx = Fixture()
        bones = fx.mixamo_bones()
        bone_parent = {b: (bones[p] if p >= 0 else None) for b, p in zip(bones, fx.parents)}
        self.assertEqual(len(core.make_plan(bone_parent, fx.key_names(), fx.metadata([])).key_index), 0)
        # malformed bone_names (too short, or a bone twice) are dropped, not trusted
        self.assertNotIn("bone_names", fx.metadata([], bones[:-1]))
        self.assertNotIn("bone_names", fx.metadata([], [bones[0]] * len(bones)))


class NameAndMetadataTest(unittest.TestCase):
    def test_find_target(self):
        bones = {"left_knee": None, "spine1": None}
        self.assertEqual(core.find_target("Key|pose_left_knee_12.001", bones), ("left_knee", 1, 2, "pose_left_knee_12"))
        self.assertEqual(core.find_target("pose_spine1_00_neg", bones), ("spine1", 0, 0, "pose_spine1_00_neg"))
        self.assertIsNone(core.find_target("pose_left_ankle_12", bones))
        self.assertIsNone(core.find_target("shape_3", bones))

    def test_mapping_without_metadata_follows_the_names(self):
        self.assertEqual(core.default_mapping("pose_a_01"), (1.0, 0.0, False))
        self.assertEqual(core.default_mapping("pose_a_01_pos"), (1.0, 0.0, True))
        self.assertEqual(core.default_mapping("pose_a_01_neg"), (-1.0, 0.0, True))

    def test_rectified_only_when_true(self):
        table = core.corrective_table({"correctives": [
            {"target": "a", "scale": 2, "offset": 1, "rectified": True},
            {"target": "b", "scale": 2, "offset": 1, "rectified": "yes"},
            {"target": "c", "scale": "x"}, {"scale": 1}, {"target": "d", "scale": float("nan")}]})
        self.assertEqual(table, {"a": (2.0, 1.0, True), "b": (2.0, 1.0, False)})

    def test_weights(self):
        f = np.array([-0.5, 0.25, -1.5])
        np.testing.assert_allclose(core.weights(f, [1, -1, -0.5], [0, 0, 0], [True, True, False]), [0, 0, 0.75])
        np.testing.assert_allclose(core.weights(f, [0.5, 0.5, 0.5], [1, 0.5, 1], [False] * 3), [0.75, 0.625, 0.25])

    def test_malformed_metadata_is_dropped(self):
        m = core.checked({"joint_names": ["a", "b"], "parents": [-1], "correctives": {"x": 1},
                          "corrective_basis": {"targets": []}})
        self.assertNotIn("joint_names", m)
        self.assertNotIn("correctives", m)
        self.assertNotIn("corrective_basis", m)
        self.assertIsNone(core.checked([1, 2]))
        bad = core.checked({"joint_names": ["a", "b"], "parents": [-1, 0],
                            "corrective_basis": {"targets": ["t"], "matrix": [1, 2], "scale": [1], "offset": [0]}})
        self.assertIsNone(core.basis_table(bad))

    def test_model_to_world(self):
        np.testing.assert_allclose(core.model_to_world("+Y", "Z") @ [0, 1, 0], [0, 0, 1], atol=1e-15)
        np.testing.assert_allclose(core.model_to_world("+Y", "Y"), np.eye(3))
        np.testing.assert_allclose(core.model_to_world("+Z", "Y") @ [0, 0, 1], [0, 1, 0], atol=1e-15)

    def test_kabsch_recovers_a_rotation(self):
        c = Rotation.from_rotvec([0.3, -0.2, 1.0]).as_matrix()
        p = np.random.default_rng(1).normal(size=(6, 3))
        fitted, residual = core.kabsch(p, 2.5 * p @ c.T + [1, 2, 3])
        np.testing.assert_allclose(fitted, c, atol=1e-12)
        self.assertLess(residual, 1e-12)


def main():
    global ARGS, core
    ap = argparse.ArgumentParser()
    ap.add_argument("--core", required=True, help="path of core.py")
    ap.add_argument("--reference", required=True, help="smpl-reference --dump-model output prefix")
    ARGS, rest = ap.parse_known_args()
    spec = importlib.util.spec_from_file_location("smpl_corrective_core", ARGS.core)
    core = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(core)
    assert "bpy" not in sys.modules and "maya" not in sys.modules
    result = unittest.main(argv=[sys.argv[0]] + rest, exit=False).result
    return 0 if result.wasSuccessful() and result.testsRun > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
