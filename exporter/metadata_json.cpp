// The metadata object of docs/file-contract.md, serialised with nlohmann::ordered_json so
// keys keep the documented order and doubles print as the shortest text that
// reads back to the same value.
//
// With --corrective-basis K (corrective_basis.h) "correctives" is empty and
//   "corrective_basis": {"targets": ["pose_basis_0", ...],   K morph target names
//                        "features": P,                      pose features per row
//                        "matrix": [...],                    C, K x P, row-major
//                        "scale": [...], "offset": [...]}    K each
// drives target k with weight_k = scale_k * sum_n matrix[k P + n] f[n] + offset_k
// (f of docs/file-contract.md). The key is absent without a basis.
//
// The sidecar <out>.smpl.json adds, last,
//   "producer": {"hash": "<16 hex digits>",
//                "outputs": [{"file": "walk.glb", "bytes": N, "sha256": "<64 hex digits>"}]}
// a hash of everything that produced the output pair (request/producer.h: exporter
// version, options, model and input identities) and the size and SHA-256 of
// every file of the output (a .gltf's .bin included); batch mode rebuilds an
// output whose sidecar hash differs or whose files are not the recorded ones.
// It is not in the glTF, so the output's bytes do not depend on it.
#include "exporter/metadata_json.h"

#include <nlohmann/json.hpp>

#include "core/io/sha256.h"
#include "core/utf8.h"

