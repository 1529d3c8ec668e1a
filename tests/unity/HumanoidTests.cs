// The Humanoid avatar setup (unity/Runtime/SmplHumanoid.cs, unity/Editor/HumanoidSetup.cs)
// on the bodies smpl-export writes: the GLBs of the SMPL, SMPL-H and SMPL-X
// fixtures (exported by the unity_humanoid_export.* tests into
// $SMPL_HUMANOID_DIR/{smpl,smplh,smplx}.glb) are read here, their node tree
// rebuilt as Transforms (names, translations, rotations as in the file), and
//   - the mapping table equals the one in docs/file-contract.md;
//   - every bone Unity requires is mapped, and every table joint exists in
//     the exported skeleton of the kinds the file contract lists for it;
//   - the avatar builds (AvatarBuilder stub checks: names, hierarchy, lengths);
//   - with decorated bone names and a `root` joint above pelvis (--root-bone),
//     the avatar and SmplCorrectives bind the same transforms, and the
//     correctives still follow a pose.
// Mono only (not shipped in the package: it needs the exported files).
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;
using SmplExport.Correctives.Editor;
using UnityEngine;

namespace SmplExport.Correctives.StubTests
{
    public sealed class HumanoidTests
    {
        static readonly string[] Kinds = { "smpl", "smplh", "smplx" };
        static readonly Dictionary<string, string> KindLabel = new Dictionary<string, string>
        {
            { "smpl", "SMPL" }, { "smplh", "SMPL-H" }, { "smplx", "SMPL-X" }
        };
        // Skeleton joints with no human bone: SMPL's knuckle end joints, and --root-bone's root.
        static readonly string[] Unmapped = { "left_hand", "right_hand", "root" };

        readonly List<GameObject> made = new List<GameObject>();

        [TearDown]
        public void DestroyObjects()
        {
            foreach (GameObject go in made) UnityEngine.Object.DestroyImmediate(go);
            made.Clear();
            UnityEditor.AssetDatabase.Created.Clear();
        }

        [Test]
        public void TableEqualsTheFileContract()
        {
            List<string[]> rows = ContractRows();
            Assert.AreEqual(SmplHumanoid.Table.Length, rows.Count, "rows in docs/file-contract.md's Unity Humanoid mapping");
            for (int i = 0; i < rows.Count; ++i)
            {
                Assert.AreEqual(SmplHumanoid.Table[i].Joint, rows[i][0], "row " + i + " joint");
                Assert.AreEqual(SmplHumanoid.Table[i].Bone.ToString(), rows[i][1], "row " + i + " (" + rows[i][0] + ") bone");
            }
        }

        [Test]
        public void EveryRequiredBoneIsMappedOnce()
        {
            var seen = new HashSet<HumanBodyBones>();
            foreach (SmplHumanoid.Entry e in SmplHumanoid.Table)
                Assert.IsTrue(seen.Add(e.Bone), e.Bone + " is mapped twice");
            for (int i = 0; i < HumanTrait.BoneCount; ++i)
                if (HumanTrait.RequiredBone(i))
                    Assert.IsTrue(seen.Contains((HumanBodyBones)i), "required bone " + (HumanBodyBones)i + " not mapped");
        }

        // Each row's joint is in the exported skeleton of every kind its Models
        // column names, and absent from the others; every exported joint is mapped
        // or one of the known unmapped ones.
        [Test]
        public void MappedJointsExistInEachExportedSkeleton()
        {
            List<string[]> rows = ContractRows();
            foreach (string kind in Kinds)
            {
                Glb glb = Glb.Read(ExportedBody(kind));
                var joints = new HashSet<string>(glb.SkinJointNames());
                int expected = 0;
                foreach (string[] row in rows)
                {
                    bool listed = row[2].Split(',').Select(s => s.Trim()).Contains(KindLabel[kind]);
                    if (listed) ++expected;
                    Assert.AreEqual(listed, joints.Contains(row[0]),
                                    kind + ".glb: joint " + row[0] + (listed ? " missing" : " unexpectedly present"));
                }
                foreach (string j in joints)
                {
                    HumanBodyBones bone;
                    Assert.IsTrue(SmplHumanoid.TryGetBone(j, out bone) || Unmapped.Contains(j),
                                  kind + ".glb: joint " + j + " neither mapped nor known unmapped");
                }
                Assert.IsTrue(expected >= 22, kind + ": " + expected + " mapped joints");
            }
        }

