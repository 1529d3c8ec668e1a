#include "exporter/dmpl_targets.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "core/models/validate_inputs.h"
#include "core/os/path.h"
#include "exporter/joint_shift_cost.h"

namespace smpl {

std::vector<DmplLayout> dmplLayout(int directions,
                                   const std::vector<const Eigen::MatrixXd*>& coefficients) {
  std::vector<DmplLayout> layout;
  for (int i = 0; i < directions; ++i) {
    double lo = 0.0, hi = 0.0;
    for (const Eigen::MatrixXd* c : coefficients)
      if (c && c->rows() > 0 && c->cols() > i) {
        lo = std::min(lo, c->col(i).minCoeff());
        hi = std::max(hi, c->col(i).maxCoeff());
      }
    DmplLayout d{i, "dmpl_" + std::to_string(i), 1.0, 0.0};
    if (hi - lo > 1e-300) {
      d.scale = 1.0 / (hi - lo);
      d.offset = -lo * d.scale;
    }
    layout.push_back(d);
  }
  return layout;
}

void addDmplTargets(const BodyModel& model, const DmplBasis& basis,
                    const std::vector<DmplLayout>& layout, bool animate_joints, Asset* asset) {
  SkinnedMesh& mesh = asset->mesh;
  DmplInfo& info = asset->metadata.dmpl;
  info.basis = os::utf8(os::fsPath(basis.path).filename());
  info.animate_joints = animate_joints;
  info.targets = layout;
  const int k = model.numJoints(), n = model.numVertices();
  info.joint_directions.resize(3 * k, static_cast<Eigen::Index>(layout.size()));
  for (const DmplLayout& d : layout) {
    const Eigen::VectorXd& dir = basis.directions.col(d.direction);
    MorphTarget t;
    t.name = d.target;
    t.rest_weight = static_cast<float>(d.offset);
    t.deltas.resize(static_cast<Eigen::Index>(mesh.source_vertex.size()), 3);
    for (size_t i = 0; i < mesh.source_vertex.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double v = dir(3 * mesh.source_vertex[i] + c);
        t.deltas(i, c) = static_cast<float>(v / d.scale);
        // weight * delta = c d + (offset/scale) d: remove the constant part from the base mesh.
        mesh.positions(i, c) = static_cast<float>(mesh.positions(i, c) - (d.offset / d.scale) * v);
      }
    mesh.morph_targets.push_back(std::move(t));
    const Eigen::MatrixXd as_rows =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(dir.data(), n,
                                                                                    3);
    const Eigen::MatrixXd joints = model.j_regressor * as_rows;  // K x 3
    for (int j = 0; j < k; ++j)
      for (int c = 0; c < 3; ++c) info.joint_directions(3 * j + c, d.direction) = joints(j, c);
  }
}

Eigen::VectorXd dmplAt(const Motion& motion, int frame, double t, int directions) {
  Eigen::VectorXd c = Eigen::VectorXd::Zero(directions);
  if (motion.dmpls.rows() == 0) return c;
  const int last = static_cast<int>(motion.dmpls.rows()) - 1;
  const int f0 = std::min(frame, last), f1 = std::min(frame + 1, last);
  const int d = std::min<int>(directions, static_cast<int>(motion.dmpls.cols()));
  c.head(d) = (1 - t) * motion.dmpls.row(f0).head(d).transpose() +
              t * motion.dmpls.row(f1).head(d).transpose();
  return c;
}

Status applyDmplFrame(const Asset& asset, const Eigen::VectorXd& c, const Rotations& local,
                      const Eigen::Matrix3d& up, int frame, AnimationClip* clip) {
  const DmplInfo& info = asset.metadata.dmpl;
  std::map<std::string, int> index;
  for (size_t i = 0; i < asset.mesh.morph_targets.size(); ++i)
    index[asset.mesh.morph_targets[i].name] = static_cast<int>(i);
  for (const DmplLayout& d : info.targets)
    clip->morph_weights(frame, index.at(d.target)) =
        static_cast<float>(d.scale * c[d.direction] + d.offset);
  const Skeleton& s = asset.skeleton;
  const int k = static_cast<int>(s.parents.size());
  const Eigen::VectorXd flat = info.joint_directions * c;
  const Eigen::MatrixXd delta =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(flat.data(), k,
                                                                                  3);
  clip->dmpl_joint_error =
      std::max(clip->dmpl_joint_error, jointShiftCost(s, asset.mesh, delta, local, up));
  if (!info.animate_joints) return Status();
  if (clip->joint_translations.empty()) {
    const uint64_t bytes = static_cast<uint64_t>(k) *
                           static_cast<uint64_t>(clip->morph_weights.rows()) *
                           sizeof(Eigen::Vector3d);
    if (Status st =
            clip->charge.add(bytes, clip->name, "joint translations (--dmpl-joints regressed)");
        !st)
      return st;
    clip->joint_translations.assign(k, std::vector<Eigen::Vector3d>(clip->morph_weights.rows()));
  }
  for (int j = 0; j < k; ++j) {
    const Eigen::Vector3d dj = delta.row(j).transpose();
    if (j == 0) {
      clip->root_translation[frame] += up * dj - local[0] * dj;
      clip->joint_translations[0][frame] = clip->root_translation[frame];
    } else {
      clip->joint_translations[j][frame] = s.rest_local.row(j).transpose() + dj - local[j] * dj;
    }
  }
  return Status();
}

Status checkDmplCoefficients(const Motion& motion, const std::string& path, int directions,
                             const std::string& basis_path) {
  if (!motion.dmpls_problem.empty()) return makeError(motion.dmpls_problem);
  if (motion.dmpls.rows() > 0 && motion.dmpls.cols() != directions)
    return makeError(path + ": 'dmpls' has " + std::to_string(motion.dmpls.cols()) +
                     " columns; the DMPL basis " + basis_path + " has " +
                     std::to_string(directions) + " directions");
  // Finite and plausible where they enter (validate_inputs.h), so 1e39 is a
  // load error naming the motion, not a float32 overflow in the writer.
  return checkDmplValues(motion.dmpls, path);
}

}  // namespace smpl
