// The C++ corrective core of the Unreal plugin
// (unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesCore.h)
// against the reference forward pass (core/math/forward.h):
// - pose features from engine world rotations (mirrored Unreal axes, bones
//   re-oriented by the importer, centimetre scale) equal the reference's to 1e-12;
// - posed vertices rebuilt from morph targets of each encoding (signed, unit,
//   split, corrective basis) with the core's weights and linear blend skinning
//   equal the reference's vertices to 1e-9 m.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/models/model_loader.h"
#include "unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesCore.h"

namespace {

namespace sc = smpl_correctives;
using smpl::BodyModel;

sc::Mat3 toMat3(const Eigen::Matrix3d& m) {
  sc::Mat3 out{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[size_t(3 * r + c)] = m(r, c);
  return out;
}

Eigen::Matrix3d toEigen(const sc::Mat3& m) {
  Eigen::Matrix3d out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = m[size_t(3 * r + c)];
  return out;
}

// An engine's view of the body: C maps model axes to engine axes, every bone
// has an arbitrary rest orientation O_k (importers roll bones, add
// pre-rotations) and a scale (centimetres): Q_k = (C G_k C^-1) O_k * 100.
struct EngineSkeleton {
  Eigen::Matrix3d axes;
  std::vector<Eigen::Matrix3d> bone_orientation;

  std::vector<sc::Mat3> world(const std::vector<Eigen::Matrix4d>& model_world) const {
    std::vector<sc::Mat3> out;
    for (size_t k = 0; k < bone_orientation.size(); ++k) {
      Eigen::Matrix3d g = model_world.empty()
                              ? Eigen::Matrix3d::Identity()
                              : Eigen::Matrix3d(model_world[k].topLeftCorner<3, 3>());
      out.push_back(toMat3(100.0 * axes * g * axes.inverse() * bone_orientation[k]));
    }
    return out;
  }
};

EngineSkeleton unrealSkeleton(int joints, uint64_t seed) {
  EngineSkeleton s;
  s.axes = toEigen(sc::unrealFbxAxes());
  Eigen::VectorXd aa = smpl::samplePoses(joints, 1, seed, 2.0)[0];
  for (int k = 0; k < joints; ++k)
    s.bone_orientation.push_back(smpl::rodrigues(aa.segment<3>(3 * k)));
  return s;
}

sc::Layout signedLayout(const BodyModel& model) {
  sc::Layout layout;
  layout.joint_names = model.joint_names;
  layout.parents = model.parents;
  for (int n = 0; n < layout.featureCount(); ++n)
    layout.correctives.push_back({"t" + std::to_string(n), n});
  return layout;
}

struct PosedCase {
  smpl::ForwardResult reference;
  std::vector<sc::Mat3> rest, now;
};

PosedCase posedCase(const BodyModel& model, const EngineSkeleton& engine, uint64_t seed) {
  smpl::ForwardInput input;
  input.rotations =
      smpl::rotationsFromAxisAngle(smpl::samplePoses(int(model.parents.size()), 1, seed)[0]);
  smpl::Result<smpl::ForwardResult> result = smpl::forward(model, input);
  EXPECT_TRUE(result.ok());
  return {*result, engine.world({}), engine.world(result->world)};
}

// The morph target set of an encoding: base mesh, deltas (3N each), metadata entries.
struct Targets {
  Eigen::MatrixXd base;                // N x 3
  std::vector<Eigen::VectorXd> delta;  // 3N per target, in layout.correctives order
  sc::Layout layout;
};

bool diagonal(int feature) { return (feature % 9) % 4 == 0; }

Targets encode(const BodyModel& model, const Eigen::MatrixXd& v_shaped,
               const std::string& encoding) {
  Targets t{v_shaped, {}, signedLayout(model)};
  t.layout.correctives.clear();
  for (int n = 0; n < t.layout.featureCount(); ++n) {
    Eigen::VectorXd p = model.posedirs.col(n);
    std::string name = "pose_" + std::to_string(n);
    if (encoding == "signed") {
      t.layout.correctives.push_back({name, n, 1.0, 0.0, false});
      t.delta.push_back(p);
    } else if (encoding == "unit") {
      double offset = diagonal(n) ? 1.0 : 0.5;
      t.layout.correctives.push_back({name, n, 0.5, offset, false});
      t.delta.push_back(p / 0.5);
      t.base -= Eigen::Map<const Eigen::Matrix<double, -1, 3, Eigen::RowMajor>>(p.data(),
                                                                                p.size() / 3, 3) *
                2 * offset;
    } else if (diagonal(n)) {  // split, diagonal: one target, delta -2 P, weight -f/2
      t.layout.correctives.push_back({name, n, -0.5, 0.0, false});
      t.delta.push_back(-2.0 * p);
    } else {  // split, off-diagonal: _pos (P, max(f, 0)) and _neg (-P, max(-f, 0))
      t.layout.correctives.push_back({name + "_pos", n, 1.0, 0.0, true});
      t.delta.push_back(p);
      t.layout.correctives.push_back({name + "_neg", n, -1.0, 0.0, true});
      t.delta.push_back(-p);
    }
  }
  return t;
}

// v' = sum_k w_ik G_k [I | -J_k] v_posed (docs/file-contract.md), with the model's weights.
Eigen::MatrixXd skin(const BodyModel& model, const smpl::ForwardResult& ref,
                     const Eigen::MatrixXd& v_posed) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(v_posed.rows(), 3);
  for (size_t k = 0; k < ref.world.size(); ++k) {
    Eigen::Matrix3d r = ref.world[k].topLeftCorner<3, 3>();
    Eigen::Vector3d t =
        ref.world[k].topRightCorner<3, 1>() - r * ref.rest_joints.row(Eigen::Index(k)).transpose();
    for (Eigen::Index i = 0; i < v_posed.rows(); ++i)
      out.row(i) +=
          model.weights(i, Eigen::Index(k)) * (r * v_posed.row(i).transpose() + t).transpose();
  }
  return out;
}

double maxVertexError(const BodyModel& model, const std::string& encoding, uint64_t seed) {
  EngineSkeleton engine = unrealSkeleton(int(model.parents.size()), 99);
  PosedCase c = posedCase(model, engine, seed);
  Targets t = encode(model, c.reference.v_shaped, encoding);
  sc::Evaluator ev;
  EXPECT_EQ(ev.bind(t.layout, sc::unrealFbxAxes(), c.rest), "");
  ev.evaluate(c.now);
  Eigen::MatrixXd v_posed = t.base;
  for (size_t i = 0; i < t.delta.size(); ++i)
    v_posed += ev.weights()[i] * Eigen::Map<const Eigen::Matrix<double, -1, 3, Eigen::RowMajor>>(
                                     t.delta[i].data(), v_posed.rows(), 3);
  return (skin(model, c.reference, v_posed) - c.reference.vertices).cwiseAbs().maxCoeff();
}

const BodyModel& smallModel() {
  static BodyModel model =
      *smpl::loadModel(std::string(SMPL_FIXTURE_DIR) + "/models/smpl_small.npz");
  return model;
}

TEST(RuntimeCore, FeaturesFromUnrealWorldRotationsMatchTheReference) {
  for (const BodyModel* model : {&smallModel(), &smpl::demoBody()}) {
    EngineSkeleton engine = unrealSkeleton(int(model->parents.size()), 5);
    for (uint64_t seed = 1; seed <= 5; ++seed) {
      PosedCase c = posedCase(*model, engine, seed);
      sc::Evaluator ev;
      ASSERT_EQ(ev.bind(signedLayout(*model), sc::unrealFbxAxes(), c.rest), "");
      ev.evaluate(c.now);
      ASSERT_EQ(ev.features().size(), size_t(c.reference.pose_features.size()));
      double worst = 0;
      for (size_t n = 0; n < ev.features().size(); ++n)
        worst = std::max(worst,
                         std::fabs(ev.features()[n] - c.reference.pose_features(Eigen::Index(n))));
      EXPECT_LT(worst, 1e-12) << model->name << " pose " << seed;
      EXPECT_GT(c.reference.pose_features.cwiseAbs().maxCoeff(), 0.1);  // a real pose, not rest
    }
  }
}

TEST(RuntimeCore, TheAxisMapMatters) {
  // With C = I instead of Unreal's mirror the features are wrong: the
  // conversion is not a no-op that a broken implementation could pass.
  EngineSkeleton engine = unrealSkeleton(int(smallModel().parents.size()), 5);
  PosedCase c = posedCase(smallModel(), engine, 3);
  sc::Evaluator ev;
  ASSERT_EQ(ev.bind(signedLayout(smallModel()), sc::identity(), c.rest), "");
  ev.evaluate(c.now);
  double worst = 0;
  for (size_t n = 0; n < ev.features().size(); ++n)
    worst =
        std::max(worst, std::fabs(ev.features()[n] - c.reference.pose_features(Eigen::Index(n))));
  EXPECT_GT(worst, 0.05);
}

// unrealFbxAxes() derived here from the two documented conversions, not
// taken from the function under test: Unreal's FBX importer ("Convert Scene",
// FbxAxisSystem to Z up, right-handed) turns the file's Y-up frame by +90
// degrees about X, (x, y, z) -> (x, -z, y); Unreal then negates Y, its frame
// being left-handed. The product is a mirror with up (+Y) -> +Z.
TEST(RuntimeCore, UnrealAxesAreTheDocumentedConversions) {
  const Eigen::Matrix3d fbx_z_up = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).matrix();
  const Eigen::Matrix3d unreal_y_flip = Eigen::Vector3d(1, -1, 1).asDiagonal();
  const Eigen::Matrix3d expected = unreal_y_flip * fbx_z_up;
  const Eigen::Matrix3d c = toEigen(sc::unrealFbxAxes());
  EXPECT_LT((c - expected).cwiseAbs().maxCoeff(), 1e-15) << c;
  EXPECT_NEAR(c.determinant(), -1.0, 1e-15);                                           // a mirror
  EXPECT_LT((c * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(), 1e-15);  // up
}

TEST(RuntimeCore, VerticesMatchTheReferenceInEveryEncoding) {
  for (const char* encoding : {"signed", "unit", "split"})
    for (uint64_t seed = 1; seed <= 3; ++seed)
      EXPECT_LT(maxVertexError(smallModel(), encoding, seed), 1e-9) << encoding << " pose " << seed;
}

TEST(RuntimeCore, SplitWeightsStayInZeroOne) {
  EngineSkeleton engine = unrealSkeleton(int(smallModel().parents.size()), 5);
  PosedCase c = posedCase(smallModel(), engine, 2);
  Targets t = encode(smallModel(), c.reference.v_shaped, "split");
  sc::Evaluator ev;
  ASSERT_EQ(ev.bind(t.layout, sc::unrealFbxAxes(), c.rest), "");
  ev.evaluate(c.now);
  int zero = 0;
  for (double w : ev.weights()) {
    EXPECT_GE(w, 0.0);
    EXPECT_LE(w, 1.0 + 1e-12);
    zero += w == 0.0;
  }
  EXPECT_GT(zero, 0);  // one of every _pos/_neg pair is clamped
}

TEST(RuntimeCore, BasisWeightsProjectTheFeatures) {
  const BodyModel& model = smallModel();
  EngineSkeleton engine = unrealSkeleton(int(model.parents.size()), 5);
  PosedCase c = posedCase(model, engine, 4);
  sc::Layout layout = signedLayout(model);
  layout.correctives.clear();
  int p = layout.featureCount();
  for (int k = 0; k < 3; ++k) {
    layout.basis.targets.push_back("pose_basis_" + std::to_string(k));
    for (int n = 0; n < p; ++n) layout.basis.matrix.push_back(std::sin(1.0 + k * p + n));
    layout.basis.scale.push_back(0.5 + k);
    layout.basis.offset.push_back(0.25 * k);
  }
  sc::Evaluator ev;
  ASSERT_EQ(ev.bind(layout, sc::unrealFbxAxes(), c.rest), "");
  ev.evaluate(c.now);
  ASSERT_EQ(ev.targetCount(), 3u);
  for (int k = 0; k < 3; ++k) {
    double sum = 0;
    for (int n = 0; n < p; ++n)
      sum += layout.basis.matrix[size_t(k * p + n)] * c.reference.pose_features(n);
    EXPECT_NEAR(ev.weights()[size_t(k)],
                layout.basis.scale[size_t(k)] * sum + layout.basis.offset[size_t(k)], 1e-10);
    EXPECT_EQ(ev.targetName(size_t(k)), "pose_basis_" + std::to_string(k));
  }
}

TEST(RuntimeCore, AMissingBoneIsRigidWithItsParent) {
  const BodyModel& model = smallModel();
  int joints = int(model.parents.size()), missing = joints - 1;
  for (int k = 1; k < joints; ++k)
    if (model.parents[size_t(k)] > 0) missing = k;  // a joint with a non-root parent
  EngineSkeleton engine = unrealSkeleton(joints, 5);
  smpl::ForwardInput input;
  input.rotations = smpl::rotationsFromAxisAngle(smpl::samplePoses(joints, 1, 8)[0]);
  input.rotations[size_t(missing)] = Eigen::Matrix3d::Identity();
  smpl::ForwardResult ref = *smpl::forward(model, input);
  std::vector<sc::Mat3> now = engine.world(ref.world);
  now[size_t(missing)] = sc::Mat3{};  // garbage: must not be read
  std::vector<bool> is_missing(size_t(joints), false);
  is_missing[size_t(missing)] = true;
  sc::Evaluator ev;
  ASSERT_EQ(ev.bind(signedLayout(model), sc::unrealFbxAxes(), engine.world({}), is_missing), "");
  ev.evaluate(now);
  for (size_t n = 0; n < ev.features().size(); ++n)
    EXPECT_NEAR(ev.features()[n], ref.pose_features(Eigen::Index(n)), 1e-12) << n;
}

TEST(RuntimeCore, ValidateNamesTheProblem) {
  sc::Layout layout = signedLayout(smallModel());
  EXPECT_EQ(sc::validate(layout), "");
  sc::Layout bad = layout;
  bad.parents[2] = 5;
  EXPECT_EQ(sc::validate(bad), "metadata: 'parents'[2] = 5; expected 0 <= parent < 2");
  bad = layout;
  bad.correctives[1].feature = layout.featureCount();
  EXPECT_NE(sc::validate(bad).find("'correctives'[1].feature"), std::string::npos);
  bad = layout;
  bad.correctives[0].scale = std::nan("");
  EXPECT_NE(sc::validate(bad).find("non-finite"), std::string::npos);
  bad = layout;
  bad.basis.targets = {"pose_basis_0"};
  EXPECT_NE(sc::validate(bad).find("'corrective_basis'"), std::string::npos);
  sc::Evaluator ev;
  EXPECT_NE(ev.bind(layout, {1, 0, 0, 0, 2, 0, 0, 0, 1},
                    std::vector<sc::Mat3>(layout.parents.size(), sc::identity())),
            "");
  EXPECT_NE(ev.bind(layout, sc::identity(), {}), "");
  EXPECT_FALSE(ev.bound());
}

TEST(RuntimeCore, QuaternionMatchesRodrigues) {
  Eigen::Vector3d aa(0.3, -1.1, 0.7);
  Eigen::Matrix3d r = smpl::rodrigues(aa);
  double angle = aa.norm(), s = std::sin(angle / 2) / angle * 3.0;  // a non-unit quaternion
  sc::Mat3 q = sc::fromQuaternion(aa.x() * s, aa.y() * s, aa.z() * s, std::cos(angle / 2) * 3.0);
  EXPECT_LT((toEigen(q) - r).cwiseAbs().maxCoeff(), 1e-14);
}

}  // namespace
