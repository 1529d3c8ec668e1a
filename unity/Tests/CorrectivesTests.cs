// Checks of unity/Runtime, shared by two runners:
//  - the mono harness (tests/unity/tests.cmake): mcs compiles unity/Runtime,
//    unity/Tests/*.cs and tests/unity/UnityEngineStub.cs with
//    -define:SMPL_EXPORT_MONO_TESTS; Main below runs everything.
//    usage: mono SmplCorrectivesTests.exe KIT_DIR
//  - Unity's Test Runner: the EditMode assembly of this folder
//    (SmplExport.Correctives.Tests.asmdef, UNITY_INCLUDE_TESTS) with the
//    NUnit wrappers in Editor/, which call the same Run methods.
// KIT_DIR is the runtime conformance kit (smpl-reference --conformance-kit,
// docs/conformance.md): KitTests runs every case through the runtime, and the
// component tests read their poses from its Unity cases (KitReference). A
// check that fails is counted and printed; the runners fail if any did.
using System;
using System.Collections.Generic;
using System.Globalization;
using SmplExport.Correctives;
using UnityEngine;

namespace SmplExport.Correctives.Tests
{
    public static class CorrectivesTests
    {
        public const double DoubleTolerance = 1e-9;
        public const double FloatTolerance = 1e-5;
        static int checks;
        /// <summary>Messages of the failed checks since the last Reset.</summary>
        public static readonly List<string> Failures = new List<string>();
        public static int CheckCount { get { return checks; } }

#if SMPL_EXPORT_MONO_TESTS
        public static int Main(string[] args)
        {
            if (args.Length != 1)
            {
                Console.Error.WriteLine("usage: SmplCorrectivesTests.exe KIT_DIR");
                return 2;
            }
            Kit kit;
            ReferenceModel model;
            try
            {
                kit = new Kit(args[0]);
                model = KitReference.Load(kit);
            }
            catch (Exception e)
            {
                Console.Error.WriteLine(args[0] + ": not a conformance kit (" + e.GetType().Name + ": " + e.Message + ")");
                return 2;
            }
            KitTests.Run(kit);
            MathTests.Run(model);
            ComponentTests.Run(model);
            UnitTests.Run();
            Benchmark.Run(model);
            Console.WriteLine(checks + " checks, " + Failures.Count + " failed");
            return Failures.Count == 0 ? 0 : 1;
        }
#endif

        public static void Reset()
        {
            checks = 0;
            Failures.Clear();
        }

        public static void Check(bool ok, string what)
        {
            ++checks;
            if (ok) return;
            Failures.Add(what);
            Console.WriteLine("FAIL: " + what);
        }

        public static void CheckClose(double error, double tolerance, string what)
        {
            Console.WriteLine(what + ": max error " + error.ToString("G3", CultureInfo.InvariantCulture));
            Check(error <= tolerance, what + ": max error " + error.ToString("G3", CultureInfo.InvariantCulture) +
                                      " > " + tolerance.ToString("G3", CultureInfo.InvariantCulture));
        }

        public static double MaxError(double[] a, double[] b)
        {
            double e = a.Length == b.Length ? 0 : double.PositiveInfinity;
            for (int i = 0; i < Math.Min(a.Length, b.Length); ++i) e = Math.Max(e, Math.Abs(a[i] - b[i]));
            return e;
        }
    }

    public sealed class ReferencePose
    {
        public double[] Features;
        public double[] BasisWeights;   // scale_k (C f)_k + offset_k of BasisSidecar
        public Quat[] IdentityRestWorld, BindRestWorld;
    }

    /// <summary>A model's poses as the component tests use them (KitReference.Load).</summary>
    public sealed class ReferenceModel
    {
        public string Name;
        public string[] JointNames;
        public int[] Parents;
        public double[] AxisMap;
        public Quat[] BindRest;
        public string BasisSidecar;     // the exporter's metadata with --corrective-basis 8 (unit)
        public List<ReferencePose> Poses = new List<ReferencePose>();

        public int JointCount { get { return Parents.Length; } }
    }

    // CorrectiveMath in doubles beyond the kit's cases (KitTests): a wrong axis
    // map is caught, a scaled one is the same conjugation.
    static class MathTests
    {
        public static void Run(ReferenceModel model)
        {
            // The comparison can fail: a wrong axis map must be caught.
            foreach (double[] wrong in new[] { CorrectiveMath.IdentityMap, CorrectiveMath.MirrorZ })
                foreach (bool useBind in new[] { false, true })
                {
                    double e = MaxError(model, wrong, useBind);
                    CorrectivesTests.Check(e > 1e-3, model.Name + ": a wrong axis map went unnoticed (max error " + e + ")");
                }
            // A scaled axis map (e.g. metres -> centimetres) is the same conjugation.
            var scaled = Array.ConvertAll(CorrectiveMath.MirrorX, x => 100.0 * x);
            CorrectivesTests.CheckClose(MaxError(model, scaled, true), CorrectivesTests.DoubleTolerance,
                                        model.Name + ": CorrectiveMath, axis map scaled by 100");
        }

        static double MaxError(ReferenceModel model, double[] axisMap, bool useBind)
        {
            string error;
            CorrectiveMath math = CorrectiveMath.Create(model.Parents, axisMap, out error);
            CorrectivesTests.Check(math != null, model.Name + ": Create failed: " + error);
            if (math == null) return double.PositiveInfinity;
            for (int k = 0; k < model.JointCount; ++k) math.SetRest(k, useBind ? model.BindRest[k] : Quat.Identity);
            var features = new double[math.FeatureCount];
            double worst = 0;
            foreach (ReferencePose pose in model.Poses)
            {
                math.Compute(useBind ? pose.BindRestWorld : pose.IdentityRestWorld, features);
                worst = Math.Max(worst, CorrectivesTests.MaxError(features, pose.Features));
            }
            return worst;
        }
    }
}
