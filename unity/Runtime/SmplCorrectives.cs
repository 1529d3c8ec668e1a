// Drives the pose-corrective blend shapes of an exported SMPL-family body
// from its bones every frame, so Unity reproduces the model's own output
// (docs/file-contract.md, "The robust runtime formula").
//
// Rotations are measured in the mesh's space (the SkinnedMeshRenderer's
// transform), the space the bind poses are stored in, so moving or turning
// the whole character changes nothing. Rest rotations come from
// Mesh.bindposes (rest of bone i in mesh space = rotation of
// inverse(bindposes[i])), which is right even if the character starts in an
// animated pose; bones missing from the renderer's bone list fall back to
// their rotation at Start, which is only right if the character is then in
// its bind pose.
//
// Blend shape weights must not be clamped: turn off
// PlayerSettings.legacyClampBlendShapeWeights (see README.md).
using System;
using System.Collections.Generic;
using UnityEngine;

namespace SmplExport.Correctives
{
    [AddComponentMenu("SMPL Export/SMPL Correctives")]
    [RequireComponent(typeof(SkinnedMeshRenderer))]
    [DisallowMultipleComponent]
    [DefaultExecutionOrder(1000)]  // after animation scripts that pose bones in LateUpdate
    public sealed class SmplCorrectives : MonoBehaviour
    {
        public enum AxisConvention { MirrorX, MirrorZ, Identity, Custom }
        public enum RestPoseSource { BindPoses, PoseAtStart }

        [Tooltip("The exporter's <asset>.smpl.json sidecar (Unity imports .json as a TextAsset). Empty: SMPL's 24-joint layout with default names.")]
        public TextAsset sidecar;
        [Tooltip("Where to look for bones besides the renderer's bone list. Empty: this object's parent.")]
        public Transform skeletonRoot;
        [Tooltip("Model axes -> Unity mesh axes. MirrorX: glTFast, UniGLTF ReverseX and Unity's FBX importer. MirrorZ: UniGLTF ReverseZ.")]
        public AxisConvention axisConvention = AxisConvention.MirrorX;
        [Tooltip("Custom: Unity coordinates of the model's +X, +Y, +Z axes.")]
        public Vector3 customModelX = new Vector3(-1, 0, 0);
        public Vector3 customModelY = new Vector3(0, 1, 0);
        public Vector3 customModelZ = new Vector3(0, 0, 1);
        [Tooltip("BindPoses: from the mesh (works from any starting pose). PoseAtStart: the bones' rotations at Start (character must be in bind pose).")]
        public RestPoseSource restPose = RestPoseSource.BindPoses;

        SkinnedMeshRenderer skin;
        CorrectiveMath math;
        SidecarLayout layout;
        Transform[] jointBones;   // per joint, null if not found
        Quat[] current;
        double[] features;
        int[] shapeIndex, shapeFeature;
        double[] shapeScale, shapeOffset;
        bool[] shapeRectified;
        int[] basisShapeIndex, basisRow;   // --corrective-basis blend shapes and their rows of C
        double[] basisWeights;

        /// <summary>Features of the last evaluation, 9(K-1) values in model order.</summary>
        public double[] Features { get { return features; } }
        public bool IsReady { get { return math != null; } }
        /// <summary>Problems found by Initialize(), one line each (also logged).</summary>
        public readonly List<string> Messages = new List<string>();

        public Transform BoneForJoint(int joint) { return jointBones[joint]; }

        /// <summary>The bone found for the joint with this name (the model's joint name, e.g. "left_knee"); null if none or not initialized.</summary>
        public Transform BoneForJoint(string jointName)
        {
            if (math == null) return null;
            int k = Array.IndexOf(layout.JointNames, jointName);
            return k < 0 ? null : jointBones[k];
        }

        void Start()
        {
            if (!Initialize()) enabled = false;
        }

        void LateUpdate()
        {
            if (math != null) Evaluate();
        }

