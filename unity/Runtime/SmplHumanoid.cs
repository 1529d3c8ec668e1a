// A Mecanim Humanoid Avatar for an imported SMPL, SMPL-H or SMPL-X body, so
// Humanoid animation clips retarget onto it. The mapping from the models'
// joint names (the authors' names, as smpl-export writes them) to Unity's
// HumanBodyBones is the table of docs/file-contract.md, "Unity Humanoid
// mapping"; a test keeps the two equal.
//
// Bones are found by name under the given root (NameMatch: exact first, then
// decorated names such as "Armature|pelvis"), so a joint named "root" above
// pelvis (smpl-export --root-bone) is simply part of the skeleton. With the
// exporter's metadata (a SidecarLayout) of a --skeleton-names mixamo|ue5
// export, each joint is looked up by its bone's name (bone_names) instead.
// MANO (a hand without a body) has no Humanoid avatar.
using System;
using System.Collections.Generic;
using UnityEngine;

namespace SmplExport.Correctives
{
    public static class SmplHumanoid
    {
        /// <summary>One row of the mapping: a model joint and the human bone it becomes.</summary>
        public struct Entry
        {
            public readonly string Joint;
            public readonly HumanBodyBones Bone;
            public Entry(string joint, HumanBodyBones bone) { Joint = joint; Bone = bone; }
        }

        /// <summary>
        /// Model joint -> HumanBodyBones, in the models' joint order: the body
        /// (all kinds), jaw and eyes (SMPL-X), the fingers (SMPL-H, SMPL-X).
        /// SMPL's left_hand/right_hand (knuckle end joints) have no human bone.
        /// </summary>
        public static readonly Entry[] Table = BuildTable();

        static Entry[] BuildTable()
        {
            var t = new List<Entry>
            {
                new Entry("pelvis", HumanBodyBones.Hips),
                new Entry("left_hip", HumanBodyBones.LeftUpperLeg),
                new Entry("right_hip", HumanBodyBones.RightUpperLeg),
                new Entry("spine1", HumanBodyBones.Spine),
                new Entry("left_knee", HumanBodyBones.LeftLowerLeg),
                new Entry("right_knee", HumanBodyBones.RightLowerLeg),
                new Entry("spine2", HumanBodyBones.Chest),
                new Entry("left_ankle", HumanBodyBones.LeftFoot),
                new Entry("right_ankle", HumanBodyBones.RightFoot),
                new Entry("spine3", HumanBodyBones.UpperChest),
                new Entry("left_foot", HumanBodyBones.LeftToes),
                new Entry("right_foot", HumanBodyBones.RightToes),
                new Entry("neck", HumanBodyBones.Neck),
                new Entry("left_collar", HumanBodyBones.LeftShoulder),
                new Entry("right_collar", HumanBodyBones.RightShoulder),
                new Entry("head", HumanBodyBones.Head),
                new Entry("left_shoulder", HumanBodyBones.LeftUpperArm),
                new Entry("right_shoulder", HumanBodyBones.RightUpperArm),
                new Entry("left_elbow", HumanBodyBones.LeftLowerArm),
                new Entry("right_elbow", HumanBodyBones.RightLowerArm),
                new Entry("left_wrist", HumanBodyBones.LeftHand),
                new Entry("right_wrist", HumanBodyBones.RightHand),
                new Entry("jaw", HumanBodyBones.Jaw),
                new Entry("left_eye_smplhf", HumanBodyBones.LeftEye),
                new Entry("right_eye_smplhf", HumanBodyBones.RightEye),
            };
            // The models' finger order (index, middle, pinky, ring, thumb); 1..3 = proximal..distal.
            string[] fingers = { "index", "middle", "pinky", "ring", "thumb" };
            HumanBodyBones[] left = { HumanBodyBones.LeftIndexProximal, HumanBodyBones.LeftMiddleProximal,
                                      HumanBodyBones.LeftLittleProximal, HumanBodyBones.LeftRingProximal,
                                      HumanBodyBones.LeftThumbProximal };
            HumanBodyBones[] right = { HumanBodyBones.RightIndexProximal, HumanBodyBones.RightMiddleProximal,
                                       HumanBodyBones.RightLittleProximal, HumanBodyBones.RightRingProximal,
                                       HumanBodyBones.RightThumbProximal };
            foreach (var side in new[] { "left_", "right_" })
                for (int f = 0; f < fingers.Length; ++f)
                    for (int s = 0; s < 3; ++s)
                    {
                        HumanBodyBones proximal = side == "left_" ? left[f] : right[f];
                        t.Add(new Entry(side + fingers[f] + (s + 1), (HumanBodyBones)((int)proximal + s)));
                    }
            return t.ToArray();
        }

        /// <summary>The human bone of a model joint name (exact name); false if the joint has none.</summary>
        public static bool TryGetBone(string joint, out HumanBodyBones bone)
        {
            foreach (Entry e in Table)
                if (e.Joint == joint) { bone = e.Bone; return true; }
            bone = HumanBodyBones.LastBone;
            return false;
        }

