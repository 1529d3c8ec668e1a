// Editor setup of SmplCorrectives on an imported smpl-export body: the
// component goes on every SkinnedMeshRenderer under the selected scene
// objects that has blend shapes, with the sidecar <model file>.smpl.json found
// next to the model asset the object was instantiated from (Unity imports
// .json files as TextAssets). Menu: Tools > SMPL > Add Correctives to Selection.
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace SmplExport.Correctives.Editor
{
    public static class CorrectivesSetup
    {
        public const string MenuPath = "Tools/SMPL/Add Correctives to Selection";
        public const string SidecarSuffix = ".smpl.json";

        /// <summary>Asset path of the exporter's sidecar for a model asset path ("Assets/body.glb" -> "Assets/body.glb.smpl.json").</summary>
        public static string SidecarPathFor(string modelAssetPath)
        {
            return string.IsNullOrEmpty(modelAssetPath) ? null : modelAssetPath + SidecarSuffix;
        }

        /// <summary>The sidecar next to the model asset a scene object comes from; null if there is none.</summary>
        public static TextAsset FindSidecar(GameObject sceneObject, out string modelPath)
        {
            modelPath = PrefabUtility.GetPrefabAssetPathOfNearestInstanceRoot(sceneObject);
            string path = SidecarPathFor(modelPath);
            return path == null ? null : AssetDatabase.LoadAssetAtPath<TextAsset>(path);
        }

        /// <summary>
        /// Adds SmplCorrectives (with Undo) to each renderer under root that has
        /// blend shapes and no SmplCorrectives yet, assigning the sidecar (may be
        /// null: SMPL's default layout). Returns the components added.
        /// </summary>
        public static List<SmplCorrectives> AddTo(GameObject root, TextAsset sidecar)
        {
            var added = new List<SmplCorrectives>();
            foreach (SkinnedMeshRenderer skin in root.GetComponentsInChildren<SkinnedMeshRenderer>(true))
            {
                if (skin.sharedMesh == null || skin.sharedMesh.blendShapeCount == 0) continue;
                if (skin.GetComponent<SmplCorrectives>() != null) continue;
                var driver = Undo.AddComponent<SmplCorrectives>(skin.gameObject);
                Undo.RecordObject(driver, "Assign SMPL sidecar");
                driver.sidecar = sidecar;
                EditorUtility.SetDirty(driver);
                added.Add(driver);
            }
            return added;
        }

        [MenuItem(MenuPath, true)]
        static bool CanAddToSelection()
        {
            foreach (GameObject go in Selection.gameObjects)
                if (!EditorUtility.IsPersistent(go)) return true;
            return false;
        }

        [MenuItem(MenuPath, false)]
        static void AddToSelection()
        {
            foreach (GameObject go in Selection.gameObjects)
            {
                if (EditorUtility.IsPersistent(go)) continue;  // a model asset, not a scene object
                string modelPath;
                TextAsset sidecar = FindSidecar(go, out modelPath);
                List<SmplCorrectives> added = AddTo(go, sidecar);
                if (added.Count == 0)
                    Debug.LogWarning(go.name + ": no SkinnedMeshRenderer with blend shapes and without SmplCorrectives below it", go);
                else if (sidecar == null)
                    Debug.LogWarning(go.name + ": no sidecar " + (SidecarPathFor(modelPath) ?? "(not a model instance)") +
                                     "; SmplCorrectives uses SMPL's 24-joint layout (assign the sidecar by hand for SMPL-H, SMPL-X, MANO)", go);
                else
                    Debug.Log(go.name + ": SmplCorrectives added to " + added.Count + " renderer(s) with sidecar " +
                              AssetDatabase.GetAssetPath(sidecar), go);
            }
            if (PlayerSettings.legacyClampBlendShapeWeights)
                Debug.LogWarning("Player setting 'Clamp BlendShapes (Deprecated)' (legacyClampBlendShapeWeights) is on: " +
                                 "negative corrective weights will be clamped to 0; turn it off (see the package README)");
        }
    }
}
