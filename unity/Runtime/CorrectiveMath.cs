// Pose features of docs/file-contract.md ("The robust runtime formula") from the world
// rotations an engine reports, in plain C# doubles with no UnityEngine
// dependency, so the exact same file runs inside Unity and under mono in CI.
//
//   D_k = Q_k(now) * Q_k(rest)^-1        world rotation change since bind
//   L_k = D_p(k)^-1 * D_k                the joint's own rotation (rest axes)
//   R_k = C^-1 * L_k * C                 C: model axes -> engine axes
//   f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc
//
// Why world rotations and not local ones: importers re-orient bones (FBX
// pre-rotations, handedness conversion), so local rotations are not R_k;
// the world-space change since bind is the same whatever the bone's own axes.
//
// C may be any orthogonal map (a mirror included). An improper C (det -1)
// equals -P with P a proper rotation, and C^-1 L C = P^-1 L P, so the whole
// computation stays in quaternions: per joint three quaternion products and
// one quaternion -> matrix conversion, no allocation.
using System;

namespace SmplExport.Correctives
{
    /// <summary>Rotation quaternion in doubles; component order (x, y, z, w) as UnityEngine.Quaternion.</summary>
    public struct Quat
    {
        public double X, Y, Z, W;

        public Quat(double x, double y, double z, double w)
        {
            X = x; Y = y; Z = z; W = w;
        }

        public static Quat Identity { get { return new Quat(0, 0, 0, 1); } }

        /// <summary>Hamilton product: applies b first, then a (same as Unity's a * b).</summary>
        public static Quat operator *(Quat a, Quat b)
        {
            return new Quat(
                a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
                a.W * b.Y + a.Y * b.W + a.Z * b.X - a.X * b.Z,
                a.W * b.Z + a.Z * b.W + a.X * b.Y - a.Y * b.X,
                a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z);
        }

        public double NormSquared { get { return X * X + Y * Y + Z * Z + W * W; } }

        /// <summary>Inverse; also correct for slightly non-unit input (engine floats).</summary>
        public Quat Inverse()
        {
            double n = NormSquared;
            if (!(n > 0)) return Identity;
            return new Quat(-X / n, -Y / n, -Z / n, W / n);
        }

        public Quat Normalized()
        {
            double n = Math.Sqrt(NormSquared);
            if (!(n > 0)) return Identity;
            return new Quat(X / n, Y / n, Z / n, W / n);
        }

        /// <summary>
        /// Rotation matrix minus identity, row-major, written to out[offset..offset+9].
        /// Scaling by 2/|q|^2 makes non-unit input still give a rotation; the
        /// diagonal is formed directly as -s(y^2+z^2) to keep precision near identity.
        /// </summary>
        public void WriteMatrixMinusIdentity(double[] output, int offset)
        {
            double n = NormSquared;
            double s = n > 0 ? 2.0 / n : 0.0;
            double xs = X * s, ys = Y * s, zs = Z * s;
            double xx = X * xs, yy = Y * ys, zz = Z * zs;
            double xy = X * ys, xz = X * zs, yz = Y * zs;
            double wx = W * xs, wy = W * ys, wz = W * zs;
            output[offset + 0] = -(yy + zz);
            output[offset + 1] = xy - wz;
            output[offset + 2] = xz + wy;
            output[offset + 3] = xy + wz;
            output[offset + 4] = -(xx + zz);
            output[offset + 5] = yz - wx;
            output[offset + 6] = xz - wy;
            output[offset + 7] = yz + wx;
            output[offset + 8] = -(xx + yy);
        }

        /// <summary>
        /// Rotation of a 3x3 block m[row*3+col] that may carry scale (e.g. a
        /// bind pose matrix in centimetres): columns are orthonormalised
        /// (Gram-Schmidt, x then y, z = x cross y) before Shepperd's method.
        /// </summary>
        public static Quat FromMatrix(double[] m)
        {
            double ax = m[0], ay = m[3], az = m[6];   // column 0
            double bx = m[1], by = m[4], bz = m[7];   // column 1
            double na = Math.Sqrt(ax * ax + ay * ay + az * az);
            if (!(na > 0)) return Identity;
            ax /= na; ay /= na; az /= na;
            double d = ax * bx + ay * by + az * bz;
            bx -= d * ax; by -= d * ay; bz -= d * az;
            double nb = Math.Sqrt(bx * bx + by * by + bz * bz);
            if (!(nb > 0)) return Identity;
            bx /= nb; by /= nb; bz /= nb;
            double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
            return FromOrthonormal(ax, bx, cx, ay, by, cy, az, bz, cz);
        }

