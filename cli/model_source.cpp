#include "cli/model_source.h"

#include <filesystem>

#include "core/demo/demo_body.h"
#include "core/io/file_io.h"
#include "core/joint_names.h"
#include "core/load/model_folder.h"
#include "core/load/model_loader.h"
#include "core/load/motion.h"
#include "core/load/npz_arrays.h"

namespace smpl {
namespace {

struct MotionHint {
  std::optional<ModelKind> kind;
  std::string gender;
};

// Kind and gender of a motion: the loader's layout and gender; an AMASS
// `surface_model_type` ("smplx", "smplh", "smpl", "mano") overrides the layout.
Result<MotionHint> motionHint(const std::string& path) {
  Result<Motion> m = loadMotion(path);
  if (!m) return m.error();
  MotionHint hint{m->layout, m->gender};
  if (hasSuffix(path, ".npz")) {
    Result<ArrayDict> d = readNpzArrays(path, {"surface_model_type"});
    if (d && d->count("surface_model_type") && !d->at("surface_model_type").strings.empty()) {
      const std::string t = d->at("surface_model_type").strings[0];
      for (ModelKind k : {ModelKind::Smpl, ModelKind::SmplH, ModelKind::SmplX, ModelKind::Mano})
        if (t == modelKindName(k)) hint.kind = k;
    }
  }
  return hint;
}

// Bytes the model's arrays occupy, held against the budget while the model is cached.
uint64_t modelBytes(const BodyModel& m) {
  const uint64_t doubles = m.v_template.size() + m.shapedirs.size() + m.exprdirs.size() +
                           m.posedirs.size() + m.weights.size() + m.hands_components_l.size() +
                           m.hands_components_r.size() + m.texcoords.size();
  return doubles * sizeof(double) + m.j_regressor.nonZeros() * (sizeof(double) + sizeof(int)) +
         (m.faces.size() + m.texcoord_faces.size()) * sizeof(int);
}

}  // namespace

bool ModelSource::isFolder() const {
  std::error_code ec;
  return option_ != "builtin" && std::filesystem::is_directory(option_, ec);
}

Result<ModelPick> ModelSource::load(const std::string& path, const std::string& name) {
  std::lock_guard<std::mutex> lock(
      mutex_);  // one load at a time; cached models are shared read-only
  auto it = cache_.find(path);
  if (it == cache_.end()) {
    Result<BodyModel> m = path == "builtin" ? Result<BodyModel>(demoBody()) : loadModel(path);
    if (!m) return m.error();
    if (!name.empty()) m->name = name;  // e.g. "smplh/male/model.npz", not just "model.npz"
    Cached cached;
    if (Status st = cached.memory.add(modelBytes(*m), path, "the model"); !st) return st.error();
    cached.model = std::make_unique<BodyModel>(std::move(*m));
    it = cache_.emplace(path, std::move(cached)).first;
  }
  return ModelPick{it->second.model.get(), path, ""};
}

Result<ModelPick> ModelSource::forMotion(const std::string& motion_path) {
  if (!isFolder()) return load(option_, "");
  MotionHint hint;
  if (!motion_path.empty()) {
    Result<MotionHint> h = motionHint(motion_path);
    if (!h) return h.error();
    hint = *h;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!listed_) listing_ = listModelFolder(option_), listed_ = true;
  }
  Result<ModelFileChoice> choice = chooseModelFile(listing_, hint.kind, hint.gender, option_);
  if (!choice) return choice.error();
  Result<ModelPick> pick =
      load((std::filesystem::path(option_) / choice->path).string(), choice->path);
  if (pick) pick->note = choice->note;
  return pick;
}

}  // namespace smpl
