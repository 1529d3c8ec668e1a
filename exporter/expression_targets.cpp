#include "exporter/expression_targets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "exporter/joint_shift_cost.h"

namespace smpl {
namespace {

double restOf(const std::vector<double>& rest, int i) {
  return i < static_cast<int>(rest.size()) ? rest[i] : 0.0;
}

// Target index of every layout entry (by name: the layout is the contract).
std::vector<int> targetIndices(const Asset& asset) {
  std::map<std::string, int> index;
  for (size_t i = 0; i < asset.mesh.morph_targets.size(); ++i)
    index[asset.mesh.morph_targets[i].name] = static_cast<int>(i);
  std::vector<int> out;
  for (const ExpressionLayout& e : asset.metadata.expression_targets.targets)
    out.push_back(index.at(e.target));
  return out;
}

std::string number(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

}  // namespace

std::vector<ExpressionLayout> expressionLayout(
    int count, const std::vector<double>& rest,
    const std::vector<const Eigen::MatrixXd*>& coefficients) {
  std::vector<ExpressionLayout> layout;
  for (int i = 0; i < count; ++i) {
    double lo = 0.0, hi = 0.0;
    for (const Eigen::MatrixXd* c : coefficients)
      if (c && c->rows() > 0 && c->cols() > i) {
        lo = std::min(lo, c->col(i).minCoeff() - restOf(rest, i));
        hi = std::max(hi, c->col(i).maxCoeff() - restOf(rest, i));
      }
    ExpressionLayout e{i, "expr_" + std::to_string(i), 1.0, 0.0};
    if (hi - lo > 1e-300) {
      e.scale = 1.0 / (hi - lo);
      e.offset = -lo * e.scale;
    }
    layout.push_back(e);
  }
  return layout;
}

void encodeExpressionTargets(const BodyModel& model, const std::vector<ExpressionLayout>& layout,
                             Asset* asset) {
  ExpressionInfo& info = asset->metadata.expression_targets;
  info.targets = layout;
  const int k = model.numJoints(), n = model.numVertices();
  info.joint_directions = Eigen::MatrixXd::Zero(3 * k, static_cast<Eigen::Index>(layout.size()));
  const std::vector<int> index = targetIndices(*asset);
  SkinnedMesh& mesh = asset->mesh;
  for (size_t j = 0; j < layout.size(); ++j) {
    const ExpressionLayout& e = layout[j];
    MorphTarget& t = mesh.morph_targets[index[j]];
    const Eigen::VectorXd dir = model.exprdirs.col(e.index);  // 3N, row 3v + c
    for (Eigen::Index i = 0; i < mesh.positions.rows(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double d = dir(3 * mesh.source_vertex[i] + c);
        t.deltas(i, c) = static_cast<float>(d / e.scale);
        mesh.positions(i, c) = static_cast<float>(mesh.positions(i, c) - e.offset / e.scale * d);
      }
    t.rest_weight = static_cast<float>(e.offset);
    const Eigen::MatrixXd as_rows =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(dir.data(), n,
                                                                                    3);
    const Eigen::MatrixXd joints = model.j_regressor * as_rows;  // K x 3
    for (int q = 0; q < k; ++q)
      for (int c = 0; c < 3; ++c) info.joint_directions(3 * q + c, j) = joints(q, c);
  }
}

Eigen::VectorXd expressionAt(const Motion& motion, int frame, double t, int count,
                             const std::vector<double>& rest) {
  Eigen::VectorXd psi(count);
  for (int i = 0; i < count; ++i) psi[i] = restOf(rest, i);
  if (motion.expression.rows() == 0) return psi;
  const int last = static_cast<int>(motion.expression.rows()) - 1;
  const int f0 = std::min(frame, last), f1 = std::min(frame + 1, last);
  const int e = std::min<int>(count, static_cast<int>(motion.expression.cols()));
  psi.head(e) = (1 - t) * motion.expression.row(f0).head(e).transpose() +
                t * motion.expression.row(f1).head(e).transpose();
  return psi;
}

void applyExpressionFrame(const Asset& asset, const Eigen::VectorXd& psi, const Rotations& local,
                          const Eigen::Matrix3d& up, int frame, AnimationClip* clip) {
  const ExpressionInfo& info = asset.metadata.expression_targets;
  const std::vector<int> index = targetIndices(asset);
  Eigen::VectorXd c(static_cast<Eigen::Index>(info.targets.size()));
  for (size_t j = 0; j < info.targets.size(); ++j) {
    const ExpressionLayout& e = info.targets[j];
    c[j] = psi[e.index] - restOf(asset.metadata.expression, e.index);
    clip->morph_weights(frame, index[j]) = static_cast<float>(e.scale * c[j] + e.offset);
  }
  const int k = static_cast<int>(asset.skeleton.parents.size());
  const Eigen::VectorXd flat = info.joint_directions * c;
  const Eigen::MatrixXd delta =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(flat.data(), k,
                                                                                  3);
  clip->expression_joint_error = std::max(
      clip->expression_joint_error, jointShiftCost(asset.skeleton, asset.mesh, delta, local, up));
}

std::vector<std::string> expressionNotes(const Motion& m, int exported, int model_count) {
  std::vector<std::string> notes;
  const int have = static_cast<int>(m.expression.cols());
  if (m.expression.rows() == 0 || have == 0) return notes;
  const double largest = m.expression.cwiseAbs().maxCoeff();
  const int kept = std::min({exported, have, model_count});
  if (exported == 0) {
    notes.push_back(m.name + ": the motion has " + std::to_string(have) +
                    " SMPL-X expression coefficients per frame (largest |value| " +
                    number("%.3g", largest) + "), not baked: add --expression-keys " +
                    std::to_string(std::min(have, std::max(model_count, 1))) +
                    " to bake them as expr_<i> weights");
    return notes;
  }
  if (kept < have) {
    const double dropped = m.expression.rightCols(have - kept).cwiseAbs().maxCoeff();
    notes.push_back(m.name + ": " + std::to_string(kept) + " of the motion's " +
                    std::to_string(have) + " expression coefficients are baked (" +
                    (exported < model_count ? "--expression-keys " + std::to_string(exported)
                                            : "the model has " + std::to_string(model_count)) +
                    "); the largest dropped |value| is " + number("%.3g", dropped));
  }
  return notes;
}

}  // namespace smpl