        [Test]
        public void AvatarBuildsOnEachExportedBody()
        {
            var humanCount = new Dictionary<string, int> { { "smpl", 22 }, { "smplh", 52 }, { "smplx", 55 } };
            foreach (string kind in Kinds)
            {
                GameObject body = Instantiate(Glb.Read(ExportedBody(kind)), "", false);
                string error;
                Avatar avatar = SmplHumanoid.Apply(body, out error);
                Assert.IsNotNull(avatar, kind + ": " + error);
                Assert.IsTrue(avatar.isValid && avatar.isHuman, kind + ": avatar valid and human");
                Assert.AreEqual(humanCount[kind], avatar.humanDescription.human.Length, kind + ": human bones");
                Assert.IsTrue(body.GetComponent<Animator>() != null && body.GetComponent<Animator>().avatar == avatar,
                              kind + ": set on the Animator");
                HumanBone hips = avatar.humanDescription.human.First(h => h.humanName == "Hips");
                Assert.AreEqual("pelvis", hips.boneName, kind + ": Hips");
                if (kind != "smpl")
                    Assert.AreEqual("left_thumb3", avatar.humanDescription.human.First(
                        h => h.humanName == "Left Thumb Distal").boneName, kind + ": Left Thumb Distal");
            }
        }

        // --skeleton-names mixamo: the bones are mixamorig:*; with the GLB's
        // metadata the avatar maps each joint through bone_names, without it
        // the required joints are not found (by their SMPL names) and named.
        [Test]
        public void AvatarMapsRenamedBonesThroughTheMetadata()
        {
            Glb glb = Glb.Read(ExportedBody("smplx_mixamo"));
            GameObject body = Instantiate(glb, "", false);
            string error;
            Assert.IsTrue(SmplHumanoid.Build(body, out error) == null, "without the metadata: no avatar");
            Assert.IsTrue(error != null && error.Contains("pelvis") && error.Contains("left_elbow"),
                          "the missing joints are named: " + error);
            SidecarLayout layout = SidecarLayout.Parse(glb.JsonText, "smplx_mixamo.glb", out error);
            Assert.IsTrue(layout != null && layout.BoneNames != null, "the metadata has bone_names: " + error);
            Avatar avatar = SmplHumanoid.Apply(body, out error, layout);
            Assert.IsNotNull(avatar, "with the metadata: " + error);
            Assert.AreEqual(55, avatar.humanDescription.human.Length, "human bones");
            var boneOf = avatar.humanDescription.human.ToDictionary(h => h.humanName, h => h.boneName);
            Assert.AreEqual("mixamorig:Hips", boneOf["Hips"], "Hips");
            Assert.AreEqual("mixamorig:LeftForeArm", boneOf["LeftLowerArm"], "LeftLowerArm");
            Assert.AreEqual("mixamorig:RightHandThumb3", boneOf["Right Thumb Distal"], "Right Thumb Distal");
            Assert.AreEqual("jaw", boneOf["Jaw"], "Mixamo has no jaw bone: the model's name stays");
            GameObject again = Instantiate(glb, "", false);
            Assert.IsNotNull(HumanoidSetup.CreateFor(again, null, out error, layout), "editor setup: " + error);
        }

        [Test]
        public void MissingRequiredJointIsNamed()
        {
            GameObject body = Instantiate(Glb.Read(ExportedBody("smpl")), "", false);
            FindDeep(body.transform, "left_elbow").name = "elbow_removed";
            string error;
            Assert.IsTrue(SmplHumanoid.Build(body, out error) == null && error != null && error.Contains("left_elbow"),
                          "missing left_elbow reported: " + error);
        }

