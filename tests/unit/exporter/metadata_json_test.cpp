// metadataJson: key order, values, round-trip doubles, hostile names.
#include "exporter/metadata_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace smpl {
namespace {

Asset metadataAsset() {
  Asset a;
  a.name = "body";
  a.skeleton.names = {"pelvis", "left_hip", "left_knee"};
  a.skeleton.parents = {-1, 0, 1};
  a.mesh.morph_targets.resize(2);
  a.mesh.morph_targets[0].name = "pose_left_hip_00";
  a.mesh.morph_targets[1].name = "shape_0";
  AssetMetadata& m = a.metadata;
  m.model_kind = "smpl";
  m.model_name = "smpl_small.npz";
  m.exporter_version = "0.1.0";
  m.betas = {0.1, -1.0 / 3.0, 2.5e-300};
  m.max_influences = 8;
  m.correctives = {{0, "pose_left_hip_00", 0.5, -0.25}};
  return a;
}

TEST(MetadataJson, KeysInDocumentedOrder) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(metadataJson(metadataAsset()));
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  const std::vector<std::string> want = {
      "model_kind", "model_name",          "exporter_version", "joint_names",  "parents",
      "betas",      "expression",          "max_influences",   "skin_weights", "units",
      "up_axis",    "corrective_encoding", "correctives",      "morph_targets"};
  EXPECT_EQ(keys, want);
  std::vector<std::string> entry_keys;
  for (auto it = j["correctives"][0].begin(); it != j["correctives"][0].end(); ++it)
    entry_keys.push_back(it.key());
  EXPECT_EQ(entry_keys, (std::vector<std::string>{"feature", "target", "scale", "offset"}));
}

TEST(MetadataJson, ValuesRoundTrip) {
  const Asset a = metadataAsset();
  nlohmann::json j = nlohmann::json::parse(metadataJson(a));
  EXPECT_EQ(j["model_kind"], "smpl");
  EXPECT_EQ(j["model_name"], "smpl_small.npz");
  EXPECT_EQ(j["exporter_version"], "0.1.0");
  EXPECT_EQ(j["joint_names"], nlohmann::json({"pelvis", "left_hip", "left_knee"}));
  EXPECT_EQ(j["parents"], nlohmann::json({-1, 0, 1}));
  // Exact equality: the text must read back to the same doubles.
  ASSERT_EQ(j["betas"].size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(j["betas"][i].get<double>(), a.metadata.betas[i]);
  EXPECT_TRUE(j["expression"].is_array());
  EXPECT_TRUE(j["expression"].empty());
  EXPECT_EQ(j["max_influences"], 8);
  EXPECT_EQ(j["units"], "meters");
  EXPECT_EQ(j["up_axis"], "+Y");
  EXPECT_EQ(j["correctives"][0]["feature"], 0);
  EXPECT_EQ(j["correctives"][0]["target"], "pose_left_hip_00");
  EXPECT_EQ(j["correctives"][0]["scale"].get<double>(), 0.5);
  EXPECT_EQ(j["correctives"][0]["offset"].get<double>(), -0.25);
  EXPECT_EQ(j["morph_targets"], nlohmann::json({"pose_left_hip_00", "shape_0"}));
}

TEST(MetadataJson, DeterministicAndEmptyListsStayArrays) {
  Asset a;
  EXPECT_EQ(metadataJson(a), metadataJson(a));
  nlohmann::json j = nlohmann::json::parse(metadataJson(a));
  for (const char* key :
       {"joint_names", "parents", "betas", "expression", "correctives", "morph_targets"})
    EXPECT_TRUE(j[key].is_array() && j[key].empty()) << key;
}

TEST(MetadataJson, InvalidUtf8NameDoesNotThrow) {
  Asset a = metadataAsset();
  a.skeleton.names[1] = std::string("bad\xff\xfe", 5);
  std::string text;
  ASSERT_NO_THROW(text = metadataJson(a));
  nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["joint_names"].size(), 3u);
}