namespace smpl {
namespace {

using Json = nlohmann::ordered_json;

Json correctivesJson(const std::vector<CorrectiveLayout>& correctives) {
  Json list = Json::array();
  for (const CorrectiveLayout& c : correctives) {
    Json entry = Json::object();
    entry["feature"] = c.feature;
    entry["target"] = c.target;
    entry["scale"] = c.scale;
    entry["offset"] = c.offset;
    if (c.rectified) entry["rectified"] = true;  // weight = max(0, scale * f + offset)
    list.push_back(std::move(entry));
  }
  return list;
}

Json basisJson(const CorrectiveBasis& basis) {
  Json o = Json::object();
  o["targets"] = basis.targets;
  o["features"] = basis.projection.cols();
  Json matrix = Json::array();
  for (Eigen::Index k = 0; k < basis.projection.rows(); ++k)
    for (Eigen::Index n = 0; n < basis.projection.cols(); ++n)
      matrix.push_back(basis.projection(k, n));
  o["matrix"] = std::move(matrix);
  o["scale"] = basis.scale;
  o["offset"] = basis.offset;
  return o;
}

// "dmpl": {"basis": file name, "joints": "fixed"|"regressed",
//          "targets": [{"direction": i, "target": "dmpl_<i>", "scale": s, "offset": o}, ...]}
// weight = scale * dmpls[frame][direction] + offset (exporter/dmpl_targets.h).
Json dmplJson(const DmplInfo& dmpl) {
  Json o = Json::object();
  o["basis"] = dmpl.basis;
  o["joints"] = dmpl.animate_joints ? "regressed" : "fixed";
  Json list = Json::array();
  for (const DmplLayout& d : dmpl.targets) {
    Json entry = Json::object();
    entry["direction"] = d.direction;
    entry["target"] = d.target;
    entry["scale"] = d.scale;
    entry["offset"] = d.offset;
    list.push_back(std::move(entry));
  }
  o["targets"] = std::move(list);
  return o;
}

Json expressionTargetsJson(const ExpressionInfo& info) {
  Json list = Json::array();
  for (const ExpressionLayout& e : info.targets) {
    Json entry = Json::object();
    entry["index"] = e.index;
    entry["target"] = e.target;
    entry["scale"] = e.scale;
    entry["offset"] = e.offset;
    list.push_back(std::move(entry));
  }
  return list;
}

// Each clip's name and where it came from (asset.h ClipSource).
Json animationsJson(const std::vector<AnimationClip>& clips) {
  Json list = Json::array();
  for (const AnimationClip& c : clips) {
    Json source = Json::object();
    source["layout"] = c.source.layout;
    if (!c.source.track.empty()) source["track"] = c.source.track;
    source["first_frame"] = c.source.first_frame;
    source["end_frame"] = c.source.end_frame;
    source["world"] = c.source.world;
    Json entry = Json::object();
    entry["name"] = c.name;
    entry["fps"] = c.fps;
    entry["frames"] = c.times.size();
    entry["source"] = std::move(source);
    list.push_back(std::move(entry));
  }
  return list;
}

Json morphTargetNamesJson(const std::vector<MorphTarget>& targets) {
  Json names = Json::array();
  for (const MorphTarget& t : targets) names.push_back(t.name);
  return names;
}

// The model's joints (asset.h Placement: without the root bone, which is not
// a model joint). With --skeleton-names mixamo|ue5 (skeleton_names.h) also
// "skeleton_names" and "bone_names": the bone of joint_names[k] in the file.
void modelJointsJson(const Skeleton& s, const AssetMetadata& m, bool root_bone, Json* o) {
  const bool renamed = m.skeleton_names != "smpl";
  const std::vector<std::string>& names = renamed ? m.model_joint_names : s.names;
  const size_t first = root_bone ? 1 : 0;
  std::vector<int> parents;
  for (size_t k = first; k < s.parents.size(); ++k)
    parents.push_back(s.parents[k] < 0 ? -1 : s.parents[k] - int(first));
  (*o)["joint_names"] = std::vector<std::string>(names.begin() + long(first), names.end());
  (*o)["parents"] = parents;
  if (m.rest_pose != "t") (*o)["rest_pose"] = m.rest_pose;  // rest_pose.h
  if (!renamed) return;
  (*o)["skeleton_names"] = m.skeleton_names;
  (*o)["bone_names"] = std::vector<std::string>(s.names.begin() + long(first), s.names.end());
}

// "origin": {"mode": "floor", "offset": [0, dy, 0]}: metres added to every
// position of the model's frame (exporter/placement.h); "root_bone": the
// joint the file adds above the model's root. Both absent by default.
void placementJson(const Asset& asset, Json* o) {
  const Placement& p = asset.placement;
  if (p.origin != "model") {
    Json origin = Json::object();
    origin["mode"] = p.origin;
    origin["offset"] = std::vector<double>{0.0, p.floor_offset, 0.0};
    (*o)["origin"] = std::move(origin);
  }
  if (!p.root_bone) return;
  Json root = Json::object();
  root["name"] = asset.skeleton.names[0];
  root["child"] = asset.skeleton.names.size() > 1 ? asset.skeleton.names[1] : "";
  root["translation"] = "ground_projection";  // (x, 0, z) of the child's world position
  (*o)["root_bone"] = std::move(root);
}

Json metadataObject(const Asset& asset) {
  const AssetMetadata& m = asset.metadata;
  Json o = Json::object();
  o["model_kind"] = m.model_kind;
  o["model_name"] = m.model_name;
  o["exporter_version"] = m.exporter_version;
  modelJointsJson(asset.skeleton, m, asset.placement.root_bone, &o);
  o["betas"] = m.betas;
  o["expression"] = m.expression;
  o["max_influences"] = m.max_influences;
  o["skin_weights"] = m.skin_weights;
  o["units"] = m.units;
  o["up_axis"] = m.up_axis;
  placementJson(asset, &o);
  o["corrective_encoding"] = m.corrective_encoding;
  o["correctives"] = correctivesJson(m.correctives);
  if (!m.corrective_basis.targets.empty()) o["corrective_basis"] = basisJson(m.corrective_basis);
  if (!m.dmpl.targets.empty()) o["dmpl"] = dmplJson(m.dmpl);
  if (!m.expression_targets.targets.empty())
    o["expression_targets"] = expressionTargetsJson(m.expression_targets);
  if (!asset.animations.empty()) o["animations"] = animationsJson(asset.animations);
  o["morph_targets"] = morphTargetNamesJson(asset.mesh.morph_targets);
  return o;
}

// Names come from model files: replace invalid UTF-8 instead of throwing
// (nlohmann's default), so a hostile name cannot abort the export.
std::string dump(const Json& o) { return o.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace

std::string metadataJson(const Asset& asset) { return dump(metadataObject(asset)); }

std::vector<RecordedOutput> recordOutputs(const std::vector<FileContent>& outputs) {
  std::vector<RecordedOutput> records;
  for (const FileContent& f : outputs)
    records.push_back(RecordedOutput{escapeInvalidUtf8(baseName(f.path)), f.totalSize(),
                                     sha256Hex(f.data, f.size, f.tail)});
  return records;
}

namespace {

// The scene's own entry: its timeline, each body's place on it, the camera.
Json sceneObject(const SceneAsset& scene) {
  Json o = Json::object();
  o["name"] = scene.name;
  o["fps"] = scene.fps;
  o["first_frame"] = scene.first_frame;
  o["end_frame"] = scene.end_frame;
  Json bodies = Json::array();
  for (const SceneBody& b : scene.bodies) {
    Json entry = Json::object();
    entry["name"] = b.asset.name;
    entry["track"] = b.track;
    entry["first_frame"] = b.first_frame;
    entry["end_frame"] = b.end_frame;
    entry["start"] = b.start;
    entry["hidden_by"] = b.visibility.empty() ? "none" : "body_scale_step";
    bodies.push_back(std::move(entry));
  }
  o["bodies"] = std::move(bodies);
  if (scene.camera.present()) {
    Json camera = Json::object();
    camera["name"] = "camera";
    camera["frames"] = scene.camera.times.size();
    camera["yfov"] = scene.camera.yfov;
    if (scene.camera.aspect > 0) camera["aspect"] = scene.camera.aspect;
    o["camera"] = std::move(camera);
  }
  return o;
}

Json sceneMetadataObject(const SceneAsset& scene) {
  Json o = Json::object();
  o["scene"] = sceneObject(scene);
  Json bodies = Json::array();
  for (const SceneBody& b : scene.bodies) bodies.push_back(metadataObject(b.asset));
  o["bodies"] = std::move(bodies);
  return o;
}

// `o` with the sidecar's "producer" entry added last.
std::string withProducer(Json o, const std::string& producer_hash,
                         const std::vector<FileContent>& outputs) {
  Json producer = Json::object();
  producer["hash"] = producer_hash;
  if (!outputs.empty()) {
    Json list = Json::array();
    for (const RecordedOutput& r : recordOutputs(outputs)) {
      Json entry = Json::object();
      entry["file"] = r.file;
      entry["bytes"] = r.bytes;
      entry["sha256"] = r.sha256;
      list.push_back(std::move(entry));
    }
    producer["outputs"] = std::move(list);
  }
  o["producer"] = std::move(producer);
  return dump(o);
}

}  // namespace

std::string sidecarJson(const Asset& asset, const std::string& producer_hash,
                        const std::vector<FileContent>& outputs) {
  return withProducer(metadataObject(asset), producer_hash, outputs);
}

std::string sceneMetadataJson(const SceneAsset& scene) { return dump(sceneMetadataObject(scene)); }

std::string sceneSidecarJson(const SceneAsset& scene, const std::string& producer_hash,
                             const std::vector<FileContent>& outputs) {
  return withProducer(sceneMetadataObject(scene), producer_hash, outputs);
}

std::vector<RecordedOutput> recordedOutputsOf(const std::string& sidecar) {
  const Json o = Json::parse(sidecar, nullptr, /*allow_exceptions=*/false);
  if (!o.is_object() || !o.contains("producer") || !o["producer"].is_object()) return {};
  const Json& list = o["producer"].value("outputs", Json());
  if (!list.is_array()) return {};
  std::vector<RecordedOutput> records;
  for (const Json& e : list) {
    if (!e.is_object() || !e.value("file", Json()).is_string() ||
        !e.value("bytes", Json()).is_number_unsigned() || !e.value("sha256", Json()).is_string())
      return {};
    records.push_back(RecordedOutput{e["file"].get<std::string>(), e["bytes"].get<uint64_t>(),
                                     e["sha256"].get<std::string>()});
  }
  return records;
}

std::string producerHashOf(const std::string& sidecar) {
  const Json o = Json::parse(sidecar, nullptr, /*allow_exceptions=*/false);
  if (!o.is_object() || !o.contains("producer") || !o["producer"].is_object()) return "";
  const Json& h = o["producer"].value("hash", Json());
  return h.is_string() ? h.get<std::string>() : "";
}

}  // namespace smpl
