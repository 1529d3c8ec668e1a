// Editor setup of a Humanoid Avatar on an imported smpl-export body (SMPL,
// SMPL-H, SMPL-X): builds it with SmplHumanoid (the mapping table of
// docs/file-contract.md), saves it as an asset next to the model and assigns
// it to the object's Animator (added if missing). Works for glTF (glTFast,
// UniGLTF) and FBX bodies alike, since it reads the scene object's
// transforms, not an importer. A --skeleton-names mixamo|ue5 body is mapped
// through its sidecar's bone_names (<model file>.smpl.json, found as
// CorrectivesSetup finds it). Menu: Tools > SMPL > Create Humanoid Avatar for Selection.
using UnityEditor;
using UnityEngine;

namespace SmplExport.Correctives.Editor
{
    public static class HumanoidSetup
    {
        public const string MenuPath = "Tools/SMPL/Create Humanoid Avatar for Selection";
        public const string AvatarSuffix = ".avatar.asset";

        /// <summary>
        /// Where the avatar asset goes: next to a model under Assets/
        /// ("Assets/body.fbx" -> "Assets/body.fbx.avatar.asset"), else (a
        /// package or no model) "Assets/&lt;object name&gt;.avatar.asset".
        /// </summary>
        public static string AvatarPathFor(string modelAssetPath, string objectName)
        {
            if (!string.IsNullOrEmpty(modelAssetPath) && modelAssetPath.StartsWith("Assets/"))
                return modelAssetPath + AvatarSuffix;
            return "Assets/" + objectName + AvatarSuffix;
        }

        /// <summary>
        /// Builds the Humanoid avatar of the body under root, sets it on root's
        /// Animator (with Undo) and, if assetPath is not null, saves it there.
        /// layout: the body's metadata (its bone_names map renamed bones), or
        /// null. Returns the avatar, or null with a one-line error.
        /// </summary>
        public static Avatar CreateFor(GameObject root, string assetPath, out string error, SidecarLayout layout = null)
        {
            Avatar avatar = SmplHumanoid.Build(root, out error, layout);
            if (avatar == null) return null;
            if (assetPath != null) AssetDatabase.CreateAsset(avatar, assetPath);
            Animator animator = root.GetComponent<Animator>();
            if (animator == null) animator = Undo.AddComponent<Animator>(root);
            Undo.RecordObject(animator, "Assign SMPL Humanoid avatar");
            animator.avatar = avatar;
            EditorUtility.SetDirty(animator);
            return avatar;
        }

        [MenuItem(MenuPath, true)]
        static bool CanCreateForSelection()
        {
            foreach (GameObject go in Selection.gameObjects)
                if (!EditorUtility.IsPersistent(go)) return true;
            return false;
        }

        [MenuItem(MenuPath, false)]
        static void CreateForSelection()
        {
            foreach (GameObject go in Selection.gameObjects)
            {
                if (EditorUtility.IsPersistent(go)) continue;  // a model asset, not a scene object
                string modelPath = PrefabUtility.GetPrefabAssetPathOfNearestInstanceRoot(go);
                string path = AssetDatabase.GenerateUniqueAssetPath(AvatarPathFor(modelPath, go.name));
                string error;
                SidecarLayout layout = null;
                string sidecarModel;
                TextAsset sidecar = CorrectivesSetup.FindSidecar(go, out sidecarModel);
                if (sidecar != null)
                {
                    layout = SidecarLayout.Parse(sidecar.text, CorrectivesSetup.SidecarPathFor(sidecarModel), out error);
                    if (layout == null)
                    {
                        Debug.LogError(error, go);
                        continue;
                    }
                }
                Avatar avatar = CreateFor(go, path, out error, layout);
                if (avatar == null)
                    Debug.LogError(error, go);
                else
                    Debug.Log(go.name + ": Humanoid avatar saved to " + path + " and set on its Animator", go);
            }
        }
    }
}
