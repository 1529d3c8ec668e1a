// The sidecar reader of the C++ runtimes
// (unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesMetadata.h):
// the exporter's own metadata (exporter/metadata_json.h) parses into the layout
// it describes; JSON errors and malformed fields are one line; unknown keys are skipped.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/demo/demo_body.h"
#include "unreal/SmplCorrectives/Source/SmplCorrectives/Public/SmplCorrectivesMetadata.h"

namespace {

namespace sc = smpl_correctives;

std::string parseError(const std::string& text) {
  sc::Layout layout;
  return sc::parseLayout(text, &layout);
}

nlohmann::json demoMetadata() {
  const smpl::BodyModel& body = smpl::demoBody();
  nlohmann::json m;
  m["model_kind"] = "smpl";
  m["joint_names"] = body.joint_names;
  m["parents"] = body.parents;
  m["up_axis"] = "+Y";
  m["corrective_encoding"] = "split";
  m["correctives"] = nlohmann::json::array();
  m["correctives"].push_back(
      {{"feature", 0}, {"target", "pose_a_00"}, {"scale", -0.5}, {"offset", 0}});
  m["correctives"].push_back({{"feature", 1},
                              {"target", "pose_a_01_neg"},
                              {"scale", -1},
                              {"offset", 0},
                              {"rectified", true}});
  m["morph_targets"] = {"pose_a_00", "pose_a_01_neg"};
  m["producer"] = {{"hash", "0123456789abcdef"}};
  return m;
}

TEST(RuntimeMetadata, ReadsTheFieldsTheCorrectivesNeed) {
  sc::Layout layout;
  ASSERT_EQ(sc::parseLayout(demoMetadata().dump(2), &layout), "");
  EXPECT_EQ(layout.joint_names, smpl::demoBody().joint_names);
  EXPECT_EQ(layout.parents, smpl::demoBody().parents);
  ASSERT_EQ(layout.correctives.size(), 2u);
  EXPECT_EQ(layout.correctives[0].target, "pose_a_00");
  EXPECT_EQ(layout.correctives[0].scale, -0.5);
  EXPECT_FALSE(layout.correctives[0].rectified);
  EXPECT_EQ(layout.correctives[1].feature, 1);
  EXPECT_EQ(layout.correctives[1].scale, -1.0);
  EXPECT_TRUE(layout.correctives[1].rectified);
  EXPECT_TRUE(layout.basis.targets.empty());
}

TEST(RuntimeMetadata, ReadsBoneNames) {
  nlohmann::json m = demoMetadata();
  const size_t k = m["joint_names"].size();
  std::vector<std::string> bones;
  for (size_t j = 0; j < k; ++j) bones.push_back("b" + std::to_string(j));
  m["skeleton_names"] = "ue5";
  m["bone_names"] = bones;
  sc::Layout layout;
  ASSERT_EQ(sc::parseLayout(m.dump(), &layout), "");
  EXPECT_EQ(layout.bone_names, bones);
  bones.pop_back();
  m["bone_names"] = bones;
  EXPECT_EQ(sc::parseLayout(m.dump(), &layout),
            "metadata: 'bone_names' must be as long as 'joint_names'");
  m["bone_names"] = {1, 2};
  EXPECT_EQ(sc::parseLayout(m.dump(), &layout), "metadata: 'bone_names' must hold strings");
  sc::Layout plain;
  ASSERT_EQ(sc::parseLayout(demoMetadata().dump(), &plain), "");
  EXPECT_TRUE(plain.bone_names.empty());
}

TEST(RuntimeMetadata, DefaultsAndBasis) {
  nlohmann::json m = demoMetadata();
  m["correctives"] = {{{"feature", 3}, {"target", "t"}},
                      {{"feature", 4}, {"target", "u"}, {"rectified", "yes"}}};
  int p = 9 * (int(smpl::demoBody().parents.size()) - 1);
  m["corrective_basis"] = {{"targets", {"pose_basis_0"}},
                           {"features", p},
                           {"matrix", std::vector<double>(size_t(p), 0.25)},
                           {"scale", {2.0}},
                           {"offset", {-1e-3}}};
  m.erase("up_axis");
  sc::Layout layout;
  ASSERT_EQ(sc::parseLayout(m.dump(), &layout), "");
  EXPECT_EQ(layout.correctives[0].scale, 1.0);
  EXPECT_EQ(layout.correctives[0].offset, 0.0);
  EXPECT_FALSE(layout.correctives[1].rectified);  // only `true` means rectified
  EXPECT_EQ(layout.up_axis, "+Y");
  ASSERT_EQ(layout.basis.targets, std::vector<std::string>{"pose_basis_0"});
  EXPECT_EQ(layout.basis.matrix.size(), size_t(p));
  EXPECT_EQ(layout.basis.offset[0], -1e-3);
}

TEST(RuntimeMetadata, MalformedFieldsAreOneLine) {
  nlohmann::json m = demoMetadata();
  m["correctives"][1]["feature"] = 1.5;
  EXPECT_EQ(parseError(m.dump()), "metadata: 'correctives'[1].feature must be an integer");
  m = demoMetadata();
  m["correctives"][0]["scale"] = "1";
  EXPECT_EQ(parseError(m.dump()), "metadata: 'correctives'[0].scale must be a number");
  m = demoMetadata();
  m["correctives"][0]["feature"] = 10000;
  EXPECT_NE(parseError(m.dump()).find("expected 0 <= feature <"), std::string::npos);
  m = demoMetadata();
  m["parents"][3] = 7;
  EXPECT_EQ(parseError(m.dump()), "metadata: 'parents'[3] = 7; expected 0 <= parent < 3");
  m = demoMetadata();
  m.erase("joint_names");
  EXPECT_EQ(parseError(m.dump()), "metadata: 'joint_names' and 'parents' must be arrays");
  m = demoMetadata();
  m["corrective_basis"] = {{"targets", {"b"}}, {"matrix", {1, 2}}, {"scale", {1}}, {"offset", {0}}};
  EXPECT_NE(parseError(m.dump()).find("'corrective_basis' has 2 matrix values"), std::string::npos);
  EXPECT_EQ(parseError("[1, 2]"), "metadata: expected a JSON object");
}

TEST(RuntimeMetadata, InvalidJsonNamesTheByte) {
  EXPECT_EQ(parseError("{\"a\": 1,}"), "metadata: invalid JSON: expected a member name at byte 8");
  EXPECT_EQ(parseError("{\"a\": tru}"), "metadata: invalid JSON: invalid literal at byte 6");
  EXPECT_EQ(parseError("{\"a\": 01}"), "metadata: invalid JSON: expected ',' or '}' at byte 7");
  EXPECT_EQ(parseError("{\"a\": 1e999}"), "metadata: invalid JSON: number out of range at byte 11");
  EXPECT_EQ(parseError("{\"a\": \"\\ud800\"}"),
            "metadata: invalid JSON: unpaired surrogate at byte 13");
  EXPECT_EQ(parseError("{\"a\": \"x"), "metadata: invalid JSON: unterminated string at byte 8");
  EXPECT_EQ(parseError("{} x"),
            "metadata: invalid JSON: unexpected text after the JSON value at byte 3");
  EXPECT_EQ(parseError(""), "metadata: invalid JSON: unexpected end of text at byte 0");
  EXPECT_EQ(parseError(std::string(66, '[') + std::string(66, ']')),
            "metadata: invalid JSON: nesting deeper than 64 levels at byte 65");
  EXPECT_EQ(parseError(std::string(65, '[') + std::string(65, ']')),
            "metadata: expected a JSON object");
}

TEST(RuntimeMetadata, StringsDecodeEscapes) {
  sc::json::Value v;
  sc::json::Parser parser("[\"a\\\"b\\\\c\\/\\n\\u00e9\\ud83d\\ude00\"]");
  ASSERT_TRUE(parser.parse(&v)) << parser.error();
  EXPECT_EQ(v.items[0].text, "a\"b\\c/\n\xc3\xa9\xf0\x9f\x98\x80");
}

}  // namespace