        /// <summary>Finds bones and blend shapes and records the rest pose. Safe to call again.</summary>
        public bool Initialize()
        {
            math = null;
            Messages.Clear();
            skin = GetComponent<SkinnedMeshRenderer>();
            if (skin == null || skin.sharedMesh == null) return Fail(name + ": SmplCorrectives needs a SkinnedMeshRenderer with a mesh");
            string error = null;
            layout = sidecar != null ? SidecarLayout.Parse(sidecar.text, sidecar.name, out error)
                                     : SidecarLayout.DefaultSmpl();
            if (layout == null) return Fail(error);
            var created = CorrectiveMath.Create(layout.Parents, AxisMap(), out error);
            if (created == null) return Fail(name + ": " + error);
            FindBones(created);
            CaptureRest(created);
            BindBlendShapes();
            current = new Quat[created.JointCount];
            features = new double[created.FeatureCount];
            math = created;
            foreach (string m in Messages) Debug.LogWarning(m, this);
            return true;
        }

        /// <summary>Reads the bones and sets the blend shape weights (called from LateUpdate).</summary>
        public void Evaluate()
        {
            Quat meshInverse = ToQuat(skin.transform.rotation).Inverse();
            for (int k = 0; k < jointBones.Length; ++k)
                if (jointBones[k] != null) current[k] = meshInverse * ToQuat(jointBones[k].rotation);
            math.Compute(current, features);
            for (int i = 0; i < shapeIndex.Length; ++i)
            {
                double f = features[shapeFeature[i]];
                skin.SetBlendShapeWeight(shapeIndex[i],
                    (float)(100.0 * CorrectiveMath.Weight(f, shapeScale[i], shapeOffset[i], shapeRectified[i])));
            }
            if (basisRow.Length == 0) return;
            CorrectiveMath.ProjectBasis(layout.Basis, basisRow, features, basisWeights);
            for (int i = 0; i < basisRow.Length; ++i)
                skin.SetBlendShapeWeight(basisShapeIndex[i], (float)(100.0 * basisWeights[i]));
        }

        /// <summary>Sets the weights of the corrective (and basis) blend shapes this component drives to 0, e.g. to compare with plain skinning; other blend shapes keep theirs.</summary>
        public void ClearWeights()
        {
            if (math == null) return;
            foreach (int i in shapeIndex) skin.SetBlendShapeWeight(i, 0f);
            foreach (int i in basisShapeIndex) skin.SetBlendShapeWeight(i, 0f);
        }

        bool Fail(string message)
        {
            Messages.Add(message);
            Debug.LogError(message, this);
            return false;
        }

        double[] AxisMap()
        {
            switch (axisConvention)
            {
                case AxisConvention.MirrorZ: return CorrectiveMath.MirrorZ;
                case AxisConvention.Identity: return CorrectiveMath.IdentityMap;
                case AxisConvention.Custom:
                    return new double[] {
                        customModelX.x, customModelY.x, customModelZ.x,
                        customModelX.y, customModelY.y, customModelZ.y,
                        customModelX.z, customModelY.z, customModelZ.z };
                default: return CorrectiveMath.MirrorX;
            }
        }

        // Candidates: the renderer's bones first (they have bind poses), then
        // every transform under the skeleton root.
        void FindBones(CorrectiveMath target)
        {
            var candidates = new List<Transform>();
            var seen = new HashSet<Transform>();
            if (skin.bones != null)
                foreach (Transform b in skin.bones)
                    if (b != null && seen.Add(b)) candidates.Add(b);
            var stack = new Stack<Transform>();
            stack.Push(skeletonRoot != null ? skeletonRoot : (transform.parent != null ? transform.parent : transform));
            while (stack.Count > 0)
            {
                Transform t = stack.Pop();
                if (seen.Add(t)) candidates.Add(t);
                for (int i = t.childCount - 1; i >= 0; --i) stack.Push(t.GetChild(i));
            }
            var names = new List<string>(candidates.Count);
            foreach (Transform t in candidates) names.Add(t.name);
            // --skeleton-names: the bones are named by the metadata's bone_names
            int[] match = NameMatch.Assign(layout.BoneNames ?? layout.JointNames, names);
            jointBones = new Transform[match.Length];
            var missing = new List<string>();
            for (int k = 0; k < match.Length; ++k)
            {
                jointBones[k] = match[k] >= 0 ? candidates[match[k]] : null;
                if (jointBones[k] == null)
                {
                    target.SetMissing(k);
                    missing.Add(layout.JointNames[k]);
                }
            }
            if (missing.Count > 0)
                Messages.Add(name + ": no bone for joint(s) " + string.Join(", ", missing.ToArray()) +
                             "; treated as rigidly attached to their parents");
        }

