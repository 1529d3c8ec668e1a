// validateAsset: one pass over every serialised array; the first value that
// is not finite (or, for float32 fields, beyond +-FLT_MAX) is named with its
// place in the asset.
#include "exporter/validate_asset.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/parallel.h"
#include "exporter/validate_structure.h"

namespace smpl {
namespace {

// "nan", "inf", "-inf" or the value (%.6g).
std::string valueText(double v) {
  if (std::isnan(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Empty when v is fine; else the problem. float32 fields must also fit a float.
std::string problem(double v, bool float32) {
  if (!std::isfinite(v)) return "is not finite (" + valueText(v) + ")";
  if (float32 && std::abs(v) > FLT_MAX) return "exceeds the float32 range (" + valueText(v) + ")";
  return "";
}

// Whether every value of a plain matrix is fine: one branch-free pass (a
// NaN fails the comparison), so the usual, valid asset costs a read of each
// array and only a failing one is scanned again for the message.
template <class Matrix>
bool allFine(const Matrix& m, bool float32) {
  using Scalar = typename Matrix::Scalar;
  // A float is within the float32 range when it is finite: compared as
  // float, without a conversion per value.
  const Scalar limit = std::is_same_v<Scalar, float> ? std::numeric_limits<float>::max()
                                                     : Scalar(float32 ? double(FLT_MAX) : DBL_MAX);
  const Scalar* v = m.data();
  int bad = 0;
  for (Eigen::Index i = 0; i < m.size(); ++i) bad |= !(std::abs(v[i]) <= limit);
  return bad == 0;
}

// Rows of a matrix: "<what> <r> <problem>" names the first bad row.
template <class Matrix>
Status checkRows(const Matrix& m, const std::string& what, bool float32) {
  if (allFine(m, float32)) return Status();
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c)
      if (std::string p = problem(static_cast<double>(m(r, c)), float32); !p.empty())
        return makeError(what + " " + std::to_string(r) + " " + p);
  return Status();
}

// Skeleton rows are named by joint: "joint <name> <what> <problem>".
Status checkJoints(const Skeleton& s, const Eigen::MatrixXd& m, const char* what) {
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c)
      if (std::string p = problem(m(r, c), true); !p.empty()) {
        const std::string name =
            static_cast<size_t>(r) < s.names.size() ? s.names[r] : std::to_string(r);
        return makeError("joint " + name + " " + what + " " + p);
      }
  return Status();
}

Status checkList(const std::vector<double>& values, const std::string& what, bool float32) {
  for (size_t i = 0; i < values.size(); ++i)
    if (std::string p = problem(values[i], float32); !p.empty())
      return makeError(what + " " + std::to_string(i) + " " + p);
  return Status();
}

Status checkMesh(const SkinnedMesh& mesh) {
  if (Status st = checkRows(mesh.positions, "mesh position of vertex", true); !st) return st;
  if (Status st = checkRows(mesh.normals, "mesh normal of vertex", true); !st) return st;
  if (Status st = checkRows(mesh.uvs, "mesh uv of vertex", true); !st) return st;
  if (Status st = checkRows(mesh.weights, "skin weight of vertex", true); !st) return st;
  // The targets are most of the asset's bytes: checked on every core, the
  // message (of the first bad one, in order) made after.
  const std::vector<MorphTarget>& targets = mesh.morph_targets;
  std::vector<char> fine(targets.size());
  runWorkers(int(std::min<size_t>(hardwareThreads(), targets.size() / 16 + 1)), [&](int w,
                                                                                    int workers) {
    for (size_t i = size_t(w); i < targets.size(); i += size_t(workers))
      fine[i] = allFine(targets[i].deltas, true) && problem(targets[i].rest_weight, true).empty();
  });
  for (size_t i = 0; i < targets.size(); ++i) {
    if (fine[i]) continue;
    const MorphTarget& t = targets[i];
    if (Status st = checkRows(t.deltas, "morph target " + t.name + " vertex", true); !st) return st;
    if (std::string p = problem(t.rest_weight, true); !p.empty())
      return makeError("morph target " + t.name + " rest weight " + p);
  }
  return Status();
}

Status checkClip(const AnimationClip& clip) {
  const std::string what = "animation " + clip.name;
  if (std::string p = problem(clip.fps, true); !p.empty()) return makeError(what + " fps " + p);
  if (Status st = checkList(clip.times, what + " key time of frame", true); !st) return st;
  for (size_t j = 0; j < clip.rotations.size(); ++j)
    for (size_t f = 0; f < clip.rotations[j].size(); ++f)
      for (int c = 0; c < 4; ++c)
        if (std::string p = problem(clip.rotations[j][f].coeffs()[c], true); !p.empty())
          return makeError(what + " joint " + std::to_string(j) + " frame " + std::to_string(f) +
                           " rotation " + p);
  for (size_t f = 0; f < clip.root_translation.size(); ++f)
    for (int c = 0; c < 3; ++c)
      if (std::string p = problem(clip.root_translation[f][c], true); !p.empty())
        return makeError(what + " frame " + std::to_string(f) + " root translation " + p);
  for (size_t j = 0; j < clip.joint_translations.size(); ++j)
    for (size_t f = 0; f < clip.joint_translations[j].size(); ++f)
      for (int c = 0; c < 3; ++c)
        if (std::string p = problem(clip.joint_translations[j][f][c], true); !p.empty())
          return makeError(what + " joint " + std::to_string(j) + " frame " + std::to_string(f) +
                           " translation " + p);
  return checkRows(clip.morph_weights, what + " morph weights of frame", true);
}

Status checkMetadata(const AssetMetadata& m) {
  if (Status st = checkList(m.betas, "metadata betas", false); !st) return st;
  if (Status st = checkList(m.expression, "metadata expression", false); !st) return st;
  for (const CorrectiveLayout& c : m.correctives)
    for (double v : {c.scale, c.offset})
      if (std::string p = problem(v, false); !p.empty())
        return makeError("metadata corrective " + c.target + " scale/offset " + p);
  for (const DmplLayout& d : m.dmpl.targets)
    for (double v : {d.scale, d.offset})
      if (std::string p = problem(v, false); !p.empty())
        return makeError("metadata dmpl " + d.target + " scale/offset " + p);
  const CorrectiveBasis& b = m.corrective_basis;
  if (Status st = checkRows(b.projection, "metadata corrective basis matrix row", false); !st)
    return st;
  if (Status st = checkList(b.scale, "metadata corrective basis scale", false); !st) return st;
  return checkList(b.offset, "metadata corrective basis offset", false);
}

}  // namespace

Status validateAsset(const Asset& asset) {
  if (Status st = checkJoints(asset.skeleton, asset.skeleton.rest_local, "rest offset"); !st)
    return st;
  if (Status st = checkJoints(asset.skeleton, asset.skeleton.rest_world, "rest position"); !st)
    return st;
  if (Status st = checkMesh(asset.mesh); !st) return st;
  for (const AnimationClip& clip : asset.animations)
    if (Status st = checkClip(clip); !st) return st;
  if (Status st = checkMetadata(asset.metadata); !st) return st;
  return validateAssetStructure(
      asset);  // numbers first: a NaN is named as such, not as a bad weight
}

}  // namespace smpl
