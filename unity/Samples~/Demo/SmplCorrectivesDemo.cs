// Demo of the SMPL Export Correctives package: put it on an imported
// smpl-export body in a scene (GLB through a glTF importer such as glTFast,
// or FBX), press Play, and a few joints bend back and forth procedurally
// while SmplCorrectives drives the pose-corrective blend shapes. Untick
// "Correctives" during Play to see plain linear blend skinning (weights 0).
//
// Bending: each joint turns about the character's left-right axis, in the
// joint's own rest frame, by amplitude * sin(2 pi cycles t + phase). That is
// no anatomical animation (a knee may bend forwards); it only has to move the
// joints far enough for the correctives to show at knees, elbows and hips.
using System.Collections.Generic;
using UnityEngine;

namespace SmplExport.Correctives.Samples
{
    [AddComponentMenu("SMPL Export/SMPL Correctives Demo")]
    [DefaultExecutionOrder(500)]  // after the Animator, before SmplCorrectives (1000)
    public sealed class SmplCorrectivesDemo : MonoBehaviour
    {
        [Tooltip("The imported body in the scene. Empty: this GameObject.")]
        public GameObject body;
        [Tooltip("The exporter's <file>.smpl.json next to the model; used if the body has no SmplCorrectives yet. Empty: SMPL's 24-joint layout.")]
        public TextAsset sidecar;
        [Tooltip("Joints to bend, by the model's joint names (the sidecar's joint_names).")]
        public string[] joints = { "left_knee", "right_knee", "left_elbow", "right_elbow", "left_hip", "spine1" };
        [Range(0f, 150f)]
        public float amplitudeDegrees = 70f;
        public float cyclesPerSecond = 0.25f;
        [Tooltip("Off: corrective weights are held at 0 (plain linear blend skinning), to compare.")]
        public bool correctives = true;

        SmplCorrectives driver;
        readonly List<Transform> bones = new List<Transform>();
        readonly List<Quaternion> restLocal = new List<Quaternion>();
        readonly List<Vector3> bendAxis = new List<Vector3>();   // in each bone's rest frame

        void Start()
        {
            GameObject root = body != null ? body : gameObject;
            driver = root.GetComponentInChildren<SmplCorrectives>(true);
            if (driver == null)
            {
                SkinnedMeshRenderer skin = BodyRenderer(root);
                if (skin == null)
                {
                    Debug.LogError(root.name + ": no SkinnedMeshRenderer with blend shapes below it; is this an smpl-export body?", this);
                    enabled = false;
                    return;
                }
                driver = skin.gameObject.AddComponent<SmplCorrectives>();
                driver.sidecar = sidecar;
            }
            // Start order between components is not defined: make sure the driver is ready now.
            if (!driver.IsReady && !driver.Initialize())
            {
                enabled = false;
                return;
            }
            Vector3 leftRight = driver.transform.rotation * Vector3.right;  // model X, in world space
            foreach (string joint in joints)
            {
                Transform bone = driver.BoneForJoint(joint);
                if (bone == null)
                {
                    Debug.LogWarning(root.name + ": no bone for joint '" + joint + "'; not animated", this);
                    continue;
                }
                bones.Add(bone);
                restLocal.Add(bone.localRotation);
                bendAxis.Add(Quaternion.Inverse(bone.rotation) * leftRight);
            }
        }

        void LateUpdate()
        {
            for (int i = 0; i < bones.Count; ++i)
            {
                float phase = 2f * Mathf.PI * (cyclesPerSecond * Time.time + 0.15f * i);
                bones[i].localRotation = restLocal[i] * Quaternion.AngleAxis(amplitudeDegrees * Mathf.Sin(phase), bendAxis[i]);
            }
            if (driver == null) return;
            driver.enabled = correctives;
            if (!correctives) driver.ClearWeights();
        }

        // The renderer with the most blend shapes: the body (an export has one mesh).
        static SkinnedMeshRenderer BodyRenderer(GameObject root)
        {
            SkinnedMeshRenderer best = null;
            foreach (SkinnedMeshRenderer skin in root.GetComponentsInChildren<SkinnedMeshRenderer>(true))
                if (skin.sharedMesh != null && skin.sharedMesh.blendShapeCount > 0 &&
                    (best == null || skin.sharedMesh.blendShapeCount > best.sharedMesh.blendShapeCount))
                    best = skin;
            return best;
        }
    }
}