// The sidecar is the metadata plus, last, the producer hash; the hash reads
// back, and anything else reads back as "" (rebuild).
TEST(MetadataJson, SidecarAddsProducerLast) {
  const Asset a = metadataAsset();
  const std::string sidecar = sidecarJson(a, "0123456789abcdef");
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(sidecar);
  EXPECT_EQ(std::prev(j.end()).key(), "producer");
  EXPECT_EQ(j["producer"]["hash"], "0123456789abcdef");
  j.erase("producer");
  EXPECT_EQ(j.dump(), nlohmann::ordered_json::parse(metadataJson(a)).dump());
  EXPECT_EQ(producerHashOf(sidecar), "0123456789abcdef");
  EXPECT_EQ(producerHashOf(metadataJson(a)), "");
  EXPECT_EQ(producerHashOf("{\"producer\": {\"hash\": 7}}"), "");
  EXPECT_EQ(producerHashOf("[1, 2"), "");
  EXPECT_EQ(producerHashOf(""), "");
}

// The sidecar records every file of its output (name, size, SHA-256 of the
// bytes written), and reads the record back; malformed records read as none.
TEST(MetadataJson, SidecarRecordsEveryOutputFile) {
  const std::string glb = "glTF bytes", bin = std::string(1000, '\0');
  const std::vector<FileContent> outputs = {{"/out/walk.gltf", glb.data(), glb.size()},
                                            {"/out/walk\xff.bin", bin.data(), bin.size()}};
  const std::string sidecar = sidecarJson(metadataAsset(), "0123456789abcdef", outputs);
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(sidecar);
  EXPECT_EQ(std::prev(j.end()).key(), "producer");
  ASSERT_EQ(j["producer"]["outputs"].size(), 2u);
  EXPECT_EQ(j["producer"]["outputs"][0]["file"], "walk.gltf");
  EXPECT_EQ(j["producer"]["outputs"][0]["bytes"], glb.size());
  // sha256sum of "glTF bytes" (an independent implementation's digest):
  EXPECT_EQ(j["producer"]["outputs"][0]["sha256"],
            "80dcc14bfc3491e609e212c9518577319eac1125b73b5a00d466a57de9787542");
  EXPECT_EQ(j["producer"]["outputs"][1]["file"], "walk\\xff.bin");  // escaped, not replaced
  const std::vector<RecordedOutput> back = recordedOutputsOf(sidecar);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].file, "walk\\xff.bin");
  EXPECT_EQ(back[1].bytes, 1000u);
  EXPECT_EQ(back[1].sha256, j["producer"]["outputs"][1]["sha256"]);
  // A file written in parts is recorded as the whole: "glTF " + "by" + "tes".
  const std::string head = "glTF ", tail = "bytes";
  const std::vector<RecordedOutput> two = recordedOutputsOf(sidecarJson(
      metadataAsset(), "0",
      {{"/out/walk.glb", head.data(), head.size(), {{tail.data(), 2}, {tail.data() + 2, 3}}}}));
  ASSERT_EQ(two.size(), 1u);
  EXPECT_EQ(two[0].bytes, glb.size());
  EXPECT_EQ(two[0].sha256, "80dcc14bfc3491e609e212c9518577319eac1125b73b5a00d466a57de9787542");
  EXPECT_EQ(producerHashOf(sidecar), "0123456789abcdef");
  EXPECT_TRUE(recordedOutputsOf(sidecarJson(metadataAsset(), "0123456789abcdef")).empty());
  EXPECT_TRUE(recordedOutputsOf(R"({"producer": {"outputs": [{"file": 1}]}})").empty());
  EXPECT_TRUE(recordedOutputsOf(R"({"producer": {"outputs": [{"file": "a", "bytes": -1,
                                    "sha256": "x"}]}})")
                  .empty());
  EXPECT_TRUE(recordedOutputsOf("[").empty());
}

}  // namespace
}  // namespace smpl
