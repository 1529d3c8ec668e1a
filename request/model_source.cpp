#include "request/model_source.h"

#include <filesystem>

#include "core/demo/demo_body.h"
#include "core/models/model_folder.h"
#include "core/models/model_loader.h"
#include "core/os/path.h"
#include "request/input_role.h"

namespace smpl {

uint64_t modelBytes(const BodyModel& m) {
  const uint64_t doubles = m.v_template.size() + m.shapedirs.size() + m.exprdirs.size() +
                           m.posedirs.size() + m.weights.size() + m.hands_components_l.size() +
                           m.hands_components_r.size() + m.texcoords.size();
  return doubles * sizeof(double) + m.j_regressor.nonZeros() * (sizeof(double) + sizeof(int)) +
         (m.faces.size() + m.texcoord_faces.size()) * sizeof(int);
}

bool ModelSource::isFolder() const {
  std::error_code ec;
  return option_ != "builtin" && std::filesystem::is_directory(os::fsPath(option_), ec);
}

Result<ModelPick> ModelSource::load(const std::string& path, const std::string& name) {
  std::lock_guard<std::mutex> lock(
      mutex_);  // one load at a time; cached models are shared read-only
  auto it = cache_.find(path);
  if (it == cache_.end()) {
    Result<BodyModel> m = path == "builtin" ? Result<BodyModel>(demoBody()) : loadModel(path);
    if (!m) return modelRoleError(path, m.error());
    if (!name.empty()) m->name = name;  // e.g. "smplh/male/model.npz", not just "model.npz"
    Cached cached;
    if (Status st = cached.memory.add(modelBytes(*m), path, "the model"); !st) return st.error();
    cached.model = std::make_unique<BodyModel>(std::move(*m));
    it = cache_.emplace(path, std::move(cached)).first;
  }
  return ModelPick{it->second.model.get(), path, ""};
}

Status ModelSource::add(const std::string& path, BodyModel model) {
  std::lock_guard<std::mutex> lock(mutex_);
  Cached cached;
  if (Status st = cached.memory.add(modelBytes(model), path, "the model"); !st) return st;
  cached.model = std::make_unique<BodyModel>(std::move(model));
  cache_[path] = std::move(cached);
  return Status();
}

Result<ModelPick> ModelSource::forMotion(const Motion* motion) {
  if (!isFolder()) return load(option_, "");
  std::optional<ModelKind> kind;
  std::string gender;
  if (motion) kind = motion->model_kind.value_or(motion->layout), gender = motion->gender;
  if (motion && kind == ModelKind::Mano) gender = motion->hand;  // "left": MANO_LEFT
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!listed_) listing_ = listModelFolder(option_), listed_ = true;
  }
  Result<ModelFileChoice> choice = chooseModelFile(listing_, kind, gender, option_);
  if (!choice) return choice.error();
  Result<ModelPick> pick =
      load(os::utf8(os::fsPath(option_) / os::fsPath(choice->path)), choice->path);
  if (pick) pick->note = choice->note;
  return pick;
}

}  // namespace smpl
