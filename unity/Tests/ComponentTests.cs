// SmplCorrectives (the MonoBehaviour) on stubbed UnityEngine objects, with
// Unity's float types: importer-decorated bone and blend shape names, a
// rotated character, rest from bind poses (in centimetres) or from Start, a
// sidecar with scale/offset, a missing bone, a wrong axis convention
// that must be detected, and a --corrective-basis sidecar.
// Uses only UnityEngine API that exists in Unity (and in the mono stub
// tests/unity/UnityEngineStub.cs), so Unity's Test Runner runs it too.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using SmplExport.Correctives;
using UnityEngine;

namespace SmplExport.Correctives.Tests
{
    // Model/ (rotated by W)
    //   Body        SkinnedMeshRenderer + SmplCorrectives
    //   Armature/   bones named prefix + joint name, parented as the model
    public sealed class TestRig
    {
        static readonly List<TestRig> live = new List<TestRig>();
        public readonly GameObject Model, Body;
        public readonly Transform[] Bones;
        public readonly SkinnedMeshRenderer Skin;
        public readonly SmplCorrectives Driver;
        public readonly Dictionary<string, int> ShapeIndex = new Dictionary<string, int>();
        public Quaternion W = Quaternion.identity;

        public TestRig(ReferenceModel model, string bonePrefix, string shapePrefix)
        {
            Model = new GameObject("Model");
            Body = new GameObject("Body");
            Body.transform.parent = Model.transform;
            var armature = new GameObject("Armature");
            armature.transform.parent = Model.transform;
            Bones = new Transform[model.JointCount];
            for (int k = 0; k < model.JointCount; ++k)
            {
                Bones[k] = new GameObject(bonePrefix + model.JointNames[k]).transform;
                Bones[k].parent = k == 0 ? armature.transform : Bones[model.Parents[k]];
            }
            Skin = Body.AddComponent<SkinnedMeshRenderer>();
            Skin.sharedMesh = new Mesh { name = "BodyMesh" };
            Skin.sharedMesh.vertices = new Vector3[1];  // Unity's blend shapes need vertices
            // Reverse order and unrelated shapes: lookup must go by name.
            AddBlendShape("Smile");
            SidecarLayout layout = SidecarLayout.FromSkeleton(model.JointNames, model.Parents);
            for (int i = layout.Correctives.Length - 1; i >= 0; --i)
            {
                ShapeIndex[layout.Correctives[i].Target] = Skin.sharedMesh.blendShapeCount;
                AddBlendShape(shapePrefix + layout.Correctives[i].Target);
            }
            Driver = Body.AddComponent<SmplCorrectives>();
            Driver.sidecar = Text("body.glb.smpl.json", Sidecar(model, 1.0, 0.0));
            live.Add(this);
        }

        /// <summary>Adds a one-frame blend shape (zero deltas) to the rig's mesh.</summary>
        public void AddBlendShape(string name)
        {
            Mesh mesh = Skin.sharedMesh;
            mesh.AddBlendShapeFrame(name, 100f, new Vector3[mesh.vertexCount], null, null);
        }

        public static TextAsset Text(string name, string text) { return new TextAsset(text) { name = name }; }

        /// <summary>Destroys the objects of every rig made so far (in Unity they would stay in the open scene).</summary>
        public static void DestroyAll()
        {
            foreach (TestRig rig in live)
            {
                UnityEngine.Object.DestroyImmediate(rig.Skin.sharedMesh);
                UnityEngine.Object.DestroyImmediate(rig.Model);
            }
            live.Clear();
        }

        public void Pose(Quat[] world)
        {
            Model.transform.rotation = W;
            for (int k = 0; k < Bones.Length; ++k) Bones[k].rotation = W * ToFloat(world[k]);
        }

