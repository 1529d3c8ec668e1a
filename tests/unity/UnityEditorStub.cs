// The few UnityEditor and NUnit types the package's Editor code, its EditMode
// test wrappers (unity/Tests/Editor) and the sample use, hand-written so they
// compile and run under mono in CI without Unity (test unity_editmode_stub).
// Signatures follow Unity's and NUnit 3's documentation; behaviour is only
// what the tests need: AssetDatabase reads TextAssets of registered package
// folders from disk, Undo/EditorUtility do no bookkeeping.
using System;
using System.Collections.Generic;
using System.IO;
using UnityEngine;

namespace UnityEditor
{
    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        public MenuItem(string itemName) { }
        public MenuItem(string itemName, bool isValidateFunction) { }
    }

    public static class Selection
    {
        public static GameObject[] gameObjects = new GameObject[0];
    }

    public static class AssetDatabase
    {
        /// <summary>Package name -> folder on disk, for "Packages/name/..." asset paths.</summary>
        public static readonly Dictionary<string, string> PackageFolders = new Dictionary<string, string>();

        public static T LoadAssetAtPath<T>(string assetPath) where T : UnityEngine.Object
        {
            if (typeof(T) != typeof(TextAsset) || assetPath == null) return null;
            string[] parts = assetPath.Split(new[] { '/' }, 3);
            string folder;
            if (parts.Length < 3 || parts[0] != "Packages" || !PackageFolders.TryGetValue(parts[1], out folder)) return null;
            string file = Path.Combine(folder, parts[2]);
            if (!File.Exists(file)) return null;
            return new TextAsset(File.ReadAllText(file)) { name = Path.GetFileNameWithoutExtension(file) } as T;
        }

        /// <summary>Assets "saved" by CreateAsset: asset path -> object (nothing is written to disk).</summary>
        public static readonly Dictionary<string, UnityEngine.Object> Created = new Dictionary<string, UnityEngine.Object>();

        public static void CreateAsset(UnityEngine.Object asset, string path)
        {
            if (asset == null || string.IsNullOrEmpty(path) || !path.StartsWith("Assets/"))
                throw new ArgumentException("CreateAsset needs an object and a path under Assets/: " + path);
            Created[path] = asset;
        }

        public static string GenerateUniqueAssetPath(string path) { return path; }

        public static string GetAssetPath(UnityEngine.Object asset)
        {
            foreach (var kv in Created)
                if (kv.Value == asset) return kv.Key;
            return "";
        }
    }

    public static class PrefabUtility
    {
        public static string GetPrefabAssetPathOfNearestInstanceRoot(UnityEngine.Object instance) { return ""; }
    }

    public static class Undo
    {
        public static T AddComponent<T>(GameObject gameObject) where T : Component, new() { return gameObject.AddComponent<T>(); }
        public static void RecordObject(UnityEngine.Object objectToUndo, string name) { }
    }

    public static class EditorUtility
    {
        public static void SetDirty(UnityEngine.Object target) { }
        public static bool IsPersistent(UnityEngine.Object target) { return false; }
    }

    public static class PlayerSettings
    {
        public static bool legacyClampBlendShapeWeights;
    }
}

namespace NUnit.Framework
{
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class TestAttribute : Attribute { }

    [AttributeUsage(AttributeTargets.Method)]
    public sealed class SetUpAttribute : Attribute { }

    [AttributeUsage(AttributeTargets.Method)]
    public sealed class TearDownAttribute : Attribute { }

    public sealed class AssertionException : Exception
    {
        public AssertionException(string message) : base(message) { }
    }

    public static class Assert
    {
        public static void IsTrue(bool condition, string message)
        {
            if (!condition) throw new AssertionException(message);
        }

        public static void IsNotNull(object anObject, string message)
        {
            if (anObject == null) throw new AssertionException(message);
        }

        public static void AreEqual(object expected, object actual, string message)
        {
            if (!Equals(expected, actual))
                throw new AssertionException(message + ": expected " + expected + ", got " + actual);
        }
    }
}
