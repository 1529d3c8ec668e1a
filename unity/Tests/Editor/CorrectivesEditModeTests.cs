// Unity Test Runner (EditMode) entry points: NUnit wrappers around the checks
// the mono harness runs (unity/Tests/*.cs), so both run the same code.
// The expected values come from the runtime conformance kit, a folder written
// by smpl-export's `smpl-reference --conformance-kit DIR` (Unity cannot run
// it): set SMPL_CONFORMANCE_KIT to DIR before starting the Editor. Without
// it the kit tests fail with a message saying so (they never skip). Each
// test fails if any check fails or if no check ran. Needs "testables" in the
// project manifest (see README.md).
using System.Collections.Generic;
using NUnit.Framework;
using UnityEditor;
using UnityEngine;

namespace SmplExport.Correctives.Tests
{
    public sealed class CorrectivesEditModeTests
    {
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
        public void ConformanceKitCases()
        {
            KitTests.Run(new Kit(Kit.DirFromEnvironment()));
            AssertAllPassed();
        }

        [Test]
        public void CorrectiveMathAxisMaps()
        {
            MathTests.Run(KitReference.Load(new Kit(Kit.DirFromEnvironment())));
            AssertAllPassed();
        }

        [Test]
        public void ComponentMatchesTheKit()
        {
            ComponentTests.Run(KitReference.Load(new Kit(Kit.DirFromEnvironment())));
            AssertAllPassed();
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
