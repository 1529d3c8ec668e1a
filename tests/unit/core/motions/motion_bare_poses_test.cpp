// Bare pose arrays (core/motions/motion_bare_poses.h): which root arrays the
// row takes, that they are read as AMASS's `poses`, and the joint-position
// refusal. Trees are built in code; the end-to-end numbers (three.js against
// numpy) are tests/cli/layouts/generation_cases.py's bare_* cases.
#include "core/motions/motion_bare_poses.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/math/forward.h"
#include "tests/unit/test_util.h"

namespace smpl {
namespace {

using test::numbers;

using test::leaf;

Result<MotionSet> decode(const DataNode& root) {
  MotionSet set;
  if (Status st = barePosesLayout().decode(root, LayoutInput{"x.npy", MotionOptions()}, &set); !st)
    return st.error();
  return set;
}

std::string found(const std::vector<int64_t>& shape, unsigned container) {
  int64_t n = 1;
  for (int64_t s : shape) n *= s;
  const MotionLayout* row = findLayout(leaf(numbers(shape, std::vector<double>(n))), container);
  return row ? row->name : "none";
}

TEST(BarePoses, DetectedByShapeInArrayContainers) {
  EXPECT_EQ(found({8, 165}, kNpyFile), "bare_poses");
  EXPECT_EQ(found({8, 72}, kPickleFile), "bare_poses");
  EXPECT_EQ(found({8, 52, 3}, kTorchFile), "bare_poses");
  EXPECT_EQ(found({8, 16, 3, 3}, kJoblibFile), "bare_poses");
  EXPECT_EQ(found({8, 322}, kNpyFile), "motionx");      // Motion-X's widths stay Motion-X's
  EXPECT_EQ(found({8, 22, 3}, kNpyFile), "positions");  // HumanML3D joints stay refused
  EXPECT_EQ(found({8, 99}, kNpyFile), "none");
  EXPECT_EQ(found({8, 46}, kNpyFile), "none");
  EXPECT_EQ(found({8, 3, 55}, kNpyFile), "none");
  EXPECT_EQ(found({0, 165}, kNpyFile), "none");
}

TEST(BarePoses, ReadAsPosesWithNoTranslation) {
  std::vector<double> data(2 * 24 * 3, 0.0);
  data[3 * 5 + 1] = 0.4;         // frame 0, joint 5, y
  data[72 + 3 * 23 + 2] = -0.7;  // frame 1, joint 23, z
  Result<MotionSet> set = decode(leaf(numbers({2, 24, 3}, data)));
  ASSERT_TRUE(set.ok()) << set.message();
  const Motion& m = set->tracks.at(0);
  EXPECT_EQ(m.layout, ModelKind::Smpl);
  ASSERT_EQ(m.frames.size(), 2u);
  EXPECT_TRUE(m.frames[0][5].isApprox(rotationsFromAxisAngle(Eigen::Vector3d(0, 0.4, 0))[0]));
  EXPECT_TRUE(m.frames[1][23].isApprox(rotationsFromAxisAngle(Eigen::Vector3d(0, 0, -0.7))[0]));
  EXPECT_TRUE(m.translation.at(1).isZero());
  EXPECT_EQ(m.world, MotionWorld::Y);
  EXPECT_EQ(m.fps, 0.0);  // loadMotion settles the row's 30 fps with a note
  EXPECT_EQ(barePosesLayout().fps_fallback, 30.0);
  ASSERT_FALSE(m.notes.empty());
  EXPECT_EQ(m.notes[0],
            "a bare pose array (2,24,3): read as SMPL poses (24 joints, axis-angle) in the model's "
            "joint order; no translation or betas in the file");
}

TEST(BarePoses, RigidJointPositionsAreRefused) {
  // Joint 0 moves along x; joints 1-3 keep 14, 14 and 12 cm from it: a skeleton, not rotations.
  std::vector<double> data(3 * 72, 0.3);
  for (int f = 0; f < 3; ++f) {
    double* p = data.data() + 72 * f;
    p[0] = 0.5 * f;
    p[3] = p[0] + 0.1, p[4] = 0.2, p[5] = 0.3;
    p[6] = p[0] - 0.1, p[7] = 0.2, p[8] = 0.3;
    p[9] = p[0], p[10] = 0.42, p[11] = 0.3;
  }
  Result<MotionSet> set = decode(leaf(numbers({3, 24, 3}, data)));
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.message(),
            "x.npy: a bare array (3,24,3) of joint positions (constant bone lengths), not "
            "rotations: fit a body first, e.g. with SMPLify");
  // One frame proves nothing: read as poses.
  data.resize(72);
  EXPECT_TRUE(decode(leaf(numbers({1, 24, 3}, data))).ok());
}

}  // namespace
}  // namespace smpl
