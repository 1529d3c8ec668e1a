// Small pieces checked on their own: name matching, sidecar parsing and its
// errors, the JSON reader on hostile input, axis map validation, and the
// bind pose rotation extraction. Needs no reference data.
using System;
using System.Collections.Generic;
using SmplExport.Correctives;

namespace SmplExport.Correctives.Tests
{
    static class UnitTests
    {
        public static void Run()
        {
            NameMatching();
            SidecarParsing();
            BasisParsing();
            HostileJson();
            AxisMapValidation();
            RotationFromScaledMatrix();
            RectifiedWeights();
        }

        // "rectified": true only when literally true; Weight() clamps those below at 0.
        static void RectifiedWeights()
        {
            string text = "{\"joint_names\":[\"root\",\"a\"],\"parents\":[-1,0],\"correctives\":[" +
                          "{\"feature\":1,\"target\":\"pose_a_01_neg\",\"scale\":-1,\"offset\":0,\"rectified\":true}," +
                          "{\"feature\":1,\"target\":\"pose_a_01\",\"scale\":-1,\"rectified\":1}]}";
            string error;
            SidecarLayout layout = SidecarLayout.Parse(text, "x.smpl.json", out error);
            Check(layout != null && layout.Correctives[0].Rectified && !layout.Correctives[1].Rectified,
                  "rectified parsed (only true counts): " + error);
            Check(CorrectiveMath.Weight(0.25, -1, 0, true) == 0 && CorrectiveMath.Weight(-0.25, -1, 0, true) == 0.25,
                  "rectified weight max(0, scale f + offset)");
            Check(CorrectiveMath.Weight(0.25, -1, 0, false) == -0.25 && CorrectiveMath.Weight(0.5, 0.5, 0.5, false) == 0.75,
                  "plain weight scale f + offset");
        }

        static void NameMatching()
        {
            Check(NameMatch.IsSuffixMatch("mixamorig:left_hip", "left_hip"), "prefix with ':'");
            Check(NameMatch.IsSuffixMatch("Armature/pelvis", "pelvis"), "prefix with '/'");
            Check(NameMatch.IsSuffixMatch("Body.pose_left_hip_00", "pose_left_hip_00"), "blend shape channel prefix");
            Check(!NameMatch.IsSuffixMatch("spine12", "spine1") && !NameMatch.IsSuffixMatch("xspine1", "spine1"),
                  "no match without a separator");
            Check(!NameMatch.IsSuffixMatch("spine1", "spine1"), "equal names are exact, not suffix, matches");
            // Exact names win, are not reused, and the least decorated suffix match wins.
            int[] m = NameMatch.Assign(new[] { "left_hip", "hip", "neck", "head" },
                                       new[] { "a:left_hip", "left_hip", "x:y:neck", "y:neck", "jaw" });
            Check(m[0] == 1, "exact match preferred over suffix (got " + m[0] + ")");
            Check(m[1] == 0, "'hip' falls back to a suffix match of an unused name (got " + m[1] + ")");
            Check(m[2] == 3, "shortest suffix match wins (got " + m[2] + ")");
            Check(m[3] == -1, "no candidate gives -1 (got " + m[3] + ")");
        }

        static void SidecarParsing()
        {
            string ok = "{\"joint_names\":[\"root\",\"a\"],\"parents\":[-1,0],\"correctives\":[" +
                        "{\"feature\":8,\"target\":\"pose_a_22\",\"scale\":0.5,\"offset\":1}]}";
            string error;
            SidecarLayout layout = SidecarLayout.Parse(ok, "x.smpl.json", out error);
            Check(layout != null && layout.Correctives.Length == 1 && layout.Correctives[0].Feature == 8 &&
                  layout.Correctives[0].Scale == 0.5 && layout.Correctives[0].Offset == 1.0, "sidecar parsed: " + error);
            layout = SidecarLayout.Parse("{\"asset\":{\"version\":\"2.0\",\"extras\":{\"smpl\":" + ok + "}}}", "a.gltf", out error);
            Check(layout != null && layout.JointNames[1] == "a", "glTF asset.extras.smpl accepted: " + error);
            ExpectError(ok.Replace("\"feature\":8", "\"feature\":9"), "feature must be an integer in [0, 9)");
            ExpectError(ok.Replace("\"feature\":8", "\"feature\":2.5"), "feature must be an integer");
            ExpectError(ok.Replace("[-1,0]", "[-1]"), "'parents' has 1 entries");
            ExpectError(ok.Replace("\"target\":\"pose_a_22\",", ""), "target must be a string");
            ExpectError("{\"joint_names\":[", "JSON error");
            ExpectError("[1,2]", "no 'joint_names'");
            // A parent table out of order: refused by the reader (the kit's bad sidecars
            // cover more) and by CorrectiveMath.Create for tables built in code.
            string bad = ok.Replace("[-1,0]", "[-1,1]");
            layout = SidecarLayout.Parse(bad, "x.smpl.json", out error);
            Check(layout == null && error != null && error.Contains("'parents'[1] = 1"), "bad parents rejected: " + error);
            // --skeleton-names: bone_names (one per joint, distinct) name the bones
            string renamed = ok.Replace("\"parents\"", "\"bone_names\":[\"mixamorig:Hips\",\"mixamorig:LeftUpLeg\"],\"parents\"");
            layout = SidecarLayout.Parse(renamed, "x.smpl.json", out error);
            Check(layout != null && layout.BoneNames != null && layout.BoneNames[1] == "mixamorig:LeftUpLeg" &&
                  layout.JointNames[1] == "a", "bone_names read: " + error);
            Check(SidecarLayout.Parse(ok, "x.smpl.json", out error).BoneNames == null, "no bone_names: null");
            ExpectError(renamed.Replace(",\"mixamorig:LeftUpLeg\"]", "]"), "'bone_names' must be an array as long as");
            ExpectError(renamed.Replace("mixamorig:LeftUpLeg", "mixamorig:Hips"), "'bone_names'[1] is not a string or not unique");
            CorrectiveMath math = CorrectiveMath.Create(new[] { -1, 1 }, CorrectiveMath.MirrorX, out error);
            Check(math == null && error != null && error.Contains("joint 1 has parent 1"), "bad parents rejected by Create: " + error);
        }