        void CaptureRest(CorrectiveMath target)
        {
            var boneIndex = new Dictionary<Transform, int>();
            Transform[] bones = skin.bones ?? new Transform[0];
            for (int i = 0; i < bones.Length; ++i)
                if (bones[i] != null && !boneIndex.ContainsKey(bones[i])) boneIndex[bones[i]] = i;
            Matrix4x4[] bindposes = restPose == RestPoseSource.BindPoses ? skin.sharedMesh.bindposes : new Matrix4x4[0];
            Quat meshInverse = ToQuat(skin.transform.rotation).Inverse();
            int fromStart = 0;
            for (int k = 0; k < jointBones.Length; ++k)
            {
                if (jointBones[k] == null) continue;
                int i;
                if (boneIndex.TryGetValue(jointBones[k], out i) && i < bindposes.Length)
                {
                    target.SetRest(k, RotationOf(bindposes[i]).Inverse());
                    continue;
                }
                target.SetRest(k, meshInverse * ToQuat(jointBones[k].rotation));
                ++fromStart;
            }
            if (restPose == RestPoseSource.BindPoses && fromStart > 0)
                Messages.Add(name + ": " + fromStart + " bone(s) have no bind pose; their rest rotation is taken at Start");
        }

        void BindBlendShapes()
        {
            Mesh mesh = skin.sharedMesh;
            var shapeNames = new List<string>(mesh.blendShapeCount);
            for (int i = 0; i < mesh.blendShapeCount; ++i) shapeNames.Add(mesh.GetBlendShapeName(i));
            var targets = new List<string>(layout.Correctives.Length);
            foreach (CorrectiveBinding b in layout.Correctives) targets.Add(b.Target);
            int[] match = NameMatch.Assign(targets, shapeNames);
            int found = 0;
            foreach (int m in match) if (m >= 0) ++found;
            shapeIndex = new int[found];
            shapeFeature = new int[found];
            shapeScale = new double[found];
            shapeOffset = new double[found];
            shapeRectified = new bool[found];
            int n = 0;
            for (int c = 0; c < match.Length; ++c)
            {
                if (match[c] < 0) continue;
                shapeIndex[n] = match[c];
                shapeFeature[n] = layout.Correctives[c].Feature;
                shapeScale[n] = layout.Correctives[c].Scale;
                shapeOffset[n] = layout.Correctives[c].Offset;
                shapeRectified[n] = layout.Correctives[c].Rectified;
                ++n;
            }
            if (found < match.Length)
                Messages.Add(name + ": mesh '" + mesh.name + "' lacks " + (match.Length - found) + " of " + match.Length +
                             " corrective blend shapes (first missing: " + FirstMissing(match) + ")");
            BindBasisShapes(shapeNames);
        }

        void BindBasisShapes(List<string> shapeNames)
        {
            var index = new List<int>();
            var rows = new List<int>();
            if (layout.Basis != null)
            {
                int[] match = NameMatch.Assign(layout.Basis.Targets, shapeNames);
                for (int r = 0; r < match.Length; ++r)
                    if (match[r] >= 0)
                    {
                        index.Add(match[r]);
                        rows.Add(r);
                    }
                if (rows.Count < match.Length)
                    Messages.Add(name + ": mesh '" + skin.sharedMesh.name + "' lacks " + (match.Length - rows.Count) + " of " +
                                 match.Length + " corrective basis blend shapes");
            }
            basisShapeIndex = index.ToArray();
            basisRow = rows.ToArray();
            basisWeights = new double[rows.Count];
        }

        string FirstMissing(int[] match)
        {
            for (int c = 0; c < match.Length; ++c)
                if (match[c] < 0) return layout.Correctives[c].Target;
            return "";
        }

        static Quat ToQuat(Quaternion q) { return new Quat(q.x, q.y, q.z, q.w); }

        static Quat RotationOf(Matrix4x4 m)
        {
            return Quat.FromMatrix(new double[] { m.m00, m.m01, m.m02, m.m10, m.m11, m.m12, m.m20, m.m21, m.m22 });
        }
    }
}
