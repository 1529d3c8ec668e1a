// The hull points of the MJCF parts (writers/mjcf/mjcf_parts.h): kept for a
// part whose dominated vertices span a solid, dropped for a flat one (MuJoCo
// cannot take the convex hull of coplanar points). MuJoCo's own reading of
// the hulls is checked by the mjcf.mesh tests (tests/roundtrip/mjcf_check.cpp).
#include "writers/mjcf/mjcf_parts.h"

#include <gtest/gtest.h>

#include "../../test_asset.h"

namespace smpl {
namespace {

// A closed box of the given height, every vertex skinned to joint 0 of two.
Asset box(float height) {
  Asset a;
  a.skeleton = test::skeletonFromWorld({"pelvis", "spine"}, {-1, 0},
                                       (Eigen::MatrixXd(2, 3) << 0, 0, 0, 0, 1, 0).finished());
  SkinnedMesh& m = a.mesh;
  m.positions.resize(8, 3);
  for (int v = 0; v < 8; ++v)
    m.positions.row(v) << float(v & 1), (v & 2) ? height : 0.f, float((v >> 2) & 1);
  m.triangles.resize(12, 3);
  // outward: -x, +x, -y, +y, -z, +z faces, two triangles each
  m.triangles << 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0,
      3, 1, 4, 5, 7, 4, 7, 6;
  m.joints = Eigen::MatrixXi::Zero(8, 1);
  m.weights = Eigen::MatrixXf::Ones(8, 1);
  return a;
}

TEST(MjcfParts, ASolidPartKeepsItsHullPointsAFlatOneDoesNot) {
  Result<MjcfParts> solid = mjcfParts(box(1.0f));
  ASSERT_TRUE(solid.ok()) << solid.message();
  EXPECT_NEAR(solid->mesh_volume, 1.0, 1e-12);
  EXPECT_EQ(solid->parts[0].geom.hull.size(), 8u);
  EXPECT_TRUE(solid->parts[1].geom.hull.empty());    // dominates no vertex
  Result<MjcfParts> flat = mjcfParts(box(0.0005f));  // half-height 0.25 mm < 1 mm
  ASSERT_TRUE(flat.ok()) << flat.message();
  EXPECT_TRUE(flat->parts[0].geom.hull.empty());
  EXPECT_NE(flat->parts[0].geom.kind, MjcfGeom::Kind::None);  // the capsule (or sphere) stays
}

}  // namespace
}  // namespace smpl
