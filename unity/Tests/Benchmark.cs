// Per-frame cost of the corrective math, printed (not asserted: CI machines
// vary). CorrectiveMath.Compute alone is the runtime's own cost; the
// SmplCorrectives line adds the stub's Transform.rotation (which walks the
// parent chain, unlike Unity's cached world rotation) and weight setting.
// Mono harness only (Unity's Test Runner does not print).
#if SMPL_EXPORT_MONO_TESTS
using System;
using System.Diagnostics;
using System.Globalization;
using SmplExport.Correctives;

namespace SmplExport.Correctives.Tests
{
    static class Benchmark
    {
        const int Frames = 10000;

        public static void Run(ReferenceModel model)
        {
            string error;
            CorrectiveMath math = CorrectiveMath.Create(model.Parents, CorrectiveMath.MirrorX, out error);
            for (int k = 0; k < model.JointCount; ++k) math.SetRest(k, model.BindRest[k]);
            Quat[] world = model.Poses[0].BindRestWorld;
            var features = new double[math.FeatureCount];
            double sum = 0;
            for (int i = 0; i < 1000; ++i) math.Compute(world, features);  // JIT warm-up
            var clock = Stopwatch.StartNew();
            for (int i = 0; i < Frames; ++i)
            {
                math.Compute(world, features);
                sum += features[i % features.Length];
            }
            double mathMicros = clock.Elapsed.TotalMilliseconds * 1000.0 / Frames;

            var rig = new TestRig(model, "", "");
            rig.Pose(world);
            rig.Driver.restPose = SmplExport.Correctives.SmplCorrectives.RestPoseSource.PoseAtStart;
            rig.Driver.Initialize();
            for (int i = 0; i < 100; ++i) rig.Driver.Evaluate();
            clock = Stopwatch.StartNew();
            for (int i = 0; i < Frames; ++i) rig.Driver.Evaluate();
            double driverMicros = clock.Elapsed.TotalMilliseconds * 1000.0 / Frames;
            TestRig.DestroyAll();

            Console.WriteLine(string.Format(CultureInfo.InvariantCulture,
                "benchmark {0}: {1} non-root joints, {2} features: CorrectiveMath.Compute {3:F2} us/frame; " +
                "SmplCorrectives.Evaluate on stub transforms {4:F2} us/frame ({5} frames, checksum {6:G6})",
                model.Name, model.JointCount - 1, math.FeatureCount, mathMicros, driverMicros, Frames, sum));
        }
    }
}
#endif
