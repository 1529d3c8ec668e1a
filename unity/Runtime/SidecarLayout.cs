// The part of the exporter's metadata (docs/file-contract.md, "Metadata")
// the runtime needs: joint names, parents, and which blend shape carries
// which feature with what scale/offset. Read from the sidecar
// <asset>.smpl.json, or from a glTF file's asset.extras.smpl; without either,
// the SMPL body layout with the exporter's default names is used.
// An export with --corrective-basis K carries "corrective_basis" instead of
// per-feature entries: blend shape Targets[k] gets
// Scale[k] * sum_n Matrix[k * FeatureCount + n] f[n] + Offset[k].
using System;
using System.Collections.Generic;

namespace SmplExport.Correctives
{
    public sealed class CorrectiveBinding
    {
        public int Feature;
        public string Target;
        public double Scale = 1.0;
        public double Offset = 0.0;
        /// <summary>"rectified": true (split encoding): weight = max(0, Scale f + Offset).</summary>
        public bool Rectified;
    }

    public sealed class CorrectiveBasisLayout
    {
        public string[] Targets;
        public int FeatureCount;    // P = 9 (K - 1)
        public double[] Matrix;     // Targets.Length x FeatureCount, row-major
        public double[] Scale, Offset;
    }

    public sealed class SidecarLayout
    {
        public string[] JointNames;
        // --skeleton-names mixamo|ue5: the bone of each joint in the file ("mixamorig:Hips");
        // null when the bones carry JointNames. The blend shapes keep JointNames.
        public string[] BoneNames;
        public int[] Parents;
        public CorrectiveBinding[] Correctives;
        public CorrectiveBasisLayout Basis;   // null: no basis

        static readonly string[] SmplNames = {
            "pelvis", "left_hip", "right_hip", "spine1", "left_knee", "right_knee", "spine2",
            "left_ankle", "right_ankle", "spine3", "left_foot", "right_foot", "neck", "left_collar",
            "right_collar", "head", "left_shoulder", "right_shoulder", "left_elbow", "right_elbow",
            "left_wrist", "right_wrist", "left_hand", "right_hand" };
        static readonly int[] SmplParents = {
            -1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19, 20, 21 };

        /// <summary>SMPL's 24 joints and the exporter's default morph target names.</summary>
        public static SidecarLayout DefaultSmpl()
        {
            return FromSkeleton((string[])SmplNames.Clone(), (int[])SmplParents.Clone());
        }

        /// <summary>Every feature bound to pose_&lt;joint&gt;_&lt;r&gt;&lt;c&gt; with scale 1, offset 0.</summary>
        public static SidecarLayout FromSkeleton(string[] jointNames, int[] parents)
        {
            var layout = new SidecarLayout { JointNames = jointNames, Parents = parents };
            int count = Math.Max(0, jointNames.Length - 1);
            layout.Correctives = new CorrectiveBinding[9 * count];
            for (int k = 1; k < jointNames.Length; ++k)
                for (int rc = 0; rc < 9; ++rc)
                    layout.Correctives[9 * (k - 1) + rc] = new CorrectiveBinding {
                        Feature = 9 * (k - 1) + rc,
                        Target = "pose_" + jointNames[k] + "_" + (rc / 3) + (rc % 3) };
            return layout;
        }

        /// <summary>Parses sidecar text; null and a one-line error on any problem.</summary>
        public static SidecarLayout Parse(string json, string context, out string error)
        {
            object root;
            if (!MiniJson.TryParse(json, out root, out error))
            {
                error = context + ": " + error;
                return null;
            }
            var meta = FindMetadata(root);
            if (meta == null)
            {
                error = context + ": no 'joint_names' object (expected a .smpl.json sidecar or a glTF with asset.extras.smpl)";
                return null;
            }
            var layout = new SidecarLayout();
            error = layout.Read(meta);
            if (error != null)
            {
                error = context + ": " + error;
                return null;
            }
            return layout;
        }

        static Dictionary<string, object> FindMetadata(object root)
        {
            var o = root as Dictionary<string, object>;
            if (o == null) return null;
            if (o.ContainsKey("joint_names")) return o;
            object asset, extras, smpl;
            if (o.TryGetValue("asset", out asset) && asset is Dictionary<string, object> &&
                ((Dictionary<string, object>)asset).TryGetValue("extras", out extras) &&
                extras is Dictionary<string, object> &&
                ((Dictionary<string, object>)extras).TryGetValue("smpl", out smpl))
                return FindMetadata(smpl);
            return null;
        }

