// Object arrays inside .npz files, as np.savez writes them (allow_pickle):
// decoded by the data-only unpickler only when a loader asks for them.
#include "core/models/npz_arrays.h"

#include <gtest/gtest.h>

#include "core/io/npz.h"

namespace smpl {
namespace {

const std::string kReleased = std::string(SMPL_FIXTURE_DIR) + "/released/";

TEST(NpzArrays, DecodesObjectDictsWhenAsked) {
  Result<ArrayDict> d =
      readNpzArrays(kReleased + "smplx_release.npz", {"joint2num", "part2num", "vt", "absent"});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->count("absent"), 0u);
  const Array& j = d->at("joint2num");
  EXPECT_TRUE(j.isObject());
  EXPECT_FALSE(j.isString());
  EXPECT_EQ(j.keys, (std::vector<std::string>{"pelvis", "left_hip", "right_hip"}));
  EXPECT_EQ(j.data, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(d->at("part2num").keys, (std::vector<std::string>{"global", "head", "leftHand"}));
  EXPECT_EQ(d->at("vt").shape[1], 2);
}

TEST(NpzArrays, AmassStageIIMarkerDict) {
  Result<ArrayDict> d =
      readNpzArrays(kReleased + "amass_stageii.npz", {"markers_latent_vids", "latent_labels"});
  ASSERT_TRUE(d.ok()) << d.message();
  const Array& v = d->at("markers_latent_vids");
  EXPECT_EQ(v.keys, (std::vector<std::string>{"C7", "CLAV", "LFHD", "RFHD", "STRN"}));
  EXPECT_EQ(v.data, (std::vector<double>{10, 20, 30, 40, 50}));
  EXPECT_EQ(d->at("latent_labels").strings.size(), 5u);
}

TEST(NpzArrays, UnneededObjectAndOddMembersAreNeverRead) {
  // odd_complex (complex128) would be refused if anything decoded it.
  Result<NpzArchive> npz = NpzArchive::open(kReleased + "smplx_release.npz");
  ASSERT_TRUE(npz.ok()) << npz.message();
  EXPECT_FALSE(npz->get("odd_complex").ok());
  EXPECT_FALSE(npz->get("joint2num").ok());  // object: the io layer alone refuses it by name
  Result<ArrayDict> d = readNpzArrays(kReleased + "smplx_release.npz", {"v_template", "f"});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->size(), 2u);
}

TEST(NpzArrays, ObjectElementsAndErrors) {
  const std::string path = kReleased + "object_cases.npz";
  Result<ArrayDict> d = readNpzArrays(path, {"names", "numbers", "text"});
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(d->at("names").strings, (std::vector<std::string>{"a", "bc"}));
  EXPECT_EQ(d->at("names").shape, std::vector<int64_t>{2});
  EXPECT_EQ(d->at("numbers").data, (std::vector<double>{1, 2.5, 3}));
  EXPECT_EQ(d->at("text").strings, std::vector<std::string>{"smplx"});
  Result<ArrayDict> nested = readNpzArrays(path, {"nested"});
  ASSERT_FALSE(nested.ok());
  EXPECT_EQ(nested.message(),
            "object_cases.npz: 'nested': object array holds a dict of str -> list; expected str -> "
            "number");
  Result<ArrayDict> mixed = readNpzArrays(path, {"mixed"});
  ASSERT_FALSE(mixed.ok());
  EXPECT_EQ(mixed.message(),
            "object_cases.npz: 'mixed': object array element is a str; expected all numbers or all "
            "strings");
}

}  // namespace
}  // namespace smpl
