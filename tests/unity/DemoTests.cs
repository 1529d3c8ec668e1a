// The sample unity/Samples~/Demo/SmplCorrectivesDemo.cs on a stubbed body
// (mono only: Unity does not compile Samples~, and once imported the sample is
// the user's code). It must add and set up SmplCorrectives, bend each listed
// joint about the model's left-right (X) axis by amplitude * sin(phase), so
// that the joint's pose feature block is R_x(theta) - I, and hold the
// corrective weights at 0 when "correctives" is off.
using System;
using System.Collections.Generic;
using System.Reflection;
using NUnit.Framework;
using SmplExport.Correctives.Samples;
using SmplExport.Correctives.Tests;
using UnityEditor;
using UnityEngine;

namespace SmplExport.Correctives.StubRunner
{
    public sealed class DemoTests
    {
        [TearDown]
        public void DestroyRigs() { TestRig.DestroyAll(); }

        [Test]
        public void BendsJointsAboutTheModelXAxisAndTogglesCorrectives()
        {
            ReferenceModel model = KitReference.Load(new Kit(Kit.DirFromEnvironment()));
            var rig = new TestRig(model, "mixamorig:", "");
            UnityEngine.Object.DestroyImmediate(rig.Driver);  // the demo must add its own
            rig.W = new Quaternion(0f, 0.6f, 0f, 0.8f);  // the character turned about +Y
            rig.Pose(Identities(model.JointCount));

            var demoObject = new GameObject("Demo");
            SmplCorrectivesDemo demo = demoObject.AddComponent<SmplCorrectivesDemo>();
            demo.body = rig.Model;
            demo.sidecar = TestRig.Text("body.glb.smpl", TestRig.Sidecar(model, 1.0, 0.0));
            demo.joints = new[] { "left_knee", "right_elbow", "no_such_joint" };
            Call(demo, "Start");
            SmplCorrectives driver = rig.Body.GetComponent<SmplCorrectives>();
            Assert.IsTrue(driver != null && driver.IsReady && driver.sidecar == demo.sidecar, "demo added a ready SmplCorrectives");

            Time.time = 0.7f;
            Call(demo, "LateUpdate");
            driver.Evaluate();  // its LateUpdate, after the demo's
            foreach (int i in new[] { 0, 1 })
            {
                int k = Array.IndexOf(model.JointNames, demo.joints[i]);
                Assert.IsTrue(k > 0, demo.joints[i] + " in the reference model");
                double theta = demo.amplitudeDegrees * Math.PI / 180.0 *
                               Math.Sin(2 * Math.PI * (demo.cyclesPerSecond * Time.time + 0.15 * i));
                double c = Math.Cos(theta) - 1, s = Math.Sin(theta);
                double[] f = driver.Features;
                int b = 9 * (k - 1);
                // R_x(theta) - I = [[0,0,0],[0,c,-s],[0,s,c]]; the sign of s depends on the axis direction.
                double err = Math.Max(Math.Abs(f[b]), Math.Max(Math.Abs(f[b + 1]), Math.Abs(f[b + 2])));
                err = Math.Max(err, Math.Max(Math.Abs(f[b + 3]), Math.Abs(f[b + 6])));
                err = Math.Max(err, Math.Max(Math.Abs(f[b + 4] - c), Math.Abs(f[b + 8] - c)));
                err = Math.Max(err, Math.Max(Math.Abs(Math.Abs(f[b + 5]) - Math.Abs(s)), Math.Abs(f[b + 5] + f[b + 7])));
                Assert.IsTrue(Math.Abs(theta) > 0.3 && err < 1e-5,
                              demo.joints[i] + ": features " + string.Join(",", Array.ConvertAll(SubArray(f, b), x => x.ToString("G4"))) +
                              " are not R_x(" + theta.ToString("G4") + ") - I (max error " + err.ToString("G3") + ")");
                for (int other = 0; other < f.Length; ++other)
                    if (other / 9 + 1 != k && other / 9 + 1 != Array.IndexOf(model.JointNames, demo.joints[1 - i]))
                        Assert.IsTrue(Math.Abs(f[other]) < 1e-5, "feature " + other + " of an unbent joint is " + f[other]);
            }
            int shape = rig.ShapeIndex["pose_left_knee_11"];
            Assert.IsTrue(Math.Abs(rig.Skin.GetBlendShapeWeight(shape)) > 1f, "corrective weight follows the bend");

            demo.correctives = false;
            Call(demo, "LateUpdate");
            Assert.IsTrue(!driver.enabled && rig.Skin.GetBlendShapeWeight(shape) == 0f, "correctives off: driver disabled, weights 0");
            demo.correctives = true;
            Call(demo, "LateUpdate");
            Assert.IsTrue(driver.enabled, "correctives on again");
        }

        static void Call(object target, string method)
        {
            target.GetType().GetMethod(method, BindingFlags.Instance | BindingFlags.NonPublic).Invoke(target, null);
        }

        static double[] SubArray(double[] a, int start)
        {
            var r = new double[9];
            Array.Copy(a, start, r, 0, 9);
            return r;
        }

        static Quat[] Identities(int count)
        {
            var q = new Quat[count];
            for (int k = 0; k < count; ++k) q[k] = Quat.Identity;
            return q;
        }
    }
}