        static void BasisParsing()
        {
            string ok = "{\"joint_names\":[\"root\",\"a\"],\"parents\":[-1,0],\"correctives\":[]," +
                        "\"corrective_basis\":{\"targets\":[\"pose_basis_0\"],\"features\":9," +
                        "\"matrix\":[1,0,0,0,2,0,0,0,3],\"scale\":[0.25],\"offset\":[0.5]}}";
            string error;
            SidecarLayout layout = SidecarLayout.Parse(ok, "x.smpl.json", out error);
            Check(layout != null && layout.Basis != null && layout.Basis.Targets[0] == "pose_basis_0" &&
                  layout.Basis.Matrix[4] == 2.0 && layout.Basis.Offset[0] == 0.5, "basis parsed: " + error);
            if (layout != null && layout.Basis != null)
            {
                var f = new double[] { 0.1, 9, 9, 9, -0.2, 9, 9, 9, 0.3 };
                var w = new double[1];
                CorrectiveMath.ProjectBasis(layout.Basis, new[] { 0 }, f, w);
                Check(Math.Abs(w[0] - (0.25 * (0.1 - 0.4 + 0.9) + 0.5)) < 1e-15, "basis weight = scale (C f) + offset: " + w[0]);
            }
            ExpectError(ok.Replace("[1,0,0,0,2,0,0,0,3]", "[1,0,0,0,2,0,0,0]"), "matrix must be an array of 9 numbers");
            ExpectError(ok.Replace("\"features\":9", "\"features\":8"), "features must be 9");
            ExpectError(ok.Replace("[0.25]", "[\"x\"]"), "scale[0] is not a number");
            ExpectError(ok.Replace("[\"pose_basis_0\"]", "[3]"), "targets[0] is not a string");
        }

        static void ExpectError(string json, string expected)
        {
            string error;
            SidecarLayout layout = SidecarLayout.Parse(json, "x.smpl.json", out error);
            Check(layout == null && error != null && error.StartsWith("x.smpl.json: ") && error.Contains(expected),
                  "expected error containing '" + expected + "', got: " + (error ?? "success"));
        }

        static void HostileJson()
        {
            object v;
            string error;
            Check(!MiniJson.TryParse(new string('[', 100000), out v, out error) && error.Contains("nesting"), "deep nesting rejected");
            foreach (string bad in new[] { "", "{", "[1,]", "\"abc", "\"\\u12\"", "{\"a\" 1}", "nul", "1 2", "-" })
                Check(!MiniJson.TryParse(bad, out v, out error), "malformed JSON accepted: " + bad);
            Check(MiniJson.TryParse(" {\"a\\n\\u0041\":[1e-3,true,null,\"x\"]} ", out v, out error) &&
                  ((List<object>)((Dictionary<string, object>)v)["a\nA"]).Count == 4, "valid JSON parsed: " + error);
        }

        static void AxisMapValidation()
        {
            string error;
            int[] parents = { -1, 0 };
            Check(CorrectiveMath.Create(parents, new double[] { 1, 0, 0, 0, 1, 0, 0, 0, 0 }, out error) == null &&
                  error.Contains("singular"), "singular axis map rejected");
            Check(CorrectiveMath.Create(parents, new double[] { 1, 1, 0, 0, 1, 0, 0, 0, 1 }, out error) == null &&
                  error.Contains("not orthogonal"), "sheared axis map rejected");
            Check(CorrectiveMath.Create(parents, new double[] { 1, 0, 0 }, out error) == null, "short axis map rejected");
            Check(CorrectiveMath.Create(new int[0], CorrectiveMath.MirrorX, out error) == null, "empty skeleton rejected");
            // A single joint has no features; Compute must still work.
            CorrectiveMath one = CorrectiveMath.Create(new[] { -1 }, CorrectiveMath.MirrorX, out error);
            Check(one != null && one.FeatureCount == 0, "single joint: " + error);
            if (one != null) one.Compute(new[] { Quat.Identity }, new double[0]);
        }

        static void RotationFromScaledMatrix()
        {
            // 90 degrees about z, scaled by 100 as in a centimetre bind pose.
            Quat q = Quat.FromMatrix(new double[] { 0, -100, 0, 100, 0, 0, 0, 0, 100 });
            double h = Math.Sqrt(0.5);
            Check(Math.Abs(Math.Abs(q.Z) - h) < 1e-12 && Math.Abs(Math.Abs(q.W) - h) < 1e-12 && q.Z * q.W > 0 &&
                  Math.Abs(q.X) < 1e-12 && Math.Abs(q.Y) < 1e-12, "rotation from a scaled matrix");
            // 180 degrees about x (trace -1, the Shepperd branch on x).
            q = Quat.FromMatrix(new double[] { 1, 0, 0, 0, -1, 0, 0, 0, -1 });
            Check(Math.Abs(Math.Abs(q.X) - 1) < 1e-12, "rotation by pi");
        }

        static void Check(bool ok, string what) { CorrectivesTests.Check(ok, "unit: " + what); }
    }
}
