// Unity Test Runner (EditMode) entry points: NUnit wrappers around the checks
// the mono harness runs (unity/Tests/*.cs), so both run the same code.
// Unity cannot run the C++ reference, so the reference features come from
// Data/csharp_reference_smpl.json, shipped with the package and kept equal to
// a fresh run of tests/unity/csharp_reference.cpp by the repository's CTest
// test unity_reference_data_current. Each test fails if any check fails or if
// no check ran. Needs "testables" in the project manifest (see README.md).
using System.Collections.Generic;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace SmplExport.Correctives.Tests
{
    public sealed class CorrectivesEditModeTests
    {
        /// <summary>Asset path of the shipped C++ reference data (a TextAsset).</summary>
        public const string ReferencePath = "Packages/com.smpl-export.correctives/Tests/Data/csharp_reference_smpl.json";

        [SetUp]
        public void ResetChecks() { CorrectivesTests.Reset(); }

        [TearDown]
        public void DestroyRigs() { TestRig.DestroyAll(); }

        [Test]
        public void NameMatchingSidecarJsonAndAxisMaps()
        {
            UnitTests.Run();
            AssertAllPassed();
        }

        [Test]
        public void CorrectiveMathMatchesCppReference()
        {
            foreach (ReferenceModel model in LoadReference()) MathTests.Run(model);
            AssertAllPassed();
        }

        [Test]
        public void ComponentMatchesCppReference()
        {
            foreach (ReferenceModel model in LoadReference()) ComponentTests.Run(model);
            AssertAllPassed();
        }

        static List<ReferenceModel> LoadReference()
        {
            var asset = AssetDatabase.LoadAssetAtPath<TextAsset>(ReferencePath);
            Assert.IsNotNull(asset, ReferencePath + ": not found (is the package's Tests folder imported?)");
            string error;
            List<ReferenceModel> models = ReferenceModel.LoadAll(asset.text, ReferencePath, out error);
            Assert.IsNotNull(models, error);
            Assert.IsTrue(models.Count > 0, ReferencePath + ": no models");
            return models;
        }

        static void AssertAllPassed()
        {
            Assert.IsTrue(CorrectivesTests.CheckCount > 0, "no check ran");
            Assert.IsTrue(CorrectivesTests.Failures.Count == 0,
                          CorrectivesTests.Failures.Count + " of " + CorrectivesTests.CheckCount + " checks failed:\n" +
                          string.Join("\n", CorrectivesTests.Failures.ToArray()));
        }
    }
}