        string Read(Dictionary<string, object> meta)
        {
            var names = meta["joint_names"] as List<object>;
            if (names == null || names.Count == 0) return "'joint_names' must be a non-empty array";
            JointNames = new string[names.Count];
            for (int k = 0; k < names.Count; ++k)
            {
                JointNames[k] = names[k] as string;
                if (JointNames[k] == null) return "'joint_names'[" + k + "] is not a string";
            }
            object parentsValue;
            if (!meta.TryGetValue("parents", out parentsValue) || !(parentsValue is List<object>))
                return "missing 'parents' array";
            var parents = (List<object>)parentsValue;
            if (parents.Count != JointNames.Length)
                return "'parents' has " + parents.Count + " entries; 'joint_names' has " + JointNames.Length;
            Parents = new int[parents.Count];
            for (int k = 0; k < parents.Count; ++k)
            {
                if (!ReadInt(parents[k], out Parents[k])) return "'parents'[" + k + "] is not an integer";
                if (k == 0 ? Parents[0] != -1 : Parents[k] < 0 || Parents[k] >= k)
                    return "'parents'[" + k + "] = " + Parents[k] + "; expected " + (k == 0 ? "-1 (the root)" : "0 <= parent < " + k);
            }
            object bonesValue;
            if (meta.TryGetValue("bone_names", out bonesValue))
            {
                var bones = bonesValue as List<object>;
                if (bones == null || bones.Count != JointNames.Length)
                    return "'bone_names' must be an array as long as 'joint_names' (" + JointNames.Length + ")";
                BoneNames = new string[bones.Count];
                var seenBones = new HashSet<string>();
                for (int k = 0; k < bones.Count; ++k)
                {
                    BoneNames[k] = bones[k] as string;
                    if (BoneNames[k] == null || !seenBones.Add(BoneNames[k]))
                        return "'bone_names'[" + k + "] is not a string or not unique";
                }
            }
            object correctives;
            if (!meta.TryGetValue("correctives", out correctives) || !(correctives is List<object>))
                return "missing 'correctives' array";
            string error = ReadCorrectives((List<object>)correctives, 9 * (JointNames.Length - 1));
            object basis;
            if (error == null && meta.TryGetValue("corrective_basis", out basis))
                error = ReadBasis(basis as Dictionary<string, object>, 9 * (JointNames.Length - 1));
            return error;
        }

        string ReadBasis(Dictionary<string, object> o, int featureCount)
        {
            if (o == null) return "'corrective_basis' is not an object";
            object v;
            var targets = o.TryGetValue("targets", out v) ? v as List<object> : null;
            if (targets == null) return "'corrective_basis'.targets must be an array";
            var b = new CorrectiveBasisLayout { FeatureCount = featureCount, Targets = new string[targets.Count] };
            for (int k = 0; k < targets.Count; ++k)
                if ((b.Targets[k] = targets[k] as string) == null) return "'corrective_basis'.targets[" + k + "] is not a string";
            int features;
            if (!o.TryGetValue("features", out v) || !ReadInt(v, out features) || features != featureCount)
                return "'corrective_basis'.features must be " + featureCount + " (9 per non-root joint)";
            string error = ReadNumbers(o, "matrix", targets.Count * featureCount, out b.Matrix);
            if (error == null) error = ReadNumbers(o, "scale", targets.Count, out b.Scale);
            if (error == null) error = ReadNumbers(o, "offset", targets.Count, out b.Offset);
            if (error != null) return error;
            Basis = b;
            return null;
        }

        static string ReadNumbers(Dictionary<string, object> o, string key, int count, out double[] values)
        {
            values = null;
            object v;
            var list = o.TryGetValue(key, out v) ? v as List<object> : null;
            if (list == null || list.Count != count)
                return "'corrective_basis'." + key + " must be an array of " + count + " numbers";
            values = new double[count];
            for (int i = 0; i < count; ++i)
                if (!ReadDouble(list[i], out values[i])) return "'corrective_basis'." + key + "[" + i + "] is not a number";
            return null;
        }

        string ReadCorrectives(List<object> list, int featureCount)
        {
            Correctives = new CorrectiveBinding[list.Count];
            for (int i = 0; i < list.Count; ++i)
            {
                var entry = list[i] as Dictionary<string, object>;
                if (entry == null) return "'correctives'[" + i + "] is not an object";
                var b = new CorrectiveBinding();
                object v;
                if (!entry.TryGetValue("feature", out v) || !ReadInt(v, out b.Feature) || b.Feature < 0 ||
                    b.Feature >= featureCount)
                    return "'correctives'[" + i + "].feature must be an integer in [0, " + featureCount + ")";
                if (!entry.TryGetValue("target", out v) || !(v is string)) return "'correctives'[" + i + "].target must be a string";
                b.Target = (string)v;
                if (entry.TryGetValue("scale", out v) && !ReadDouble(v, out b.Scale))
                    return "'correctives'[" + i + "].scale must be a number";
                if (entry.TryGetValue("offset", out v) && !ReadDouble(v, out b.Offset))
                    return "'correctives'[" + i + "].offset must be a number";
                b.Rectified = entry.TryGetValue("rectified", out v) && v is bool && (bool)v;
                Correctives[i] = b;
            }
            return null;
        }

        static bool ReadDouble(object v, out double d)
        {
            d = 0;
            if (!(v is double)) return false;
            d = (double)v;
            return !double.IsNaN(d) && !double.IsInfinity(d);
        }

        static bool ReadInt(object v, out int i)
        {
            i = 0;
            double d;
            if (!ReadDouble(v, out d) || d != Math.Floor(d) || d < int.MinValue || d > int.MaxValue) return false;
            i = (int)d;
            return true;
        }
    }
}
