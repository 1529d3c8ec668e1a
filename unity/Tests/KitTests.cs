// The Unity runtime as a loader of the runtime conformance kit
// (docs/conformance.md in the smpl-export repository): every case's sidecar
// through SidecarLayout.Parse, the engine world rotations through
// CorrectiveMath (the case's axis map and rest rotations), the weights through
// CorrectiveMath.Weight and ProjectBasis, compared with the kit's tolerance
// table; every bad sidecar must be refused with an error naming the kit's
// field. The kit is a folder written by `smpl-reference --conformance-kit DIR`;
// KitReference builds the ReferenceModel the component tests use from its
// Unity cases (unity_identity.basis, unity_bind.basis).
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using SmplExport.Correctives;

namespace SmplExport.Correctives.Tests
{
    /// <summary>The kit's manifest and files (System.IO: runs in Unity and under mono).</summary>
    public sealed class Kit
    {
        public readonly string Dir;
        public readonly Dictionary<string, object> Manifest;

        public Kit(string dir)
        {
            Dir = dir;
            Manifest = Object(ReadJson("manifest.json"), "manifest.json");
        }

        /// <summary>The kit folder: $SMPL_CONFORMANCE_KIT, or an error naming how to make it.</summary>
        public static string DirFromEnvironment()
        {
            string dir = Environment.GetEnvironmentVariable("SMPL_CONFORMANCE_KIT");
            if (string.IsNullOrEmpty(dir))
                throw new InvalidOperationException("SMPL_CONFORMANCE_KIT is not set: generate the kit with " +
                                                    "smpl-reference --model builtin --conformance-kit DIR and set it to DIR");
            return dir;
        }

        public string ReadText(string file) { return File.ReadAllText(Path.Combine(Dir, file)); }

        public object ReadJson(string file)
        {
            object root;
            string error;
            if (!MiniJson.TryParse(ReadText(file), out root, out error))
                throw new InvalidDataException(Path.Combine(Dir, file) + ": " + error);
            return root;
        }

        public double Tolerance(string quantity, string precision)
        {
            var t = Object(Object(Manifest["tolerances"], "tolerances")[quantity], quantity);
            return (double)t[precision];
        }

        public List<object> List(string key) { return (List<object>)Manifest[key]; }

        public static Dictionary<string, object> Object(object v, string what)
        {
            var o = v as Dictionary<string, object>;
            if (o == null) throw new InvalidDataException(what + ": not a JSON object");
            return o;
        }

        public static double[] Numbers(object v) { return ((List<object>)v).ConvertAll(x => (double)x).ToArray(); }

        /// <summary>Quaternions (x, y, z, w) of a list of 4-number lists.</summary>
        public static Quat[] Quats(object v)
        {
            var list = (List<object>)v;
            var q = new Quat[list.Count];
            for (int i = 0; i < list.Count; ++i)
            {
                double[] c = Numbers(list[i]);
                q[i] = new Quat(c[0], c[1], c[2], c[3]);
            }
            return q;
        }
    }

    public static class KitTests
    {
        /// <summary>Every case and bad sidecar of the kit; failures go to CorrectivesTests.Check.</summary>
        public static void Run(Kit kit)
        {
            int cases = 0;
            foreach (object e in kit.List("cases"))
            {
                var entry = Kit.Object(e, "cases[]");
                RunCase(kit, entry);
                ++cases;
            }
            CorrectivesTests.Check(cases > 0, kit.Dir + ": no cases");
            foreach (object b in kit.List("bad"))
            {
                var entry = Kit.Object(b, "bad[]");
                string file = (string)entry["sidecar"], field = (string)entry["error"];
                string error;
                SidecarLayout layout = SidecarLayout.Parse(kit.ReadText(file), file, out error);
                CorrectivesTests.Check(layout == null, file + ": accepted (" + entry["what"] + ")");
                CorrectivesTests.Check(layout != null || field == "json" || error.Contains(field),
                                       file + ": the error does not name '" + field + "': " + error);
            }
        }

