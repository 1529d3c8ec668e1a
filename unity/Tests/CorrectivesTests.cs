// Checks of unity/Runtime against the C++ reference, shared by two runners:
//  - the mono harness (tests/unity/tests.cmake): mcs compiles unity/Runtime,
//    unity/Tests/*.cs and tests/unity/UnityEngineStub.cs with
//    -define:SMPL_EXPORT_MONO_TESTS; Main below runs everything.
//    usage: mono SmplCorrectivesTests.exe reference.json
//  - Unity's Test Runner: the EditMode assembly of this folder
//    (SmplExport.Correctives.Tests.asmdef, UNITY_INCLUDE_TESTS) with the
//    NUnit wrappers in Editor/, which call the same Run methods.
// reference.json comes from tests/unity/csharp_reference.cpp: the C++
// reference features poseFeatures(R) for random poses, and the world
// rotations Unity would report for two imported skeletons. A check that
// fails is counted and printed; the runners fail if any did.
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
                Console.Error.WriteLine("usage: SmplCorrectivesTests.exe reference.json");
                return 2;
            }
            string error;
            List<ReferenceModel> models = ReferenceModel.LoadAll(System.IO.File.ReadAllText(args[0]), args[0], out error);
            if (models == null)
            {
                Console.Error.WriteLine(error);
                return 2;
            }
            Check(models.Count >= 2, "reference has " + models.Count + " models; expected at least 2");
            foreach (ReferenceModel model in models)
            {
                MathTests.Run(model);
                ComponentTests.Run(model);
            }
            UnitTests.Run();
            foreach (ReferenceModel model in models) Benchmark.Run(model);
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

    public sealed class ReferenceModel
    {
        public string Name;
        public string[] JointNames;
        public int[] Parents;
        public double[] AxisMap;
        public Quat[] BindRest;
        public string BasisSidecar;     // the exporter's metadata with --corrective-basis 16
        public List<ReferencePose> Poses = new List<ReferencePose>();

        public ReferenceModel(Dictionary<string, object> o)
        {
            Name = (string)o["name"];
            var names = (List<object>)o["joint_names"];
            JointNames = names.ConvertAll(x => (string)x).ToArray();
            Parents = Array.ConvertAll(Numbers(o["parents"]), x => (int)x);
            AxisMap = Numbers(o["axis_map"]);
            BindRest = Quats(o["bind_rest"]);
            BasisSidecar = (string)o["basis_sidecar"];
            foreach (object p in (List<object>)o["poses"])
            {
                var d = (Dictionary<string, object>)p;
                Poses.Add(new ReferencePose {
                    Features = Numbers(d["features"]),
                    BasisWeights = Numbers(d["basis_weights"]),
                    IdentityRestWorld = Quats(d["identity_rest_world"]),
                    BindRestWorld = Quats(d["bind_rest_world"]) });
            }
        }

        public int JointCount { get { return Parents.Length; } }

        /// <summary>The models of a reference.json text; null and a one-line error if it is not one.</summary>
        public static List<ReferenceModel> LoadAll(string json, string context, out string error)
        {
            object root;
            if (!MiniJson.TryParse(json, out root, out error))
            {
                error = context + ": " + error;
                return null;
            }
            var result = new List<ReferenceModel>();
            try
            {
                foreach (object m in (List<object>)((Dictionary<string, object>)root)["models"])
                    result.Add(new ReferenceModel((Dictionary<string, object>)m));
            }
            catch (Exception e)
            {
                error = context + ": not reference data of csharp_reference.cpp (" + e.GetType().Name + ": " + e.Message + ")";
                return null;
            }
            return result;
        }

        static double[] Numbers(object v) { return ((List<object>)v).ConvertAll(x => (double)x).ToArray(); }

        static Quat[] Quats(object v)
        {
            var list = (List<object>)v;
            var result = new Quat[list.Count];
            for (int i = 0; i < list.Count; ++i)
            {
                double[] q = Numbers(list[i]);
                result[i] = new Quat(q[0], q[1], q[2], q[3]);
            }
            return result;
        }
    }

    // CorrectiveMath in doubles against the C++ reference.
    static class MathTests
    {
        public static void Run(ReferenceModel model)
        {
            double identity = MaxError(model, CorrectiveMath.MirrorX, false);
            CorrectivesTests.CheckClose(identity, CorrectivesTests.DoubleTolerance,
                                        model.Name + ": CorrectiveMath, identity-rest bones, mirror X");
            double bind = MaxError(model, CorrectiveMath.MirrorX, true);
            CorrectivesTests.CheckClose(bind, CorrectivesTests.DoubleTolerance,
                                        model.Name + ": CorrectiveMath, bind-rest bones, mirror X");
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
