// Runs the package's EditMode tests (unity/Tests/Editor, NUnit wrappers) and
// the sample's tests (DemoTests.cs) under mono, against the UnityEngine,
// UnityEditor and NUnit stubs: every public method marked [Test] of every
// class in this assembly, with its [SetUp] and [TearDown]. This is not
// Unity's Test Runner; it checks that the wrappers, the Editor code and the
// sample compile and behave as intended on the stubbed API, and that the
// reference data shipped in the package matches the runtime.
//
// usage: mono SmplEditModeTests.exe UNITY_PACKAGE_DIR
// Exit 0 only if every test passed and at least one ran.
using System;
using System.Linq;
using System.Reflection;
using NUnit.Framework;

namespace SmplExport.Correctives.StubRunner
{
    public static class EditModeRunner
    {
        public static int Main(string[] args)
        {
            if (args.Length != 1)
            {
                Console.Error.WriteLine("usage: SmplEditModeTests.exe UNITY_PACKAGE_DIR");
                return 2;
            }
            UnityEditor.AssetDatabase.PackageFolders["com.smpl-export.correctives"] = args[0];
            int run = 0, failed = 0;
            foreach (Type type in typeof(EditModeRunner).Assembly.GetTypes().OrderBy(t => t.FullName))
            {
                MethodInfo[] tests = Marked<TestAttribute>(type);
                if (tests.Length == 0) continue;
                foreach (MethodInfo test in tests)
                {
                    ++run;
                    object fixture = Activator.CreateInstance(type);
                    string error = Invoke(Marked<SetUpAttribute>(type), fixture) ?? Invoke(new[] { test }, fixture);
                    string teardown = Invoke(Marked<TearDownAttribute>(type), fixture);
                    error = error ?? teardown;
                    if (error != null) ++failed;
                    Console.WriteLine((error == null ? "PASS " : "FAIL ") + type.Name + "." + test.Name +
                                      (error == null ? "" : ": " + error));
                }
            }
            Console.WriteLine(run + " tests, " + failed + " failed");
            return run > 0 && failed == 0 ? 0 : 1;
        }

        static MethodInfo[] Marked<T>(Type type) where T : Attribute
        {
            return type.GetMethods(BindingFlags.Public | BindingFlags.Instance)
                       .Where(m => m.GetCustomAttributes(typeof(T), false).Length > 0)
                       .OrderBy(m => m.Name).ToArray();
        }

        // The first failure's message, or null.
        static string Invoke(MethodInfo[] methods, object fixture)
        {
            foreach (MethodInfo m in methods)
            {
                try
                {
                    m.Invoke(fixture, null);
                }
                catch (TargetInvocationException e)
                {
                    Exception inner = e.InnerException ?? e;
                    return inner is AssertionException ? inner.Message : inner.ToString();
                }
            }
            return null;
        }
    }
}
