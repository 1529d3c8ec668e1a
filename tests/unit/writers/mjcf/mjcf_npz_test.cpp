// The MJCF writer's .npz (writers/mjcf/mjcf_npz.h), read back by the
// project's own reader (core/io/npz.h); numpy reads the written files in the
// mjcf.motion tests (tests/roundtrip/mjcf_reference.py).
#include "writers/mjcf/mjcf_npz.h"

#include <gtest/gtest.h>

#include "core/io/npz.h"

namespace smpl {
namespace {

Result<std::string> sample() {
  Result<NpyMember> names = npyStrings("joint_names", {"pelvis", "left_hip_x", "h\xc3\xa9"});
  if (!names) return names.error();
  return npzBytes(
      {npyDoubles("qpos", {2, 3}, {1, 2, 3, 4, 5, -6.5}), npyDoubles("fps", {}, {60.0}), *names});
}

TEST(MjcfNpz, ReadsBackWithTheNpzReader) {
  Result<std::string> bytes = sample();
  ASSERT_TRUE(bytes.ok()) << bytes.message();
  Result<NpzArchive> npz = NpzArchive::fromBytes(reinterpret_cast<const uint8_t*>(bytes->data()),
                                                 bytes->size(), "t.qpos.npz");
  ASSERT_TRUE(npz.ok()) << npz.message();
  EXPECT_EQ(npz->keys(), (std::vector<std::string>{"qpos", "fps", "joint_names"}));
  Result<Array> qpos = npz->get("qpos");
  ASSERT_TRUE(qpos.ok()) << qpos.message();
  EXPECT_EQ(qpos->dtype, "<f8");
  EXPECT_EQ(qpos->shape, (std::vector<int64_t>{2, 3}));
  EXPECT_EQ(qpos->data, (std::vector<double>{1, 2, 3, 4, 5, -6.5}));
  Result<Array> fps = npz->get("fps");
  ASSERT_TRUE(fps.ok()) << fps.message();
  EXPECT_TRUE(fps->shape.empty());
  EXPECT_EQ(fps->data, std::vector<double>{60.0});
  Result<Array> names = npz->get("joint_names");
  ASSERT_TRUE(names.ok()) << names.message();
  EXPECT_EQ(names->dtype, "<U10");
  EXPECT_EQ(names->strings, (std::vector<std::string>{"pelvis", "left_hip_x", "h\xc3\xa9"}));
}

TEST(MjcfNpz, SameBytesAndChecked) {
  Result<std::string> a = sample(), b = sample();
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(*a, *b);
  std::string broken = *a;
  broken[110] ^= 1;  // inside qpos.npy's data: the member's CRC no longer matches
  Result<NpzArchive> npz = NpzArchive::fromBytes(reinterpret_cast<const uint8_t*>(broken.data()),
                                                 broken.size(), "t.qpos.npz");
  ASSERT_TRUE(npz.ok()) << npz.message();
  EXPECT_FALSE(npz->get("qpos").ok());
  EXPECT_FALSE(npyStrings("joint_names", {"bad\xff"}).ok());
}

}  // namespace
}  // namespace smpl