        // An FBX-style import: decorated names ("body:pelvis") and a root joint
        // above pelvis. The avatar maps Hips to body:pelvis; SmplCorrectives (with
        // the GLB's own metadata as sidecar) binds every joint to the same
        // transform the avatar maps, and a knee bend (what a Humanoid clip does to
        // the transforms) moves only the knee's features.
        [Test]
        public void CorrectivesBindTheAvatarsBones()
        {
            Glb glb = Glb.Read(ExportedBody("smplx"));
            GameObject body = Instantiate(glb, "body:", true);
            string error;
            Avatar avatar = SmplHumanoid.Apply(body, out error);
            Assert.IsNotNull(avatar, "avatar with decorated names and a root bone: " + error);
            Assert.AreEqual("body:pelvis", avatar.humanDescription.human.First(h => h.humanName == "Hips").boneName, "Hips");
            Assert.IsTrue(avatar.humanDescription.skeleton.Any(s => s.name == "body:root"), "root is in the skeleton");

            SidecarLayout layout = SidecarLayout.Parse(glb.JsonText, "smplx.glb", out error);
            Assert.IsNotNull(layout, "the GLB's metadata: " + error);
            var meshObject = new GameObject("Body");
            meshObject.transform.parent = body.transform;
            var skin = meshObject.AddComponent<SkinnedMeshRenderer>();
            skin.sharedMesh = new Mesh { name = "BodyMesh" };
            skin.sharedMesh.vertices = new Vector3[1];
            foreach (CorrectiveBinding c in layout.Correctives)
                skin.sharedMesh.AddBlendShapeFrame("Body." + c.Target, 100f, new Vector3[1], null, null);
            var driver = meshObject.AddComponent<SmplCorrectives>();
            driver.sidecar = new TextAsset(glb.JsonText) { name = "smplx.glb" };
            driver.restPose = SmplCorrectives.RestPoseSource.PoseAtStart;
            Assert.IsTrue(driver.Initialize(), "correctives initialize: " + string.Join("; ", driver.Messages.ToArray()));
            Assert.AreEqual(0, driver.Messages.Count, "no missing bones: " + string.Join("; ", driver.Messages.ToArray()));

            var boneOf = avatar.humanDescription.human.ToDictionary(h => h.humanName, h => h.boneName);
            int checkedJoints = 0;
            foreach (SmplHumanoid.Entry e in SmplHumanoid.Table)
            {
                Transform bound = driver.BoneForJoint(e.Joint);
                string humanName = HumanTrait.BoneName[(int)e.Bone];
                Assert.IsTrue(bound != null && boneOf.ContainsKey(humanName) && bound.name == boneOf[humanName],
                              e.Joint + ": correctives and avatar bind the same transform (" +
                              (bound == null ? "none" : bound.name) + ")");
                ++checkedJoints;
            }
            Assert.AreEqual(55, checkedJoints, "SMPL-X joints checked");

            int knee = Array.IndexOf(layout.JointNames, "left_knee");
            driver.BoneForJoint("left_knee").localRotation = Quaternion.AngleAxis(60f, Vector3.right);
            driver.Evaluate();
            double[] f = driver.Features;
            for (int k = 1; k < layout.JointNames.Length; ++k)
            {
                double norm = 0;
                for (int i = 0; i < 9; ++i) norm += Math.Abs(f[9 * (k - 1) + i]);
                if (k == knee)
                    Assert.IsTrue(norm > 0.5, "left_knee features follow the bend (|f| = " + norm + ")");
                else
                    Assert.IsTrue(norm < 1e-6, layout.JointNames[k] + " features stay 0 (|f| = " + norm + ")");
            }
        }

        [Test]
        public void EditorSetupSavesAndAssigns()
        {
            Assert.AreEqual("Assets/Bodies/body.fbx.avatar.asset", HumanoidSetup.AvatarPathFor("Assets/Bodies/body.fbx", "body"), "next to the model");
            Assert.AreEqual("Assets/body.avatar.asset", HumanoidSetup.AvatarPathFor("Packages/x/body.glb", "body"), "a package model");
            Assert.AreEqual("Assets/body.avatar.asset", HumanoidSetup.AvatarPathFor(null, "body"), "no model");
            GameObject body = Instantiate(Glb.Read(ExportedBody("smplh")), "", false);
            string error;
            Avatar avatar = HumanoidSetup.CreateFor(body, "Assets/body.glb.avatar.asset", out error);
            Assert.IsNotNull(avatar, "editor setup: " + error);
            Assert.IsTrue(UnityEditor.AssetDatabase.Created["Assets/body.glb.avatar.asset"] == avatar, "saved as an asset");
            Assert.IsTrue(body.GetComponent<Animator>().avatar == avatar, "assigned to the Animator");
        }

        // ---- helpers -------------------------------------------------------

        static string ExportedBody(string kind)
        {
            string dir = Environment.GetEnvironmentVariable("SMPL_HUMANOID_DIR");
            if (string.IsNullOrEmpty(dir)) throw new AssertionException("SMPL_HUMANOID_DIR is not set (see tests/unity/tests.cmake)");
            string path = Path.Combine(dir, kind + ".glb");
            if (!File.Exists(path)) throw new AssertionException(path + ": not exported (test unity_humanoid_export." + kind + ")");
            return path;
        }

