// The mirrored body model (core/math/mirror_model.h): for every pose,
// mirrored(S R S) = S model(R), checked with the reference forward pass.
#include "core/math/mirror_model.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "core/models/model_loader.h"

namespace smpl {
namespace {

const std::string kModels = std::string(SMPL_FIXTURE_DIR) + "/models/";

TEST(MirrorModel, MirroredPoseGivesTheMirroredBody) {
  for (const char* file : {"mano_small.npz", "smplx_small.npz"}) {
    Result<BodyModel> model = loadModel(kModels + file);
    ASSERT_TRUE(model.ok()) << model.message();
    const BodyModel mirrored = mirrorModel(*model);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    for (int pose = 0; pose < 4; ++pose) {
      ForwardInput in, out;
      Eigen::VectorXd aa(3 * model->numJoints());
      for (Eigen::Index i = 0; i < aa.size(); ++i) aa[i] = u(rng);
      in.rotations = rotationsFromAxisAngle(aa);
      in.betas =
          Eigen::VectorXd::NullaryExpr(std::min(model->numBetas(), 8), [&] { return u(rng); });
      in.expression =
          Eigen::VectorXd::NullaryExpr(model->numExpressions() > 0 ? 5 : 0, [&] { return u(rng); });
      in.translation = Eigen::Vector3d(0.2, -0.1, 0.4);
      out = in;
      for (Eigen::Matrix3d& r : out.rotations) r = mirrorRotation(r);
      out.translation.x() *= -1;
      Result<ForwardResult> a = forward(*model, in), b = forward(mirrored, out);
      ASSERT_TRUE(a.ok() && b.ok());
      Eigen::MatrixXd expected = a->vertices;
      expected.col(0) *= -1.0;
      EXPECT_LT((b->vertices - expected).cwiseAbs().maxCoeff(), 1e-12) << file << " " << pose;
    }
    // Winding: the mirrored rest mesh's face normals are the mirrored normals.
    const auto normal = [](const BodyModel& m, int f) {
      const Eigen::Vector3d p0 = m.v_template.row(m.faces(f, 0)),
                            p1 = m.v_template.row(m.faces(f, 1)),
                            p2 = m.v_template.row(m.faces(f, 2));
      return Eigen::Vector3d((p1 - p0).cross(p2 - p0));
    };
    for (int f : {0, 7}) {
      Eigen::Vector3d n = normal(*model, f);
      n.x() *= -1;
      EXPECT_LT((normal(mirrored, f) - n).norm(), 1e-12) << file;
    }
  }
}

TEST(MirrorModel, SideFromTheFileName) {
  BodyModel m;
  m.name = "MANO_LEFT.pkl";
  EXPECT_EQ(manoSide(m), "left");
  m.name = "MANO_RIGHT.pkl";
  EXPECT_EQ(manoSide(m), "right");
  m.name = "mano_small.npz";
  EXPECT_EQ(manoSide(m), "right");
}

}  // namespace
}  // namespace smpl