        /// <summary>
        /// The HumanDescription of the body under root: a HumanBone for every
        /// table joint found (boneName = the transform's own, possibly
        /// decorated, name), a SkeletonBone (local position in metres as
        /// imported, local rotation, scale) for root and every transform below
        /// it, and Unity's importer defaults for twist, stretch and feet
        /// spacing. The body must be in its rest pose (SMPL's T-pose, as
        /// imported). layout: the export's metadata (sidecar or the glTF's
        /// asset.extras.smpl); with bone_names (--skeleton-names mixamo|ue5)
        /// joint k's transform is found by bone_names[k]; null or without
        /// bone_names, by the joint's own name. Returns null, with one line in
        /// error naming the missing joints, if a bone Unity requires
        /// (HumanTrait.RequiredBone) is not found.
        /// </summary>
        public static HumanDescription? Describe(Transform root, out string error, SidecarLayout layout = null)
        {
            error = null;
            if (root == null)
            {
                error = "SmplHumanoid: no root transform";
                return null;
            }
            var transforms = new List<Transform>();
            Collect(root, transforms);
            var names = new List<string>(transforms.Count);
            foreach (Transform t in transforms) names.Add(t.name);
            var wanted = new List<string>(Table.Length);
            foreach (Entry e in Table) wanted.Add(BoneNameOf(e.Joint, layout));
            int[] match = NameMatch.Assign(wanted, names);

            var human = new List<HumanBone>();
            var missing = new List<string>();
            for (int i = 0; i < Table.Length; ++i)
            {
                if (match[i] < 0)
                {
                    if (HumanTrait.RequiredBone((int)Table[i].Bone))
                        missing.Add(wanted[i] == Table[i].Joint ? wanted[i] : Table[i].Joint + " (" + wanted[i] + ")");
                    continue;
                }
                var bone = new HumanBone
                {
                    boneName = names[match[i]],
                    humanName = HumanTrait.BoneName[(int)Table[i].Bone],
                };
                bone.limit.useDefaultValues = true;
                human.Add(bone);
            }
            if (missing.Count > 0)
            {
                error = root.name + ": not an SMPL, SMPL-H or SMPL-X body: no bone for required joint(s) " +
                        string.Join(", ", missing.ToArray());
                return null;
            }
            var skeleton = new SkeletonBone[transforms.Count];
            for (int i = 0; i < transforms.Count; ++i)
                skeleton[i] = new SkeletonBone
                {
                    name = transforms[i].name,
                    position = transforms[i].localPosition,
                    rotation = transforms[i].localRotation,
                    scale = transforms[i].localScale,
                };
            return new HumanDescription
            {
                human = human.ToArray(),
                skeleton = skeleton,
                upperArmTwist = 0.5f,
                lowerArmTwist = 0.5f,
                upperLegTwist = 0.5f,
                lowerLegTwist = 0.5f,
                armStretch = 0.05f,
                legStretch = 0.05f,
                feetSpacing = 0f,
                hasTranslationDoF = false,
            };
        }

        /// <summary>
        /// Builds the Humanoid Avatar of the body under root
        /// (AvatarBuilder.BuildHumanAvatar with Describe's description) and
        /// names it "&lt;root&gt; Avatar". Returns null with a one-line error if
        /// a required joint is missing or Unity reports the avatar invalid or
        /// not human. layout as in Describe. Does not assign it: see Apply.
        /// </summary>
        public static Avatar Build(GameObject root, out string error, SidecarLayout layout = null)
        {
            HumanDescription? description = Describe(root == null ? null : root.transform, out error, layout);
            if (description == null) return null;
            Avatar avatar = AvatarBuilder.BuildHumanAvatar(root, description.Value);
            if (avatar == null || !avatar.isValid || !avatar.isHuman)
            {
                error = root.name + ": Unity rejected the Humanoid avatar (see the console for AvatarBuilder's reason)";
                return null;
            }
            avatar.name = root.name + " Avatar";
            return avatar;
        }

        /// <summary>Builds the avatar (Build) and sets it on root's Animator, adding one if there is none. Returns null and an error on failure.</summary>
        public static Avatar Apply(GameObject root, out string error, SidecarLayout layout = null)
        {
            Avatar avatar = Build(root, out error, layout);
            if (avatar == null) return null;
            Animator animator = root.GetComponent<Animator>();
            if (animator == null) animator = root.AddComponent<Animator>();  // not ??: Unity overloads == null
            animator.avatar = avatar;
            return avatar;
        }

        // The name of joint's bone: bone_names[k] of the metadata's joint k, else the joint's own.
        static string BoneNameOf(string joint, SidecarLayout layout)
        {
            if (layout == null || layout.BoneNames == null) return joint;
            int k = Array.IndexOf(layout.JointNames, joint);
            return k < 0 ? joint : layout.BoneNames[k];
        }

        // Depth first, root first (the order of SkeletonBone entries Unity's importer writes).
        static void Collect(Transform t, List<Transform> into)
        {
            into.Add(t);
            for (int i = 0; i < t.childCount; ++i) Collect(t.GetChild(i), into);
        }
    }
}
