// Tests of unity/Runtime under mono (tests/unity/tests.cmake), never compiled
// by Unity (the asmdef next to this file requires SMPL_EXPORT_MONO_TESTS).
//
// usage: mono SmplCorrectivesTests.exe reference.json
// reference.json comes from tests/unity/csharp_reference.cpp: the C++
// reference features poseFeatures(R) for random poses, and the world
// rotations Unity would report for two imported skeletons. Exit code 0 only
// if every check passes.
#if SMPL_EXPORT_MONO_TESTS
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using SmplExport.Correctives;
using UnityEngine;

namespace SmplExport.Correctives.Tests
{
    public static class CorrectivesTests
    {
        public const double DoubleTolerance = 1e-9;
        public const double FloatTolerance = 1e-5;
        static int failures, checks;

        public static int Main(string[] args)
        {
            if (args.Length != 1)
            {
                Console.Error.WriteLine("usage: SmplCorrectivesTests.exe reference.json");
                return 2;
            }
            object root;
            string error;
            if (!MiniJson.TryParse(File.ReadAllText(args[0]), out root, out error))
            {
                Console.Error.WriteLine(args[0] + ": " + error);
                return 2;
            }
            var models = (List<object>)((Dictionary<string, object>)root)["models"];
            Check(models.Count >= 2, "reference has " + models.Count + " models; expected at least 2");
            foreach (object m in models)
            {
                var model = new ReferenceModel((Dictionary<string, object>)m);
                MathTests.Run(model);
                ComponentTests.Run(model);
            }
            UnitTests.Run();
            foreach (object m in models) Benchmark.Run(new ReferenceModel((Dictionary<string, object>)m));
            Console.WriteLine(checks + " checks, " + failures + " failed");
            return failures == 0 ? 0 : 1;
        }

        public static void Check(bool ok, string what)
        {
            ++checks;
            if (ok) return;
            ++failures;
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
#endif