        public static string Sidecar(ReferenceModel model, double scale, double offset)
        {
            var sb = new StringBuilder("{\"model_kind\":\"smpl\",\"joint_names\":[");
            for (int k = 0; k < model.JointCount; ++k) sb.Append(k > 0 ? "," : "").Append('"').Append(model.JointNames[k]).Append('"');
            sb.Append("],\"parents\":[").Append(string.Join(",", Array.ConvertAll(model.Parents, p => p.ToString(CultureInfo.InvariantCulture))));
            sb.Append("],\"units\":\"meters\",\"correctives\":[");
            for (int n = 0; n < 9 * (model.JointCount - 1); ++n)
            {
                int k = n / 9 + 1, rc = n % 9;
                sb.Append(n > 0 ? "," : "").Append("{\"feature\":").Append(n)
                  .Append(",\"target\":\"pose_").Append(model.JointNames[k]).Append('_').Append(rc / 3).Append(rc % 3)
                  .Append("\",\"scale\":").Append(scale.ToString("R", CultureInfo.InvariantCulture))
                  .Append(",\"offset\":").Append(offset.ToString("R", CultureInfo.InvariantCulture)).Append('}');
            }
            return sb.Append("]}").ToString();
        }

        public static Quaternion ToFloat(Quat q) { return new Quaternion((float)q.X, (float)q.Y, (float)q.Z, (float)q.W); }

        // Unity's bind pose of a bone whose mesh-space rest rotation is `rest`,
        // for an asset in centimetres (uniform scale 100).
        public static Matrix4x4 BindPose(Quat rest)
        {
            var m = new double[9];
            rest.Inverse().WriteMatrixMinusIdentity(m, 0);
            for (int i = 0; i < 3; ++i) m[4 * i] += 1.0;
            return new Matrix4x4 {
                m00 = (float)(100 * m[0]), m01 = (float)(100 * m[1]), m02 = (float)(100 * m[2]),
                m10 = (float)(100 * m[3]), m11 = (float)(100 * m[4]), m12 = (float)(100 * m[5]),
                m20 = (float)(100 * m[6]), m21 = (float)(100 * m[7]), m22 = (float)(100 * m[8]),
                m33 = 1 };
        }
    }

    static class ComponentTests
    {
        static readonly Quaternion Turned = Normalised(new Quaternion(0.3f, -0.5f, 0.2f, 0.78f));

        public static void Run(ReferenceModel model)
        {
            StartPoseDecoratedNames(model);
            BindPosesWithSidecar(model);
            WrongAxisConventionIsDetected(model);
            MissingBone(model);
            RenamedBones(model);
            BasisSidecar(model);
            SplitSidecar(model);
            TestRig.DestroyAll();
        }

        // The exporter's --corrective-basis metadata (the kit's K = 8, unit weights):
        // basis blend shapes get scale (C f) + offset, as the C++ computes it.
        static void BasisSidecar(ReferenceModel model)
        {
            var rig = new TestRig(model, "Armature|", "");
            string error;
            SidecarLayout layout = SidecarLayout.Parse(model.BasisSidecar, "basis.glb.smpl.json", out error);
            CorrectivesTests.Check(layout != null && layout.Basis != null && layout.Basis.Targets.Length == 8 &&
                                   layout.Correctives.Length == 0, model.Name + ": basis sidecar parsed: " + error);
            if (layout == null || layout.Basis == null) return;
            var basisIndex = new int[layout.Basis.Targets.Length];
            for (int k = layout.Basis.Targets.Length - 1; k >= 0; --k)  // reverse order: lookup goes by name
            {
                basisIndex[k] = rig.Skin.sharedMesh.blendShapeCount;
                rig.AddBlendShape(model.Name + "." + layout.Basis.Targets[k]);
            }
            rig.Driver.sidecar = TestRig.Text("basis.glb.smpl.json", model.BasisSidecar);
            if (!InitializeAtRest(rig, model.JointCount, model.Name + ": basis setup")) return;
            double worst = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                rig.Pose(pose.IdentityRestWorld);
                rig.Driver.Evaluate();
                for (int k = 0; k < basisIndex.Length; ++k)
                    worst = Math.Max(worst, Math.Abs(rig.Skin.GetBlendShapeWeight(basisIndex[k]) / 100.0 - pose.BasisWeights[k]));
            }
            CorrectivesTests.CheckClose(worst, CorrectivesTests.FloatTolerance, model.Name + ": basis blend shape weights / 100");
        }

