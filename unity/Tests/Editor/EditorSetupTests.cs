// Tests of the Editor setup (unity/Editor/CorrectivesSetup.cs) used by
// Tools > SMPL > Add Correctives to Selection: the sidecar path next to the
// model, and which renderers get the component.
using NUnit.Framework;
using SmplExport.Correctives.Editor;
using UnityEngine;

namespace SmplExport.Correctives.Tests
{
    public sealed class EditorSetupTests
    {
        GameObject root;

        [TearDown]
        public void DestroyObjects()
        {
            if (root == null) return;
            foreach (SkinnedMeshRenderer skin in root.GetComponentsInChildren<SkinnedMeshRenderer>(true))
                Object.DestroyImmediate(skin.sharedMesh);
            Object.DestroyImmediate(root);
            root = null;
        }

        [Test]
        public void SidecarSitsNextToTheModel()
        {
            Assert.AreEqual("Assets/Bodies/body.glb.smpl.json", CorrectivesSetup.SidecarPathFor("Assets/Bodies/body.glb"), "GLB");
            Assert.AreEqual("Assets/body.fbx.smpl.json", CorrectivesSetup.SidecarPathFor("Assets/body.fbx"), "FBX");
            Assert.IsTrue(CorrectivesSetup.SidecarPathFor("") == null && CorrectivesSetup.SidecarPathFor(null) == null,
                          "no model path gives no sidecar path");
        }

        // body/ (selected)         Body: renderer with blend shapes  -> gets the component
        //   Body, Hair, Armature   Hair: renderer without blend shapes -> does not
        [Test]
        public void AddsToRenderersWithBlendShapesOnce()
        {
            root = new GameObject("body");
            SkinnedMeshRenderer body = Renderer("Body", "pose_left_knee_00");
            SkinnedMeshRenderer hair = Renderer("Hair", null);
            new GameObject("Armature").transform.parent = root.transform;
            TextAsset sidecar = TestRig.Text("body.glb.smpl", "{}");

            var added = CorrectivesSetup.AddTo(root, sidecar);
            Assert.AreEqual(1, added.Count, "components added");
            SmplCorrectives driver = body.GetComponent<SmplCorrectives>();
            Assert.IsTrue(driver != null && added[0] == driver && driver.sidecar == sidecar, "on the body, with the sidecar");
            Assert.IsTrue(hair.GetComponent<SmplCorrectives>() == null, "a mesh without blend shapes is left alone");
            Assert.AreEqual(0, CorrectivesSetup.AddTo(root, sidecar).Count, "a second run adds nothing");
        }

        SkinnedMeshRenderer Renderer(string name, string blendShape)
        {
            var go = new GameObject(name);
            go.transform.parent = root.transform;
            var skin = go.AddComponent<SkinnedMeshRenderer>();
            skin.sharedMesh = new Mesh { name = name + "Mesh" };
            skin.sharedMesh.vertices = new Vector3[1];
            if (blendShape != null) skin.sharedMesh.AddBlendShapeFrame(blendShape, 100f, new Vector3[1], null, null);
            return skin;
        }
    }
}
