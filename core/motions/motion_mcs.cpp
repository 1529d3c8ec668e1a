#include "core/motions/motion_mcs.h"

#include <algorithm>
#include <utility>

#include "core/io/npz.h"
#include "core/io/printable.h"
#include "core/io/tree/npz_tree.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_mcs_gltf.h"
#include "core/motions/motion_smplcodec.h"

namespace smpl {
namespace {

// scenes[scene].extensions.MC_scene_description, or nullptr.
const DataNode* sceneDescription(const DataNode& root) {
  if (!root.isDict()) return nullptr;
  const Array* which = root.leaf("scene");
  const int64_t i =
      which && which->data.size() == 1 && which->data[0] >= 0 ? int64_t(which->data[0]) : 0;
  const DataNode* scene = mcs::element(root.get("scenes"), i);
  const DataNode* ext = scene && scene->isDict() ? scene->get("extensions") : nullptr;
  const DataNode* desc = ext && ext->isDict() ? ext->get("MC_scene_description") : nullptr;
  return desc && desc->isDict() ? desc : nullptr;
}

bool matchesMcs(const DataNode& root) { return sceneDescription(root) != nullptr; }

// Body k: its .smpl decoded, placed at frame_presence[0].
Status decodeBody(const DataNode& root, const DataNode& body, int64_t k, const std::string& path,
                  Motion* m) {
  const std::string ctx = path + ": smpl_bodies[" + std::to_string(k) + "]";
  if (!body.isDict()) return makeError(ctx + " is not an object");
  Result<int64_t> view = mcs::integer(body, "bufferView", -1, ctx);
  if (!view) return view.error();
  const Array* presence = body.leaf("frame_presence");
  if (!presence || presence->isString() || presence->shape != std::vector<int64_t>{2} ||
      !(presence->data[0] >= 0) || !(presence->data[1] > presence->data[0]) ||
      presence->data[1] > 1e9)
    return makeError(ctx + ": 'frame_presence' is not [first, end) frame numbers");
  Result<std::vector<uint8_t>> bytes = mcs::bufferViewBytes(root, *view, path);
  if (!bytes) return bytes.error();
  const std::string smpl = ctx + " (.smpl)";
  Result<NpzArchive> npz = NpzArchive::fromBytes(bytes->data(), bytes->size(), smpl);
  if (!npz) return npz.error();
  if (!npz->has("bodyPose"))
    return makeError(smpl + ": no 'bodyPose' (a body shape, not a motion)");
  Result<DataNode> tree = readNpzTree(*npz, smplCodecLayout().keys);
  if (!tree) return tree.error();
  if (Status s = motion_detail::decodeSmplCodec(*tree, smpl, m); !s) return s;
  std::string ignored;  // e.g. vertexOffsets (detail outside the shape space)
  for (const std::string& key : npz->keys()) {
    const std::vector<std::string>& read = smplCodecLayout().keys;
    if (key != "codecVersion" && std::find(read.begin(), read.end(), key) == read.end())
      ignored += (ignored.empty() ? "" : ", ") + printable(key, 64);
  }
  if (!ignored.empty()) m->notes.push_back("body " + std::to_string(k) + ": ignored: " + ignored);
  const int64_t first = int64_t(presence->data[0]), end = int64_t(presence->data[1]);
  if (end - first != int64_t(m->frames.size()))
    return makeError(ctx + ": 'frame_presence' [" + std::to_string(first) + ", " +
                     std::to_string(end) + ") spans " + std::to_string(end - first) +
                     " frames; its body has " + std::to_string(m->frames.size()));
  m->track = std::to_string(k);
  m->first_frame = first;
  m->world = MotionWorld::Y;
  return Status();
}

Status decodeMcs(const DataNode& root, const LayoutInput& in, MotionSet* out) {
  const DataNode& desc = *sceneDescription(root);
  const DataNode* bodies = desc.get("smpl_bodies");
  if (!bodies || !bodies->isList() || bodies->children.empty())
    return makeError(in.path + ": 'MC_scene_description' has no smpl_bodies");
  Result<int64_t> num_frames =
      mcs::integer(desc, "num_frames", 0, in.path + ": MC_scene_description");
  if (!num_frames) return num_frames.error();
  out->notes.push_back("read as a Meshcapade scene (.mcs: " +
                       std::to_string(bodies->children.size()) + " SMPLCodec bodies, tracks 0.." +
                       std::to_string(bodies->children.size() - 1) + " on the scene's timeline)");
  double fps = 0;
  for (size_t k = 0; k < bodies->children.size(); ++k) {
    Motion m;
    if (Status s = decodeBody(root, bodies->children[k], int64_t(k), in.path, &m); !s) return s;
    if (fps <= 0) fps = m.fps;
    out->tracks.push_back(std::move(m));
  }
  if (in.options.source_fps) fps = *in.options.source_fps;
  if (fps <= 0) fps = 30.0;  // settleFps says so for the tracks
  Result<SceneCamera> camera = mcs::readCamera(root, fps, *num_frames, in.path, &out->notes);
  if (!camera) return camera.error();
  out->camera = std::move(*camera);
  return Status();
}

}  // namespace

const MotionLayout& mcsLayout() {
  static const MotionLayout row{
      "mcs",
      "Meshcapade scene (.mcs: glTF with MC_scene_description)",
      kJsonFile,
      matchesMcs,
      {"scenes", "buffers", "bufferViews", "accessors", "nodes", "cameras", "animations"},
      decodeMcs};
  return row;
}

}  // namespace smpl