        static void RunCase(Kit kit, Dictionary<string, object> entry)
        {
            string name = (string)entry["name"], sidecar = (string)entry["sidecar"];
            var data = Kit.Object(kit.ReadJson((string)entry["data"]), name);
            string error;
            SidecarLayout layout = SidecarLayout.Parse(kit.ReadText(sidecar), sidecar, out error);
            CorrectivesTests.Check(layout != null, name + ": " + error);
            if (layout == null) return;
            CorrectiveMath math = CorrectiveMath.Create(layout.Parents, Kit.Numbers(data["axes"]), out error);
            CorrectivesTests.Check(math != null, name + ": Create failed: " + error);
            if (math == null) return;
            Quat[] rest = Kit.Quats(data["rest_world"]);
            for (int k = 0; k < math.JointCount; ++k) math.SetRest(k, rest[k]);
            double tf = kit.Tolerance("features", "float64"), tw = kit.Tolerance("weights", "float64");
            var features = new double[math.FeatureCount];
            List<object> poses = (List<object>)data["poses"];
            for (int i = 0; i < poses.Count; ++i)
            {
                var pose = Kit.Object(poses[i], name);
                math.Compute(Kit.Quats(pose["world"]), features);
                Compare(name, i, "features", features, Kit.Numbers(pose["features"]), tf);
                Compare(name, i, "weights", Weights(layout, features), Kit.Numbers(pose["weights"]), tw);
            }
        }

        /// <summary>Correctives in sidecar order, then every basis row.</summary>
        static double[] Weights(SidecarLayout layout, double[] features)
        {
            int basis = layout.Basis == null ? 0 : layout.Basis.Targets.Length;
            var w = new double[layout.Correctives.Length + basis];
            for (int i = 0; i < layout.Correctives.Length; ++i)
            {
                CorrectiveBinding c = layout.Correctives[i];
                w[i] = CorrectiveMath.Weight(features[c.Feature], c.Scale, c.Offset, c.Rectified);
            }
            if (basis == 0) return w;
            var rows = new int[basis];
            for (int r = 0; r < basis; ++r) rows[r] = r;
            var projected = new double[basis];
            CorrectiveMath.ProjectBasis(layout.Basis, rows, features, projected);
            Array.Copy(projected, 0, w, layout.Correctives.Length, basis);
            return w;
        }

        static void Compare(string name, int pose, string what, double[] got, double[] want, double tol)
        {
            double e = CorrectivesTests.MaxError(got, want);
            CorrectivesTests.Check(e <= tol, name + ": pose " + pose + ": " + what + " differ by " +
                                             e.ToString("G3", CultureInfo.InvariantCulture) + " (> " +
                                             tol.ToString("G3", CultureInfo.InvariantCulture) + ")");
        }
    }

    /// <summary>The ReferenceModel of the component tests, from the kit's Unity cases.</summary>
    public static class KitReference
    {
        public static ReferenceModel Load(Kit kit)
        {
            var identity = Kit.Object(kit.ReadJson("unity_identity.basis.json"), "unity_identity.basis.json");
            var bind = Kit.Object(kit.ReadJson("unity_bind.basis.json"), "unity_bind.basis.json");
            string sidecar = kit.ReadText("unity_bind.basis.smpl.json");
            var meta = Kit.Object(kit.ReadJson("unity_bind.basis.smpl.json"), "unity_bind.basis.smpl.json");
            var model = new ReferenceModel();
            model.Name = (string)meta["model_name"] + " (kit)";
            model.JointNames = ((List<object>)meta["joint_names"]).ConvertAll(x => (string)x).ToArray();
            model.Parents = Array.ConvertAll(Kit.Numbers(meta["parents"]), x => (int)x);
            model.AxisMap = Kit.Numbers(bind["axes"]);
            model.BindRest = Kit.Quats(bind["rest_world"]);
            model.BasisSidecar = sidecar;
            var a = (List<object>)identity["poses"];
            var b = (List<object>)bind["poses"];
            for (int i = 0; i < a.Count; ++i)
            {
                var pa = Kit.Object(a[i], "poses[]");
                var pb = Kit.Object(b[i], "poses[]");
                model.Poses.Add(new ReferencePose {
                    Features = Kit.Numbers(pb["features"]),
                    BasisWeights = Kit.Numbers(pb["weights"]),
                    IdentityRestWorld = Kit.Quats(pa["world"]),
                    BindRestWorld = Kit.Quats(pb["world"]) });
            }
            return model;
        }
    }
}