        // Rows (joint, bone, models) of the table under "### Unity Humanoid mapping".
        static List<string[]> ContractRows()
        {
            string package = UnityEditor.AssetDatabase.PackageFolders["com.smpl-export.correctives"];
            string path = Path.Combine(Path.Combine(package, ".."), Path.Combine("docs", "file-contract.md"));
            var rows = new List<string[]>();
            bool inSection = false;
            foreach (string line in File.ReadAllLines(path))
            {
                if (line.StartsWith("#")) inSection = line.Trim() == "### Unity Humanoid mapping";
                if (!inSection || !line.StartsWith("| `")) continue;
                string[] cells = line.Trim('|').Split('|').Select(c => c.Trim().Trim('`')).ToArray();
                if (cells.Length != 3) throw new AssertionException(path + ": bad mapping row: " + line);
                rows.Add(cells);
            }
            if (rows.Count == 0) throw new AssertionException(path + ": no '### Unity Humanoid mapping' table");
            return rows;
        }

        // The GLB's node tree as GameObjects under a new root (the scene), names
        // prefixed; withRoot inserts a "root" joint at the origin above pelvis.
        GameObject Instantiate(Glb glb, string prefix, bool withRoot)
        {
            var scene = new GameObject(prefix + "body");
            made.Add(scene);
            var nodes = (List<object>)glb.Json["nodes"];
            var transforms = new Transform[nodes.Count];
            for (int i = 0; i < nodes.Count; ++i)
            {
                var node = (Dictionary<string, object>)nodes[i];
                object name;
                transforms[i] = new GameObject(prefix + (node.TryGetValue("name", out name) ? (string)name : "node" + i)).transform;
                double[] t = Numbers(node, "translation", 3), r = Numbers(node, "rotation", 4);
                if (t != null) transforms[i].localPosition = new Vector3((float)t[0], (float)t[1], (float)t[2]);
                if (r != null) transforms[i].localRotation = new Quaternion((float)r[0], (float)r[1], (float)r[2], (float)r[3]);
            }
            var hasParent = new bool[nodes.Count];
            for (int i = 0; i < nodes.Count; ++i)
            {
                object children;
                if (!((Dictionary<string, object>)nodes[i]).TryGetValue("children", out children)) continue;
                foreach (object c in (List<object>)children)
                {
                    transforms[(int)(double)c].parent = transforms[i];
                    hasParent[(int)(double)c] = true;
                }
            }
            for (int i = 0; i < nodes.Count; ++i)
            {
                if (hasParent[i]) continue;
                if (withRoot && transforms[i].name == prefix + "pelvis")
                {
                    var root = new GameObject(prefix + "root").transform;
                    root.parent = scene.transform;
                    transforms[i].parent = root;
                }
                else
                {
                    transforms[i].parent = scene.transform;
                }
            }
            return scene;
        }

        static double[] Numbers(Dictionary<string, object> node, string key, int n)
        {
            object v;
            if (!node.TryGetValue(key, out v)) return null;
            var list = (List<object>)v;
            if (list.Count != n) throw new AssertionException("node " + key + " has " + list.Count + " values");
            return list.Select(x => (double)x).ToArray();
        }

        static Transform FindDeep(Transform t, string name)
        {
            if (t.name == name) return t;
            for (int i = 0; i < t.childCount; ++i)
            {
                Transform found = FindDeep(t.GetChild(i), name);
                if (found != null) return found;
            }
            return null;
        }

        // A GLB's JSON chunk (glTF 2.0 binary container: 12-byte header, then the JSON chunk).
        sealed class Glb
        {
            public string JsonText;
            public Dictionary<string, object> Json;

            public static Glb Read(string path)
            {
                byte[] bytes = File.ReadAllBytes(path);
                if (bytes.Length < 20 || BitConverter.ToUInt32(bytes, 0) != 0x46546C67u || BitConverter.ToUInt32(bytes, 16) != 0x4E4F534Au)
                    throw new AssertionException(path + ": not a GLB with a JSON chunk");
                int length = (int)BitConverter.ToUInt32(bytes, 12);
                var glb = new Glb { JsonText = Encoding.UTF8.GetString(bytes, 20, length).TrimEnd(' ', '\0') };
                object parsed;
                string error;
                if (!MiniJson.TryParse(glb.JsonText, out parsed, out error)) throw new AssertionException(path + ": " + error);
                glb.Json = (Dictionary<string, object>)parsed;
                return glb;
            }

            public List<string> SkinJointNames()
            {
                var nodes = (List<object>)Json["nodes"];
                var skin = (Dictionary<string, object>)((List<object>)Json["skins"])[0];
                return ((List<object>)skin["joints"])
                    .Select(j => (string)((Dictionary<string, object>)nodes[(int)(double)j])["name"]).ToList();
            }
        }
    }
}
