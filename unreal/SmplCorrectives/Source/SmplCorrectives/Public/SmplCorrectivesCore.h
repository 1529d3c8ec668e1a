// SmplCorrectivesCore.h: the engine-independent corrective core of smpl-export's
// C++ runtimes (header-only, C++17 standard library only, double precision).
//
// Why a separate header: Unreal cannot run on our CI machines, so everything
// that can be wrong (the formula, the metadata's weight mapping, the corrective
// basis, the axis conversion) lives here, where GoogleTest checks it against the
// C++ reference forward pass (tests/unit/unreal/runtime_core_test.cpp). The Unreal
// plugin (SmplCorrectives module) only copies bone rotations in and weights out.
//
// The robust runtime formula (docs/file-contract.md), for model joint k with
// world rotations Q taken in one common engine space (e.g. component space):
//
//   D_k = Q_k(now) Q_k(rest)^-1      world rotation change since bind
//   L_k = D_p(k)^-1 D_k              the joint's own rotation, engine axes
//   R_k = C^-1 L_k C                 C: model axes -> engine axes (any orthogonal
//                                    matrix, mirrors included: Unreal is left-handed)
//   f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc          (P = 9(K-1) features)
//
// Weight mapping (metadata "correctives"): w = scale f[feature] + offset, and
// w = max(0, scale f[feature] + offset) for entries with "rectified": true
// (the "split" encoding). Corrective basis (--corrective-basis):
// w_k = scale_k (M f)_k + offset_k, M K x P row-major.
//
// Usage:
//   smpl_correctives::Layout layout = ...;          // filled from the sidecar
//   std::string error = smpl_correctives::validate(layout);
//   smpl_correctives::Evaluator ev;
//   error = ev.bind(layout, axes /* C */, rest /* K Q_k(rest) */);
//   ev.evaluate(now /* K Q_k(now) */);                // ev.features(), ev.weights()
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace smpl_correctives {

/// 3x3 matrix, row-major: m[3 * r + c].
using Mat3 = std::array<double, 9>;

inline Mat3 identity() { return {1, 0, 0, 0, 1, 0, 0, 0, 1}; }

inline Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 out{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
  return out;
}

inline Mat3 transpose(const Mat3& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}

/// Rotation matrix of the quaternion (x, y, z, w) (Hamilton, any norm > 0:
/// scaled by 2/|q|^2), as Unreal's FQuat and Unity's Quaternion store it.
inline Mat3 fromQuaternion(double x, double y, double z, double w) {
  double n = x * x + y * y + z * z + w * w;
  double s = n > 0 ? 2.0 / n : 0.0;
  return {1 - s * (y * y + z * z), s * (x * y - w * z),     s * (x * z + w * y),
          s * (x * y + w * z),     1 - s * (x * x + z * z), s * (y * z - w * x),
          s * (x * z - w * y),     s * (y * z + w * x),     1 - s * (x * x + y * y)};
}

/// The rotation of a matrix whose columns may carry a scale (centimetres, a
/// scaled bone): each column divided by its length.
inline Mat3 withUnitColumns(const Mat3& a) {
  Mat3 out = a;
  for (int c = 0; c < 3; ++c) {
    double n = std::sqrt(a[c] * a[c] + a[3 + c] * a[3 + c] + a[6 + c] * a[6 + c]);
    if (n > 0)
      for (int r = 0; r < 3; ++r) out[3 * r + c] /= n;
  }
  return out;
}

/// C for smpl-export's FBX (+Y up, right-handed, metres) imported by Unreal's
/// FBX importer with default options (Z up, left-handed): the FBX SDK converts
/// (x, y, z) -> (x, -z, y) (Y up -> Z up) and Unreal then negates Y, so model
/// (x, y, z) -> Unreal (x, z, y). A mirror (det -1). Derived from the two
/// documented conversions, not measured inside Unreal (unreal/README.md, "Axes";
/// tests/unit/unreal/runtime_core_test.cpp derives it on its own).
inline Mat3 unrealFbxAxes() { return {1, 0, 0, 0, 0, 1, 0, 1, 0}; }

/// One corrective morph target of the metadata's "correctives" array.
struct Corrective {
  std::string target;  ///< morph target name, e.g. pose_left_knee_12 or ..._12_pos
  int feature = 0;     ///< index n into f, 0 <= n < P
  double scale = 1.0;  ///< weight = scale * f[n] + offset
  double offset = 0.0;
  bool rectified = false;  ///< weight = max(0, scale * f[n] + offset) (split encoding)
};

/// The metadata's "corrective_basis" (absent: empty targets).
struct Basis {
  std::vector<std::string> targets;   ///< B morph target names, pose_basis_<k>
  std::vector<double> matrix;         ///< B x P, row-major
  std::vector<double> scale, offset;  ///< B each
};

/// The fields of the sidecar <file>.smpl.json the correctives need
/// (docs/file-contract.md, "Metadata"); engine glue fills it from its JSON reader.
struct Layout {
  std::vector<std::string> joint_names;  ///< K, the model authors' names
  /// K or empty: --skeleton-names mixamo|ue5, the bone of each joint in the file
  /// ("thigh_l"); empty when the bones carry joint_names
  std::vector<std::string> bone_names;
  std::vector<int> parents;              ///< K, -1 for the root, parents[k] < k
  std::string up_axis = "+Y";
  std::vector<Corrective> correctives;
  Basis basis;
  int featureCount() const { return parents.empty() ? 0 : 9 * (int(parents.size()) - 1); }
};

/// Empty when the layout is usable, else one line naming the problem.
inline std::string validate(const Layout& layout) {
  size_t k = layout.parents.size();
  if (k == 0 || layout.joint_names.size() != k)
    return "metadata: 'joint_names' and 'parents' must be non-empty and of one length";
  if (!layout.bone_names.empty() && layout.bone_names.size() != k)
    return "metadata: 'bone_names' must be as long as 'joint_names'";
  if (layout.parents[0] != -1) return "metadata: 'parents'[0] must be -1 (the root)";
  for (size_t j = 1; j < k; ++j)
    if (layout.parents[j] < 0 || size_t(layout.parents[j]) >= j)
      return "metadata: 'parents'[" + std::to_string(j) +
             "] = " + std::to_string(layout.parents[j]) + "; expected 0 <= parent < " +
             std::to_string(j);
  int p = layout.featureCount();
  for (size_t i = 0; i < layout.correctives.size(); ++i) {
    const Corrective& c = layout.correctives[i];
    if (c.feature < 0 || c.feature >= p)
      return "metadata: 'correctives'[" + std::to_string(i) +
             "].feature = " + std::to_string(c.feature) + "; expected 0 <= feature < " +
             std::to_string(p);
    if (!std::isfinite(c.scale) || !std::isfinite(c.offset))
      return "metadata: 'correctives'[" + std::to_string(i) + "] has a non-finite scale or offset";
  }
  const Basis& b = layout.basis;
  size_t rows = b.targets.size();
  if (b.matrix.size() != rows * size_t(p) || b.scale.size() != rows || b.offset.size() != rows)
    return "metadata: 'corrective_basis' has " + std::to_string(b.matrix.size()) +
           " matrix values for " + std::to_string(rows) + " targets; expected targets x " +
           std::to_string(p);
  for (const std::vector<double>* v : {&b.matrix, &b.scale, &b.offset})
    for (double x : *v)
      if (!std::isfinite(x)) return "metadata: 'corrective_basis' holds a non-finite number";
  return "";
}

/// Empty when C is orthogonal (1e-6), else the problem.
inline std::string checkAxes(const Mat3& c) {
  Mat3 ctc = multiply(transpose(c), c);
  for (int i = 0; i < 9; ++i)
    if (std::fabs(ctc[i] - (i % 4 == 0 ? 1.0 : 0.0)) > 1e-6)
      return "axis map: matrix is not orthogonal";
  return "";
}

/// Pose features f (P) from world rotations; C and the rest pose bound once.
/// Joints without a bone in the engine (missing[k]) are rigid with their parent.
class Evaluator {
 public:
  /// rest: K world rotations at bind, Q_k(rest) (columns may carry scale).
  /// axes: C. Returns an error line, or empty.
  std::string bind(const Layout& layout, const Mat3& axes, const std::vector<Mat3>& rest,
                   const std::vector<bool>& missing = {}) {
    std::string error = validate(layout);
    if (error.empty()) error = checkAxes(axes);
    if (error.empty() && rest.size() != layout.parents.size())
      error = "rest pose: " + std::to_string(rest.size()) + " rotations; expected " +
              std::to_string(layout.parents.size());
    if (!error.empty()) return error;
    layout_ = layout;
    axes_ = axes;
    axes_inv_ = transpose(axes);
    missing_ = missing.empty() ? std::vector<bool>(rest.size(), false) : missing;
    missing_.resize(rest.size(), false);
    rest_inv_.resize(rest.size());
    for (size_t k = 0; k < rest.size(); ++k) rest_inv_[k] = transpose(withUnitColumns(rest[k]));
    change_.assign(rest.size(), identity());
    features_.assign(size_t(layout.featureCount()), 0.0);
    weights_.assign(layout.correctives.size() + layout.basis.targets.size(), 0.0);
    bound_ = true;
    return "";
  }

  /// now: K world rotations Q_k(now) in the space of the rest rotations.
  /// Fills features() and weights() (correctives in metadata order, then basis rows).
  void evaluate(const std::vector<Mat3>& now) {
    if (!bound_ || now.size() != rest_inv_.size()) return;
    computeFeatures(now);
    for (size_t i = 0; i < layout_.correctives.size(); ++i)
      weights_[i] = weight(layout_.correctives[i]);
    size_t first = layout_.correctives.size(), p = features_.size();
    for (size_t r = 0; r < layout_.basis.targets.size(); ++r) {
      double sum = 0;
      for (size_t n = 0; n < p; ++n) sum += layout_.basis.matrix[r * p + n] * features_[n];
      weights_[first + r] = layout_.basis.scale[r] * sum + layout_.basis.offset[r];
    }
  }

  /// The weight mapping of one metadata entry for the current features.
  double weight(const Corrective& c) const {
    double w = c.scale * features_[size_t(c.feature)] + c.offset;
    return c.rectified ? std::max(0.0, w) : w;
  }

  const std::vector<double>& features() const { return features_; }
  const std::vector<double>& weights() const { return weights_; }
  /// Morph target name of weights()[i].
  const std::string& targetName(size_t i) const {
    size_t first = layout_.correctives.size();
    return i < first ? layout_.correctives[i].target : layout_.basis.targets[i - first];
  }
  size_t targetCount() const { return weights_.size(); }
  bool bound() const { return bound_; }

 private:
  void computeFeatures(const std::vector<Mat3>& now) {
    for (size_t k = 0; k < now.size(); ++k) {
      if (missing_[k])
        change_[k] = k == 0 ? identity() : change_[size_t(layout_.parents[k])];
      else  // E_k = C^-1 D_k C, so that E_p^-1 E_k = C^-1 L_k C = R_k
        change_[k] =
            multiply(axes_inv_, multiply(multiply(withUnitColumns(now[k]), rest_inv_[k]), axes_));
    }
    for (size_t k = 1; k < now.size(); ++k) {
      Mat3 r = multiply(transpose(change_[size_t(layout_.parents[k])]), change_[k]);
      for (int i = 0; i < 9; ++i)
        features_[9 * (k - 1) + size_t(i)] = r[size_t(i)] - (i % 4 == 0 ? 1.0 : 0.0);
    }
  }

  Layout layout_;
  Mat3 axes_ = identity(), axes_inv_ = identity();
  std::vector<bool> missing_;
  std::vector<Mat3> rest_inv_, change_;
  std::vector<double> features_, weights_;
  bool bound_ = false;
};

}  // namespace smpl_correctives