        // Shepperd: pick the largest of w, x, y, z to divide by.
        static Quat FromOrthonormal(double m00, double m01, double m02, double m10, double m11,
                                    double m12, double m20, double m21, double m22)
        {
            double trace = m00 + m11 + m22;
            if (trace > 0)
            {
                double s = Math.Sqrt(trace + 1.0) * 2.0;
                return new Quat((m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s);
            }
            if (m00 > m11 && m00 > m22)
            {
                double s = Math.Sqrt(1.0 + m00 - m11 - m22) * 2.0;
                return new Quat(0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s);
            }
            if (m11 > m22)
            {
                double s = Math.Sqrt(1.0 + m11 - m00 - m22) * 2.0;
                return new Quat((m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s);
            }
            double t = Math.Sqrt(1.0 + m22 - m00 - m11) * 2.0;
            return new Quat((m02 + m20) / t, (m12 + m21) / t, 0.25 * t, (m10 - m01) / t);
        }
    }

    /// <summary>
    /// Pose features for one skeleton. Build with Create(), set the rest
    /// rotations once, then call Compute() every frame. All rotations passed
    /// in must be in one common space (world, or the mesh's local space).
    /// </summary>
    public sealed class CorrectiveMath
    {
        /// <summary>Unity's import of glTF and FBX: model (x, y, z) -> Unity (-x, y, z).</summary>
        public static readonly double[] MirrorX = { -1, 0, 0, 0, 1, 0, 0, 0, 1 };
        /// <summary>UniGLTF's older "ReverseZ" axis conversion: (x, y, z) -> (x, y, -z).</summary>
        public static readonly double[] MirrorZ = { 1, 0, 0, 0, 1, 0, 0, 0, -1 };
        public static readonly double[] IdentityMap = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };

        readonly int[] parents;
        readonly bool[] hasBone;
        readonly Quat axis;          // P, the proper rotation with C = +-P
        readonly Quat axisInverse;
        readonly Quat[] restInverseTimesAxis;  // Q_k(rest)^-1 * P, precomputed
        readonly Quat[] change;                // E_k = P^-1 D_k P, per frame

        public int JointCount { get { return parents.Length; } }
        public int FeatureCount { get { return 9 * (parents.Length - 1); } }

        CorrectiveMath(int[] parents, Quat axis)
        {
            this.parents = (int[])parents.Clone();
            this.axis = axis;
            axisInverse = axis.Inverse();
            hasBone = new bool[parents.Length];
            restInverseTimesAxis = new Quat[parents.Length];
            change = new Quat[parents.Length];
            for (int k = 0; k < parents.Length; ++k)
            {
                hasBone[k] = true;
                restInverseTimesAxis[k] = axis;
            }
        }

        /// <summary>
        /// parents: K entries, parents[0] == -1, 0 <= parents[k] < k.
        /// axisMap: 3x3 row-major, column j = engine coordinates of model axis j;
        /// must be orthogonal up to a uniform scale. Returns null and sets error otherwise.
        /// </summary>
        public static CorrectiveMath Create(int[] parents, double[] axisMap, out string error)
        {
            error = CheckParents(parents);
            if (error != null) return null;
            Quat axis;
            error = AxisRotation(axisMap, out axis);
            if (error != null) return null;
            return new CorrectiveMath(parents, axis);
        }

        static string CheckParents(int[] parents)
        {
            if (parents == null || parents.Length < 1) return "parents: empty joint table";
            if (parents[0] != -1) return "parents: joint 0 must be the root (parent -1), found " + parents[0];
            for (int k = 1; k < parents.Length; ++k)
                if (parents[k] < 0 || parents[k] >= k)
                    return "parents: joint " + k + " has parent " + parents[k] + "; parents must precede their children";
            return null;
        }

        // C = s * sign * P with P a proper rotation; returns P as a quaternion.
        static string AxisRotation(double[] c, out Quat axis)
        {
            axis = Quat.Identity;
            if (c == null || c.Length != 9) return "axis map: expected 9 values (3x3 row-major)";
            double det = c[0] * (c[4] * c[8] - c[5] * c[7]) - c[1] * (c[3] * c[8] - c[5] * c[6]) +
                         c[2] * (c[3] * c[7] - c[4] * c[6]);
            if (!(Math.Abs(det) > 1e-12)) return "axis map: matrix is singular";
            double scale = Math.Pow(Math.Abs(det), 1.0 / 3.0);
            double sign = det < 0 ? -1.0 : 1.0;
            var p = new double[9];
            for (int i = 0; i < 9; ++i) p[i] = c[i] * sign / scale;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                {
                    double dot = p[i] * p[j] + p[3 + i] * p[3 + j] + p[6 + i] * p[6 + j];
                    if (Math.Abs(dot - (i == j ? 1.0 : 0.0)) > 1e-6)
                        return "axis map: matrix is not orthogonal (columns " + i + " and " + j + ")";
                }
            axis = Quat.FromMatrix(p);
            return null;
        }

        /// <summary>Rest (bind) rotation of joint k, in the same space as the per-frame rotations.</summary>
        public void SetRest(int joint, Quat restRotation)
        {
            restInverseTimesAxis[joint] = restRotation.Inverse() * axis;
            hasBone[joint] = true;
        }

        /// <summary>
        /// Joint k has no bone in the engine: it is treated as rigidly attached to
        /// its parent (R_k = I), and its children are measured against the parent.
        /// </summary>
        public void SetMissing(int joint)
        {
            hasBone[joint] = false;
        }

        public bool HasBone(int joint) { return hasBone[joint]; }

        /// <summary>
        /// current: K rotations (entries of missing joints are ignored);
        /// features: at least FeatureCount values, overwritten.
        /// </summary>
        public void Compute(Quat[] current, double[] features)
        {
            int count = parents.Length;
            for (int k = 0; k < count; ++k)
            {
                if (hasBone[k])
                    change[k] = Multiply(axisInverse, Multiply(current[k], restInverseTimesAxis[k]));
                else
                    change[k] = k == 0 ? Quat.Identity : change[parents[k]];
            }
            for (int k = 1; k < count; ++k)
            {
                // conj(E_p) * E_k, written out: mono's JIT does not inline the operator.
                Quat a = change[parents[k]], b = change[k];
                var local = new Quat(
                    a.W * b.X - a.X * b.W - a.Y * b.Z + a.Z * b.Y,
                    a.W * b.Y - a.Y * b.W - a.Z * b.X + a.X * b.Z,
                    a.W * b.Z - a.Z * b.W - a.X * b.Y + a.Y * b.X,
                    a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z);
                local.WriteMatrixMinusIdentity(features, 9 * (k - 1));
            }
        }

        /// <summary>
        /// The weight mapping of a "correctives" entry (docs/file-contract.md):
        /// scale * feature + offset, clamped below at 0 when the entry is
        /// "rectified" (the split encoding's _pos/_neg targets).
        /// </summary>
        public static double Weight(double feature, double scale, double offset, bool rectified)
        {
            double w = scale * feature + offset;
            return rectified && !(w > 0) ? 0.0 : w;
        }

        /// <summary>
        /// Weights of basis blend shapes (--corrective-basis): for each i,
        /// weights[i] = scale[rows[i]] * (matrix row rows[i] . features) + offset[rows[i]],
        /// matrix row-major with FeatureCount columns. No allocation.
        /// </summary>
        public static void ProjectBasis(CorrectiveBasisLayout basis, int[] rows, double[] features, double[] weights)
        {
            int p = basis.FeatureCount;
            for (int i = 0; i < rows.Length; ++i)
            {
                int r = rows[i], start = r * p;
                double sum = 0;
                for (int n = 0; n < p; ++n) sum += basis.Matrix[start + n] * features[n];
                weights[i] = basis.Scale[r] * sum + basis.Offset[r];
            }
        }

        static Quat Multiply(Quat a, Quat b)
        {
            return new Quat(
                a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
                a.W * b.Y + a.Y * b.W + a.Z * b.X - a.X * b.Z,
                a.W * b.Z + a.Z * b.W + a.X * b.Y - a.Y * b.X,
                a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z);
        }
    }
}