        // The split encoding (exact with every weight at zero): diagonal
        // feature n -> one shape, weight -f/2; off-diagonal -> pose_..._pos
        // (max(f, 0)) and pose_..._neg (max(-f, 0)), entries "rectified": true.
        static void SplitSidecar(ReferenceModel model)
        {
            var rig = new TestRig(model, "", "");
            var sb = new StringBuilder("{\"joint_names\":[");
            for (int k = 0; k < model.JointCount; ++k) sb.Append(k > 0 ? "," : "").Append('"').Append(model.JointNames[k]).Append('"');
            sb.Append("],\"parents\":[").Append(string.Join(",", Array.ConvertAll(model.Parents, p => p.ToString(CultureInfo.InvariantCulture))));
            sb.Append("],\"corrective_encoding\":\"split\",\"correctives\":[");
            var entries = new List<KeyValuePair<string, double[]>>();  // target -> {feature, scale}
            for (int n = 0; n < 9 * (model.JointCount - 1); ++n)
            {
                int k = n / 9 + 1, rc = n % 9;
                string target = "pose_" + model.JointNames[k] + "_" + (rc / 3) + (rc % 3);
                if (rc % 4 == 0) entries.Add(new KeyValuePair<string, double[]>(target, new double[] { n, -0.5 }));
                else
                {
                    entries.Add(new KeyValuePair<string, double[]>(target + "_pos", new double[] { n, 1 }));
                    entries.Add(new KeyValuePair<string, double[]>(target + "_neg", new double[] { n, -1 }));
                }
            }
            var index = new Dictionary<string, int>();
            for (int i = 0; i < entries.Count; ++i)
            {
                string target = entries[i].Key;
                bool half = target.EndsWith("_pos") || target.EndsWith("_neg");
                sb.Append(i > 0 ? "," : "").Append("{\"feature\":").Append((int)entries[i].Value[0])
                  .Append(",\"target\":\"").Append(target).Append("\",\"scale\":")
                  .Append(entries[i].Value[1].ToString("R", CultureInfo.InvariantCulture)).Append(",\"offset\":0")
                  .Append(half ? ",\"rectified\":true}" : "}");
                if (half)
                {
                    index[target] = rig.Skin.sharedMesh.blendShapeCount;
                    rig.AddBlendShape(target);
                }
                else index[target] = rig.ShapeIndex[target];
            }
            rig.Driver.sidecar = TestRig.Text("split.glb.smpl.json", sb.Append("]}").ToString());
            if (!InitializeAtRest(rig, model.JointCount, model.Name + ": split setup")) return;
            double worst = 0, decoded = 0, below = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                rig.Pose(pose.IdentityRestWorld);
                rig.Driver.Evaluate();
                foreach (var e in entries)
                {
                    double f = pose.Features[(int)e.Value[0]], w = rig.Skin.GetBlendShapeWeight(index[e.Key]) / 100.0;
                    bool half = e.Key.EndsWith("_pos") || e.Key.EndsWith("_neg");
                    worst = Math.Max(worst, Math.Abs(w - (half ? Math.Max(0, e.Value[1] * f) : -0.5 * f)));
                    below = Math.Min(below, w);
                    if (e.Key.EndsWith("_pos"))  // the pair decodes to f: posedirs * (w_pos - w_neg)
                        decoded = Math.Max(decoded, Math.Abs(w - rig.Skin.GetBlendShapeWeight(index[e.Key.Replace("_pos", "_neg")]) / 100.0 - f));
                }
            }
            CorrectivesTests.CheckClose(worst, CorrectivesTests.FloatTolerance, model.Name + ": split blend shape weights / 100");
            CorrectivesTests.CheckClose(decoded, CorrectivesTests.FloatTolerance, model.Name + ": split pairs decode to f");
            CorrectivesTests.Check(below >= 0, model.Name + ": a split weight below 0: " + below);
        }

        // Identity-rest bones with Mixamo-style names, rest taken at Start.
        static void StartPoseDecoratedNames(ReferenceModel model)
        {
            var rig = new TestRig(model, "mixamorig:", "BlendShapeChannel.");
            rig.W = Turned;
            if (model.JointCount == 24) rig.Driver.sidecar = null;  // the built-in SMPL layout
            if (!InitializeAtRest(rig, model.JointCount, model.Name + ": StartPose setup")) return;
            double feature = 0, weight = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                rig.Pose(pose.IdentityRestWorld);
                rig.Driver.Evaluate();
                feature = Math.Max(feature, CorrectivesTests.MaxError(rig.Driver.Features, pose.Features));
                weight = Math.Max(weight, WeightError(rig, model, pose.Features, 1.0, 0.0));
            }
            CorrectivesTests.CheckClose(feature, CorrectivesTests.FloatTolerance, model.Name + ": SmplCorrectives features, rest at Start");
            string last = model.JointNames[model.JointCount - 1];
            CorrectivesTests.Check(rig.Driver.BoneForJoint(last) == rig.Bones[model.JointCount - 1] &&
                                   rig.Driver.BoneForJoint("no_such_joint") == null, model.Name + ": BoneForJoint by name");
            CorrectivesTests.CheckClose(weight, CorrectivesTests.FloatTolerance, model.Name + ": blend shape weights / 100, rest at Start");
        }

        // Bones with random bind orientations (FBX-like), rest from the mesh's
        // bind poses while the character starts in a non-rest pose, and a
        // sidecar mapping every feature to 100 * (0.5 f + 0.5).
        static void BindPosesWithSidecar(ReferenceModel model)
        {
            var rig = new TestRig(model, "Armature|", model.Name + ".");
            rig.W = Turned;
            var order = new List<int>();
            for (int k = model.JointCount - 1; k >= 0; --k) order.Add(k);  // renderer order != model order
            rig.Skin.bones = order.ConvertAll(k => rig.Bones[k]).ToArray();
            rig.Skin.sharedMesh.bindposes = order.ConvertAll(k => TestRig.BindPose(model.BindRest[k])).ToArray();
            rig.Driver.sidecar = TestRig.Text("body.glb.smpl.json", TestRig.Sidecar(model, 0.5, 0.5));
            rig.Pose(model.Poses[0].BindRestWorld);
            bool ready = rig.Driver.Initialize();
            CorrectivesTests.Check(ready && rig.Driver.Messages.Count == 0,
                                   model.Name + ": BindPoses setup: " + string.Join("; ", rig.Driver.Messages.ToArray()));
            if (!ready) return;
            double feature = 0, weight = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                rig.Pose(pose.BindRestWorld);
                rig.Driver.Evaluate();
                feature = Math.Max(feature, CorrectivesTests.MaxError(rig.Driver.Features, pose.Features));
                weight = Math.Max(weight, WeightError(rig, model, pose.Features, 0.5, 0.5));
            }
            CorrectivesTests.CheckClose(feature, CorrectivesTests.FloatTolerance, model.Name + ": SmplCorrectives features, bind poses");
            CorrectivesTests.CheckClose(weight, CorrectivesTests.FloatTolerance, model.Name + ": weights with sidecar scale/offset");
            // ClearWeights zeroes the driven shapes (here 0.5 f + 0.5, rarely 0) and leaves others alone.
            rig.Skin.SetBlendShapeWeight(0, 42f);  // "Smile"
            rig.Driver.ClearWeights();
            double cleared = 0;
            foreach (int index in rig.ShapeIndex.Values) cleared = Math.Max(cleared, Math.Abs(rig.Skin.GetBlendShapeWeight(index)));
            CorrectivesTests.Check(cleared == 0 && rig.Skin.GetBlendShapeWeight(0) == 42f,
                                   model.Name + ": ClearWeights left weight " + cleared + ", Smile " + rig.Skin.GetBlendShapeWeight(0));
        }

        static void WrongAxisConventionIsDetected(ReferenceModel model)
        {
            var rig = new TestRig(model, "", "");
            rig.Driver.axisConvention = SmplCorrectives.AxisConvention.Identity;
            rig.Pose(Identities(model.JointCount));
            rig.Driver.Initialize();
            double worst = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                rig.Pose(pose.IdentityRestWorld);
                rig.Driver.Evaluate();
                worst = Math.Max(worst, CorrectivesTests.MaxError(rig.Driver.Features, pose.Features));
            }
            CorrectivesTests.Check(worst > 1e-3, model.Name + ": identity axis convention went unnoticed (max error " + worst + ")");
        }

        // A leaf joint without a bone: its features are zero, the rest still match.
        static void MissingBone(ReferenceModel model)
        {
            int leaf = model.JointCount - 1;
            var rig = new TestRig(model, "", "");
            rig.Bones[leaf].name = "unrelated_" + leaf + "x";
            rig.Driver.restPose = SmplCorrectives.RestPoseSource.PoseAtStart;
            rig.Pose(Identities(model.JointCount));
            rig.Driver.Initialize();
            CorrectivesTests.Check(rig.Driver.Messages.Count == 1 && rig.Driver.Messages[0].Contains(model.JointNames[leaf]),
                                   model.Name + ": missing bone not reported: " + string.Join("; ", rig.Driver.Messages.ToArray()));
            ReferencePose pose = model.Poses[0];
            rig.Pose(pose.IdentityRestWorld);
            rig.Driver.Evaluate();
            var expected = (double[])pose.Features.Clone();
            for (int i = 0; i < 9; ++i) expected[9 * (leaf - 1) + i] = 0;
            CorrectivesTests.CheckClose(CorrectivesTests.MaxError(rig.Driver.Features, expected), CorrectivesTests.FloatTolerance,
                                        model.Name + ": features with a missing leaf bone");
        }

        // --skeleton-names: bones named otherwise than the joints (no name match at all),
        // found through the sidecar's bone_names; the features match as with joint names.
        static void RenamedBones(ReferenceModel model)
        {
            var rig = new TestRig(model, "", "");
            var bones = new string[model.JointCount];
            for (int k = 0; k < model.JointCount; ++k) rig.Bones[k].name = bones[k] = "rig:Bone" + k + "x";
            string sidecar = TestRig.Sidecar(model, 1.0, 0.0).Replace(
                "],\"parents\"", "],\"skeleton_names\":\"mixamo\",\"bone_names\":[\"" + string.Join("\",\"", bones) + "\"],\"parents\"");
            rig.Driver.sidecar = TestRig.Text("body.glb.smpl.json", sidecar);
            if (!InitializeAtRest(rig, model.JointCount, model.Name + ": renamed bones not found")) return;
            double worst = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                rig.Pose(pose.IdentityRestWorld);
                rig.Driver.Evaluate();
                worst = Math.Max(worst, CorrectivesTests.MaxError(rig.Driver.Features, pose.Features));
            }
            CorrectivesTests.CheckClose(worst, CorrectivesTests.FloatTolerance, model.Name + ": features with renamed bones (bone_names)");
        }

        static double WeightError(TestRig rig, ReferenceModel model, double[] features, double scale, double offset)
        {
            double worst = 0;
            for (int k = 1; k < model.JointCount; ++k)
                for (int rc = 0; rc < 9; ++rc)
                {
                    string target = "pose_" + model.JointNames[k] + "_" + (rc / 3) + (rc % 3);
                    double expected = scale * features[9 * (k - 1) + rc] + offset;
                    double actual = rig.Skin.GetBlendShapeWeight(rig.ShapeIndex[target]) / 100.0;
                    worst = Math.Max(worst, Math.Abs(actual - expected));
                }
            return worst;
        }

        // The driver initialised with the rig at rest (RestPoseSource.PoseAtStart), checked to
        // report nothing; false when it could not start ("<what>: <its messages>" is recorded).
        static bool InitializeAtRest(TestRig rig, int jointCount, string what)
        {
            rig.Driver.restPose = SmplCorrectives.RestPoseSource.PoseAtStart;
            rig.Pose(Identities(jointCount));
            bool ready = rig.Driver.Initialize();
            CorrectivesTests.Check(ready && rig.Driver.Messages.Count == 0,
                                   what + ": " + string.Join("; ", rig.Driver.Messages.ToArray()));
            return ready;
        }

        static Quat[] Identities(int count)
        {
            var q = new Quat[count];
            for (int k = 0; k < count; ++k) q[k] = Quat.Identity;
            return q;
        }

        static Quaternion Normalised(Quaternion q)
        {
            float n = (float)Math.Sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
            return new Quaternion(q.x / n, q.y / n, q.z / n, q.w / n);
        }
    }
}
