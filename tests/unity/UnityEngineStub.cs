// The few UnityEngine types unity/Runtime uses, hand-written so the runtime
// compiles and runs under mono in CI without Unity. Semantics follow Unity's
// documentation where the runtime depends on them: float quaternions with
// Hamilton products, Transform.rotation as the world rotation (derived from
// the parent chain and localRotation), SkinnedMeshRenderer blend shape weights
// on Unity's 0..100 scale, unclamped (legacyClampBlendShapeWeights off).
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 right { get { return new Vector3(1, 0, 0); } }
        public static Vector3 one { get { return new Vector3(1, 1, 1); } }
        public static Vector3 operator +(Vector3 a, Vector3 b) { return new Vector3(a.x + b.x, a.y + b.y, a.z + b.z); }
        public static Vector3 operator -(Vector3 a, Vector3 b) { return new Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
        public float magnitude { get { return (float)Math.Sqrt(x * x + y * y + z * z); } }
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion identity { get { return new Quaternion(0, 0, 0, 1); } }

        public static Quaternion operator *(Quaternion a, Quaternion b)
        {
            return new Quaternion(
                a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
                a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
                a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
        }

        public static Quaternion Inverse(Quaternion q) { return new Quaternion(-q.x, -q.y, -q.z, q.w); }

        // Rotates v by q (unit q): v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z).
        public static Vector3 operator *(Quaternion q, Vector3 v)
        {
            float tx = 2 * (q.y * v.z - q.z * v.y), ty = 2 * (q.z * v.x - q.x * v.z), tz = 2 * (q.x * v.y - q.y * v.x);
            return new Vector3(v.x + q.w * tx + q.y * tz - q.z * ty,
                               v.y + q.w * ty + q.z * tx - q.x * tz,
                               v.z + q.w * tz + q.x * ty - q.y * tx);
        }

        // Unity: angle in degrees, about the normalised axis.
        public static Quaternion AngleAxis(float angle, Vector3 axis)
        {
            double n = Math.Sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
            double h = angle * Math.PI / 360.0, s = n > 0 ? Math.Sin(h) / n : 0;
            return new Quaternion((float)(s * axis.x), (float)(s * axis.y), (float)(s * axis.z), (float)Math.Cos(h));
        }
    }

    public struct Matrix4x4
    {
        public float m00, m01, m02, m03, m10, m11, m12, m13, m20, m21, m22, m23, m30, m31, m32, m33;
    }

    public class Object
    {
        public string name = "";
        // A component is removed from its GameObject, as in Unity; other objects
        // are only dropped by the tests (no scene to remove them from).
        public static void DestroyImmediate(Object obj)
        {
            var c = obj as Component;
            if (c != null && c.gameObject != null) c.gameObject.components.Remove(c);
        }
    }

    public class GameObject : Object
    {
        internal readonly List<Component> components = new List<Component>();
        public readonly Transform transform;

        public GameObject(string name)
        {
            this.name = name;
            transform = new Transform();
            Attach(transform);
        }

        void Attach(Component c)
        {
            c.gameObject = this;
            c.name = name;
            components.Add(c);
        }

        public T AddComponent<T>() where T : Component, new()
        {
            var c = new T();
            Attach(c);
            return c;
        }

        public T GetComponent<T>() where T : Component
        {
            foreach (Component c in components)
                if (c is T) return (T)c;
            return null;
        }

        // Depth first, this object first, as Unity.
        public T[] GetComponentsInChildren<T>(bool includeInactive) where T : Component
        {
            var found = new List<T>();
            Collect(transform, found);
            return found.ToArray();
        }

        public T GetComponentInChildren<T>(bool includeInactive) where T : Component
        {
            T[] all = GetComponentsInChildren<T>(includeInactive);
            return all.Length > 0 ? all[0] : null;
        }

        static void Collect<T>(Transform t, List<T> found) where T : Component
        {
            foreach (Component c in t.gameObject.components)
                if (c is T) found.Add((T)c);
            for (int i = 0; i < t.childCount; ++i) Collect(t.GetChild(i), found);
        }
    }

    public class Component : Object
    {
        public GameObject gameObject;
        public Transform transform { get { return gameObject.transform; } }
        public T GetComponent<T>() where T : Component { return gameObject.GetComponent<T>(); }
    }

    public class Behaviour : Component
    {
        public bool enabled = true;
    }

    public class MonoBehaviour : Behaviour { }

    public class Transform : Component
    {
        Transform parentTransform;
        readonly List<Transform> children = new List<Transform>();
        public Quaternion localRotation = Quaternion.identity;
        public Vector3 localPosition;
        public Vector3 localScale = Vector3.one;

        public Transform parent
        {
            get { return parentTransform; }
            set
            {
                if (parentTransform != null) parentTransform.children.Remove(this);
                parentTransform = value;
                if (value != null) value.children.Add(this);
            }
        }

        public int childCount { get { return children.Count; } }
        public Transform GetChild(int index) { return children[index]; }

        public Quaternion rotation
        {
            get { return parentTransform == null ? localRotation : parentTransform.rotation * localRotation; }
            set { localRotation = parentTransform == null ? value : Quaternion.Inverse(parentTransform.rotation) * value; }
        }
    }

    public class Mesh : Object
    {
        readonly List<string> blendShapeNames = new List<string>();
        Matrix4x4[] bindposeArray = new Matrix4x4[0];
        Vector3[] vertexArray = new Vector3[0];
        public int blendShapeCount { get { return blendShapeNames.Count; } }
        public string GetBlendShapeName(int index) { return blendShapeNames[index]; }
        public Vector3[] vertices
        {
            get { return (Vector3[])vertexArray.Clone(); }
            set { vertexArray = (Vector3[])value.Clone(); }
        }
        public int vertexCount { get { return vertexArray.Length; } }

        // Unity's signature; as Unity, one delta per vertex and a new name per shape.
        public void AddBlendShapeFrame(string shapeName, float frameWeight, Vector3[] deltaVertices,
                                       Vector3[] deltaNormals, Vector3[] deltaTangents)
        {
            if (deltaVertices == null || deltaVertices.Length != vertexArray.Length)
                throw new ArgumentException("deltaVertices must have one entry per vertex");
            if (blendShapeNames.Contains(shapeName)) throw new ArgumentException("blend shape exists: " + shapeName);
            blendShapeNames.Add(shapeName);
        }
        // Unity returns a copy, as here.
        public Matrix4x4[] bindposes
        {
            get { return (Matrix4x4[])bindposeArray.Clone(); }
            set { bindposeArray = (Matrix4x4[])value.Clone(); }
        }
    }

    public class Renderer : Component { }

    public class SkinnedMeshRenderer : Renderer
    {
        public Mesh sharedMesh;
        public Transform[] bones = new Transform[0];
        public Transform rootBone;
        public readonly Dictionary<int, float> weights = new Dictionary<int, float>();

        public void SetBlendShapeWeight(int index, float value)
        {
            if (sharedMesh == null || index < 0 || index >= sharedMesh.blendShapeCount)
                throw new ArgumentOutOfRangeException("index");
            weights[index] = value;
        }

        public float GetBlendShapeWeight(int index)
        {
            float v;
            return weights.TryGetValue(index, out v) ? v : 0f;
        }
    }

    public class TextAsset : Object
    {
        readonly string content;
        public TextAsset() : this("") { }
        public TextAsset(string text) { content = text; }
        public string text { get { return content; } }
    }

    public static class Debug
    {
        public static readonly List<string> Messages = new List<string>();
        public static void Log(object message, Object context) { Messages.Add("info: " + message); }
        public static void LogWarning(object message, Object context) { Messages.Add("warning: " + message); }
        public static void LogError(object message, Object context) { Messages.Add("error: " + message); }
        public static void Log(object message) { Log(message, null); }
        public static void LogWarning(object message) { LogWarning(message, null); }
        public static void LogError(object message) { LogError(message, null); }
    }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class AddComponentMenu : Attribute { public AddComponentMenu(string menuName) { } }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponent : Attribute { public RequireComponent(Type t) { } }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class DisallowMultipleComponent : Attribute { }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class DefaultExecutionOrder : Attribute { public DefaultExecutionOrder(int order) { } }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class TooltipAttribute : Attribute { public TooltipAttribute(string tooltip) { } }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class RangeAttribute : Attribute { public RangeAttribute(float min, float max) { } }

    public static class Mathf
    {
        public const float PI = (float)Math.PI;
        public static float Sin(float f) { return (float)Math.Sin(f); }
    }

    // Settable here so tests can step time; read-only in Unity.
    public static class Time
    {
        public static float time;
    }
}
