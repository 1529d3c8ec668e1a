"""The Maya package's glue (maya/scripts/smpl_maya: bind, node, menu) against a
stand-in of the Maya API (tests/runtimes/fake_maya), with the C++ reference
forward pass as the truth. Not Maya: this checks what smpl_maya asks of Maya
(joints by name through the skinCluster, rest pose from bindPreMatrix, blend
shape targets by alias, Maya's row-vector matrices, Y-up and Z-up scenes, the
node's compute, the bake), not Maya itself.

  /usr/bin/python3 maya_glue_test.py --package <build>/maya --reference PREFIX
"""
import argparse
import json
import os
import sys
import tempfile
import unittest

import numpy as np
from scipy.spatial.transform import Rotation

from reference_poses import load_reference, world_rotations

ARGS = None
HERE = os.path.dirname(os.path.abspath(__file__))


def maya_matrix(rotation, translation):
    """Maya's 16 values (row vectors, v' = v M): the transpose of [R | t]."""
    m = np.eye(4)
    m[:3, :3] = rotation.T
    m[3, :3] = translation
    return m.ravel().tolist()


def split_entries(names):
    """Metadata entries of the split encoding (common brief) for K joints."""
    entries = []
    for n in range(9 * (len(names) - 1)):
        base = "pose_%s_%d%d" % (names[n // 9 + 1], (n % 9) // 3, n % 3)
        if (n % 9) % 4 == 0:
            entries.append({"feature": n, "target": base, "scale": -0.5, "offset": 0.0, "rectified": True})
        else:
            entries.append({"feature": n, "target": base + "_pos", "scale": 1.0, "offset": 0.0, "rectified": True})
            entries.append({"feature": n, "target": base + "_neg", "scale": -1.0, "offset": 0.0, "rectified": True})
    return entries


def expected_weights(entries, features):
    w = np.array([e["scale"] * features[e["feature"]] + e["offset"] for e in entries])
    rect = np.array([e.get("rectified") is True for e in entries])
    return np.where(rect, np.maximum(w, 0), w)


class MayaGlueTest(unittest.TestCase):
    def setUp(self):
        from maya import cmds
        self.cmds = cmds
        self.scene = cmds.reset()
        self.header, self.a = load_reference(ARGS.reference)
        self.names = self.header["joint_names"]
        self.parents = self.header["parents"]
        self.entries = split_entries(self.names)
        self.tmp = tempfile.TemporaryDirectory()
        self.fbx = os.path.join(self.tmp.name, "body.fbx")
        with open(self.fbx + ".smpl.json", "w") as f:
            json.dump({"joint_names": self.names, "parents": self.parents, "up_axis": "+Y",
                       "corrective_encoding": "split", "correctives": self.entries}, f)

    def tearDown(self):
        self.tmp.cleanup()

    def build_scene(self, up):
        """An imported FBX as Maya holds it: namespaced joints with their own
        orientations, a skinCluster whose matrix indices are not the model's
        order, a blendShape whose weight indices are shuffled among other targets."""
        s = self.scene
        s.up = up
        rng = np.random.default_rng(3)
        self.axes = np.eye(3) if up == "y" else Rotation.from_euler("x", 90, degrees=True).as_matrix()
        self.orient = Rotation.random(len(self.names), random_state=4).as_matrix()
        rest_j = self.a["rest_joints"]
        for k, name in enumerate(self.names):
            p = self.parents[k]
            s.add("body:" + name, "joint", parent=("body:" + self.names[p]) if p >= 0 else None)
        s.add("body:mesh", "mesh")
        s.add("skinCluster1", "skinCluster")
        s.add("blendShape1", "blendShape")
        s.history["body:mesh"] = ["skinCluster1", "blendShape1", "tweak1"]
        order = rng.permutation(len(self.names))
        for index, k in enumerate(order):
            name = "body:" + self.names[k]
            s.connections["skinCluster1.matrix[%d]" % (index + 2)] = name + ".worldMatrix[0]"
            rest = maya_matrix(self.axes @ self.orient[k] * 100.0, 100.0 * self.axes @ rest_j[k])
            s.nodes["skinCluster1"]["attrs"]["bindPreMatrix[%d]" % (index + 2)] = \
                np.linalg.inv(np.array(rest).reshape(4, 4)).ravel().tolist()
        targets = ["shape_0"] + [e["target"] for e in self.entries] + ["expr_1"]
        slots = rng.permutation(len(targets)) + 5
        alias = []
        for t, slot in zip(targets, slots):
            alias += [t, "weight[%d]" % slot]
        s.aliases["blendShape1"] = alias
        self.weight_index = dict(zip(targets, slots))
        s.on_time = self.pose
        self.pose(0)

    def pose(self, frame):
        """Joints' world matrices for reference pose `frame` (Maya's layout, cm)."""
        i = int(frame) % self.a["poses"].shape[0]
        world = world_rotations(self.a["poses"][i], self.parents)
        c = self.axes
        for k, name in enumerate(self.names):
            q = c @ world[k] @ c.T @ c @ self.orient[k] * 100.0
            self.scene.nodes["body:" + name]["world"] = maya_matrix(q, 100.0 * c @ self.a["joints"][i][k])

    def bind(self):
        import smpl_maya.bind as sb
        return sb.bind("body:mesh", metadata_path=self.fbx)

    def check_weights(self, up):
        self.build_scene(up)
        node = self.bind()
        self.assertEqual(node, "mesh_smplCorrectives")
        for i in range(self.a["poses"].shape[0]):
            self.cmds.currentTime(i)
            want = expected_weights(self.entries, self.a["features"][i])
            got = np.array([self.cmds.getAttr("blendShape1.weight[%d]" % self.weight_index[e["target"]])
                            for e in self.entries])
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
            self.assertTrue((got >= 0).all())
        self.assertGreater(np.abs(want).max(), 0.1)
        for t in ("shape_0", "expr_1"):  # other targets are left alone
            self.assertNotIn("blendShape1.weight[%d]" % self.weight_index[t], self.scene.connections)

    def test_weights_in_a_y_up_scene(self):
        self.check_weights("y")

    def test_weights_in_a_z_up_scene(self):
        self.check_weights("z")

    def test_connections(self):
        self.build_scene("y")
        node = self.bind()
        sources = {d: s for d, s in self.scene.connections.items() if d.startswith(node + ".inMatrix[")}
        self.assertEqual(len(sources), len(self.names))
        self.assertTrue(all(s.startswith("body:") and s.endswith(".worldMatrix[0]") for s in sources.values()))
        driven = [d for d, s in self.scene.connections.items() if s.startswith(node + ".outWeight[")]
        self.assertEqual(len(driven), len(self.entries))
        from maya.api import OpenMaya
        _, _, attrs, affects = OpenMaya.MFnPlugin.registered["smplCorrectives"]
        self.assertTrue(attrs["inMatrix"].array and attrs["outWeight"].array and attrs["outWeight"].usesArrayDataBuilder)
        self.assertIn(("inMatrix", "outWeight"), affects)
        self.assertIn(("layout", "outWeight"), affects)

    def test_bake_keys_every_frame_and_removes_the_node(self):
        import smpl_maya.bind as sb
        self.build_scene("y")
        node = self.bind()
        plugs = sb.bake(node, 0, 4)
        self.assertEqual(len(plugs), len(self.entries))
        self.assertNotIn(node, self.scene.nodes)
        for e in self.entries[:40]:
            keys = self.scene.keys["blendShape1.weight[%d]" % self.weight_index[e["target"]]]
            self.assertEqual(sorted(keys), [0, 1, 2, 3, 4])
            for frame, value in keys.items():
                self.assertAlmostEqual(value, expected_weights([e], self.a["features"][frame])[0], places=12)

    def test_no_metadata_binds_by_names(self):
        import smpl_maya.bind as sb
        self.build_scene("y")
        node = sb.bind("body:mesh", metadata_path=os.path.join(self.tmp.name, "missing.fbx"))
        self.cmds.currentTime(2)
        f = self.a["features"][2]
        for e in self.entries:  # names alone give the split mapping, except the diagonal scale
            got = self.cmds.getAttr("blendShape1.weight[%d]" % self.weight_index[e["target"]])
            if e["target"].endswith(("_pos", "_neg")):
                self.assertAlmostEqual(got, expected_weights([e], f)[0], places=12)
            else:
                self.assertAlmostEqual(got, f[e["feature"]], places=12)
        self.assertTrue(node)

    def test_errors_name_the_problem(self):
        import smpl_maya.bind as sb
        self.build_scene("y")
        self.scene.history["body:mesh"] = ["skinCluster1"]
        with self.assertRaisesRegex(RuntimeError, "body:mesh: no skinCluster and blendShape"):
            sb.bind("body:mesh")
        self.scene.history["body:mesh"] = ["skinCluster1", "blendShape1"]
        self.scene.aliases["blendShape1"] = ["shape_0", "weight[0]"]
        with self.assertRaisesRegex(RuntimeError, "blendShape1: no blend shape target"):
            sb.bind("body:mesh")

    def test_menu_and_shelf(self):
        import smpl_maya.menu as menu
        self.build_scene("y")
        menu.install()
        menu.install()  # idempotent
        ui = self.scene.ui
        self.assertEqual(ui.count(("menu", menu.MENU)), 1)
        self.assertIn(("menuItem", "Bind correctives"), ui)
        self.assertIn(("menuItem", "Bake correctives"), ui)
        self.assertIn(("shelfButton", "Bind"), ui)
        self.scene.selection = ["body:mesh"]
        self.scene.dialog_answer = [self.fbx + ".smpl.json"]
        nodes = self.scene.commands["Bind correctives"]()
        self.assertEqual(nodes, ["mesh_smplCorrectives"])
        self.scene.selection = []
        self.scene.ui_range = (1, 3)
        self.assertEqual(self.scene.commands["Bake correctives"](), ["mesh_smplCorrectives"])
        self.assertEqual(len(self.scene.keys), len(self.entries))

    def test_malformed_layout_writes_no_weights(self):
        from maya.api import OpenMaya
        self.build_scene("y")
        node = self.bind()
        self.cmds.setAttr(node + ".layout", "{\"driven\": 3}", type="string")
        self.assertEqual(self.cmds.getAttr("blendShape1.weight[%d]" % self.weight_index[self.entries[1]["target"]]), 0.0)
        self.assertTrue(any("malformed layout" in e for e in OpenMaya.MGlobal.errors))


def main():
    global ARGS
    ap = argparse.ArgumentParser()
    ap.add_argument("--package", required=True, help="the Maya package folder (with scripts/, plug-ins/)")
    ap.add_argument("--reference", required=True, help="smpl-reference output prefix")
    ARGS, rest = ap.parse_known_args()
    sys.path[:0] = [os.path.join(HERE, "fake_maya"), os.path.join(ARGS.package, "scripts")]
    os.environ["MAYA_PLUG_IN_PATH"] = os.path.join(ARGS.package, "plug-ins")
    import smpl_maya
    assert os.path.dirname(smpl_maya.core.__file__) == os.path.dirname(smpl_maya.__file__), \
        "the package must ship core.py (copied by the build)"
    result = unittest.main(argv=[sys.argv[0]] + rest, exit=False).result
    return 0 if result.wasSuccessful() and result.testsRun > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
