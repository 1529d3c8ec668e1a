#include "core/math/mirror_model.h"

#include <algorithm>
#include <cctype>

namespace smpl {
namespace {

// x rows (3i + 0) of a 3N-row matrix negated.
// An empty matrix (a model without expressions: 3N x 0) has no data pointer; Eigen's row() on it
// offsets a null pointer, so it is skipped.
void negateX(Eigen::MatrixXd* m) {
  if (m->size() == 0) return;
  for (Eigen::Index i = 0; i < m->rows(); i += 3) m->row(i) *= -1.0;
}

// 15 axis-angle triples per row (C x 45): y and z negated.
void mirrorHandPca(Eigen::MatrixXd* components) {
  if (components->size() == 0) return;
  for (Eigen::Index c = 0; c < components->cols(); ++c)
    if (c % 3 != 0) components->col(c) *= -1.0;
}

void mirrorHandMean(Eigen::VectorXd* mean) {
  for (Eigen::Index c = 0; c < mean->size(); ++c)
    if (c % 3 != 0) (*mean)[c] *= -1.0;
}

}  // namespace

Eigen::Matrix3d mirrorRotation(const Eigen::Matrix3d& r) {
  const Eigen::Matrix3d s = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  return s * r * s;
}

BodyModel mirrorModel(const BodyModel& model) {
  BodyModel m = model;
  m.name = model.name + " (mirrored)";
  m.v_template.col(0) *= -1.0;
  negateX(&m.shapedirs);
  negateX(&m.exprdirs);
  negateX(&m.posedirs);
  for (Eigen::Index n = 0; n < m.posedirs.cols(); ++n) {
    const int r = static_cast<int>((n % 9) / 3), c = static_cast<int>(n % 3);
    if ((r == 0) != (c == 0)) m.posedirs.col(n) *= -1.0;  // s_r s_c = -1 for exactly one x index
  }
  if (m.faces.size() > 0) m.faces.col(1).swap(m.faces.col(2));
  mirrorHandPca(&m.hands_components_l);
  mirrorHandPca(&m.hands_components_r);
  mirrorHandMean(&m.hands_mean_l);
  mirrorHandMean(&m.hands_mean_r);
  return m;
}

std::string manoSide(const BodyModel& model) {
  std::string name = model.name;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return name.find("left") != std::string::npos ? "left" : "right";
}

}  // namespace smpl
