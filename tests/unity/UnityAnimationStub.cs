// The UnityEngine animation types the Humanoid setup (unity/Runtime/SmplHumanoid.cs)
// uses, hand-written so it compiles and runs under mono without Unity.
// Names, fields and the enum's values follow Unity's scripting reference
// (HumanBodyBones, HumanTrait.BoneName: the same order; HumanTrait.RequiredBone:
// the 15 bones Mecanim needs). AvatarBuilder.BuildHumanAvatar checks what the
// Humanoid documentation asks of a rig, and returns an invalid avatar (with an
// error logged, as Unity) when a check fails:
//   - every humanName is one of HumanTrait.BoneName, at most once;
//   - every boneName names exactly one transform under the root (Unity maps by name);
//   - every required bone is mapped;
//   - a mapped bone's nearest mapped ancestor in Unity's human template is its
//     ancestor in the transform hierarchy (e.g. LeftLowerLeg below LeftUpperLeg);
//   - every mapped transform and its ancestors up to the root have a SkeletonBone;
//   - a mapped bone is not at its human parent's position (rest pose from the SkeletonBones).
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public enum HumanBodyBones
    {
        Hips = 0, LeftUpperLeg, RightUpperLeg, LeftLowerLeg, RightLowerLeg, LeftFoot, RightFoot, Spine, Chest, Neck, Head,
        LeftShoulder, RightShoulder, LeftUpperArm, RightUpperArm, LeftLowerArm, RightLowerArm, LeftHand, RightHand,
        LeftToes, RightToes, LeftEye, RightEye, Jaw,
        LeftThumbProximal, LeftThumbIntermediate, LeftThumbDistal, LeftIndexProximal, LeftIndexIntermediate,
        LeftIndexDistal, LeftMiddleProximal, LeftMiddleIntermediate, LeftMiddleDistal, LeftRingProximal,
        LeftRingIntermediate, LeftRingDistal, LeftLittleProximal, LeftLittleIntermediate, LeftLittleDistal,
        RightThumbProximal, RightThumbIntermediate, RightThumbDistal, RightIndexProximal, RightIndexIntermediate,
        RightIndexDistal, RightMiddleProximal, RightMiddleIntermediate, RightMiddleDistal, RightRingProximal,
        RightRingIntermediate, RightRingDistal, RightLittleProximal, RightLittleIntermediate, RightLittleDistal,
        UpperChest, LastBone
    }

    public static class HumanTrait
    {
        public static readonly string[] BoneName = MakeNames();
        public static int BoneCount { get { return (int)HumanBodyBones.LastBone; } }

        static readonly HumanBodyBones[] Required =
        {
            HumanBodyBones.Hips, HumanBodyBones.LeftUpperLeg, HumanBodyBones.RightUpperLeg, HumanBodyBones.LeftLowerLeg,
            HumanBodyBones.RightLowerLeg, HumanBodyBones.LeftFoot, HumanBodyBones.RightFoot, HumanBodyBones.Spine,
            HumanBodyBones.Head, HumanBodyBones.LeftUpperArm, HumanBodyBones.RightUpperArm, HumanBodyBones.LeftLowerArm,
            HumanBodyBones.RightLowerArm, HumanBodyBones.LeftHand, HumanBodyBones.RightHand
        };

        public static bool RequiredBone(int i) { return Array.IndexOf(Required, (HumanBodyBones)i) >= 0; }
        public static int RequiredBoneCount { get { return Required.Length; } }

        /// <summary>The bone's parent in Unity's human template; -1 for Hips.</summary>
        public static int GetParentBone(int i)
        {
            var b = (HumanBodyBones)i;
            switch (b)
            {
                case HumanBodyBones.Hips: return -1;
                case HumanBodyBones.LeftUpperLeg: case HumanBodyBones.RightUpperLeg: case HumanBodyBones.Spine: return 0;
                case HumanBodyBones.LeftLowerLeg: return (int)HumanBodyBones.LeftUpperLeg;
                case HumanBodyBones.RightLowerLeg: return (int)HumanBodyBones.RightUpperLeg;
                case HumanBodyBones.LeftFoot: return (int)HumanBodyBones.LeftLowerLeg;
                case HumanBodyBones.RightFoot: return (int)HumanBodyBones.RightLowerLeg;
                case HumanBodyBones.LeftToes: return (int)HumanBodyBones.LeftFoot;
                case HumanBodyBones.RightToes: return (int)HumanBodyBones.RightFoot;
                case HumanBodyBones.Chest: return (int)HumanBodyBones.Spine;
                case HumanBodyBones.UpperChest: return (int)HumanBodyBones.Chest;
                case HumanBodyBones.Neck: case HumanBodyBones.LeftShoulder: case HumanBodyBones.RightShoulder:
                    return (int)HumanBodyBones.UpperChest;
                case HumanBodyBones.Head: return (int)HumanBodyBones.Neck;
                case HumanBodyBones.LeftEye: case HumanBodyBones.RightEye: case HumanBodyBones.Jaw:
                    return (int)HumanBodyBones.Head;
                case HumanBodyBones.LeftUpperArm: return (int)HumanBodyBones.LeftShoulder;
                case HumanBodyBones.RightUpperArm: return (int)HumanBodyBones.RightShoulder;
                case HumanBodyBones.LeftLowerArm: return (int)HumanBodyBones.LeftUpperArm;
                case HumanBodyBones.RightLowerArm: return (int)HumanBodyBones.RightUpperArm;
                case HumanBodyBones.LeftHand: return (int)HumanBodyBones.LeftLowerArm;
                case HumanBodyBones.RightHand: return (int)HumanBodyBones.RightLowerArm;
            }
            if (b >= HumanBodyBones.LeftThumbProximal && b <= HumanBodyBones.RightLittleDistal)
            {
                int phalanx = (i - (int)HumanBodyBones.LeftThumbProximal) % 3;
                if (phalanx > 0) return i - 1;
                return (int)(b < HumanBodyBones.RightThumbProximal ? HumanBodyBones.LeftHand : HumanBodyBones.RightHand);
            }
            return -1;
        }

        static string[] MakeNames()
        {
            var names = new string[(int)HumanBodyBones.LastBone];
            string[] fingers = { "Thumb", "Index", "Middle", "Ring", "Little" };
            string[] phalanges = { "Proximal", "Intermediate", "Distal" };
            for (int i = 0; i < names.Length; ++i)
            {
                var b = (HumanBodyBones)i;
                if (b >= HumanBodyBones.LeftThumbProximal && b <= HumanBodyBones.RightLittleDistal)
                {
                    int k = i - (int)HumanBodyBones.LeftThumbProximal;
                    names[i] = (k < 15 ? "Left " : "Right ") + fingers[(k % 15) / 3] + " " + phalanges[k % 3];
                }
                else
                {
                    names[i] = b.ToString();
                }
            }
            return names;
        }
    }

    public struct HumanLimit
    {
        public bool useDefaultValues;
        public Vector3 min, max, center;
        public float axisLength;
    }

    public struct HumanBone
    {
        public string boneName;
        public string humanName;
        public HumanLimit limit;
    }

    public struct SkeletonBone
    {
        public string name;
        public Vector3 position;
        public Quaternion rotation;
        public Vector3 scale;
    }

    public struct HumanDescription
    {
        public HumanBone[] human;
        public SkeletonBone[] skeleton;
        public float upperArmTwist, lowerArmTwist, upperLegTwist, lowerLegTwist, armStretch, legStretch, feetSpacing;
        public bool hasTranslationDoF;
    }

    public class Avatar : Object
    {
        public bool isValid { get; internal set; }
        public bool isHuman { get; internal set; }
        /// <summary>The description it was built from (Unity: Avatar.humanDescription).</summary>
        public HumanDescription humanDescription { get; internal set; }
    }

    public class Animator : Behaviour
    {
        public Avatar avatar;
    }

    public static class AvatarBuilder
    {
        public static Avatar BuildHumanAvatar(GameObject go, HumanDescription description)
        {
            string problem = Check(go, description);
            if (problem != null) Debug.LogError("AvatarBuilder: " + problem, go);
            return new Avatar { isValid = problem == null, isHuman = problem == null, humanDescription = description };
        }

        static string Check(GameObject go, HumanDescription d)
        {
            if (go == null || d.human == null || d.skeleton == null) return "no root or no description";
            var byName = new Dictionary<string, List<Transform>>();
            Index(go.transform, byName);
            var mapped = new Dictionary<int, Transform>();
            foreach (HumanBone h in d.human)
            {
                int bone = Array.IndexOf(HumanTrait.BoneName, h.humanName);
                if (bone < 0) return "unknown human bone '" + h.humanName + "'";
                if (mapped.ContainsKey(bone)) return h.humanName + " is mapped twice";
                List<Transform> found;
                if (h.boneName == null || !byName.TryGetValue(h.boneName, out found)) return "no transform '" + h.boneName + "'";
                if (found.Count != 1) return found.Count + " transforms are named '" + h.boneName + "'";
                mapped[bone] = found[0];
            }
            for (int i = 0; i < HumanTrait.BoneCount; ++i)
                if (HumanTrait.RequiredBone(i) && !mapped.ContainsKey(i)) return "required bone " + HumanTrait.BoneName[i] + " not mapped";
            var skeleton = new Dictionary<string, SkeletonBone>();
            foreach (SkeletonBone s in d.skeleton)
                if (s.name != null) skeleton[s.name] = s;
            foreach (var kv in mapped)
            {
                for (Transform t = kv.Value; t != null; t = t == go.transform ? null : t.parent)
                    if (!skeleton.ContainsKey(t.name)) return "no SkeletonBone for '" + t.name + "'";
                int parent = HumanTrait.GetParentBone(kv.Key);
                while (parent >= 0 && !mapped.ContainsKey(parent)) parent = HumanTrait.GetParentBone(parent);
                if (parent < 0) continue;
                if (!IsAncestor(mapped[parent], kv.Value))
                    return HumanTrait.BoneName[kv.Key] + " ('" + kv.Value.name + "') is not below " +
                           HumanTrait.BoneName[parent] + " ('" + mapped[parent].name + "')";
                if ((RestPosition(kv.Value, go.transform, skeleton) - RestPosition(mapped[parent], go.transform, skeleton)).magnitude < 1e-5f)
                    return HumanTrait.BoneName[kv.Key] + " has zero length";
            }
            return null;
        }

        static void Index(Transform t, Dictionary<string, List<Transform>> byName)
        {
            List<Transform> list;
            if (!byName.TryGetValue(t.name, out list)) byName[t.name] = list = new List<Transform>();
            list.Add(t);
            for (int i = 0; i < t.childCount; ++i) Index(t.GetChild(i), byName);
        }

        static bool IsAncestor(Transform ancestor, Transform t)
        {
            for (Transform p = t.parent; p != null; p = p.parent)
                if (p == ancestor) return true;
            return false;
        }

        // Position in the root's space from the SkeletonBones' local positions and rotations (unit scale).
        static Vector3 RestPosition(Transform t, Transform root, Dictionary<string, SkeletonBone> skeleton)
        {
            var chain = new List<SkeletonBone>();
            for (Transform p = t; p != null && p != root; p = p.parent) chain.Add(skeleton[p.name]);
            Vector3 position = new Vector3(0, 0, 0);
            Quaternion rotation = Quaternion.identity;
            for (int i = chain.Count - 1; i >= 0; --i)
            {
                position = position + rotation * chain[i].position;
                rotation = rotation * chain[i].rotation;
            }
            return position;
        }
    }
}
