// Where each export's body model comes from: `--model FILE`, `--model builtin`
// or `--model DIR` (core/models/model_folder.h picks the file per motion from
// the motion as the export decoded it: its model kind from its joint layout,
// its gender from `gender`; the motion file is not read again). Loaded models
// are cached by path and shared by the batch workers (thread-safe), so a
// mixed-gender AMASS folder loads each model once; each cached model's arrays
// are charged to the memory budget.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/body_model.h"
#include "core/memory_budget.h"
#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

struct ModelPick {
  const BodyModel* model = nullptr;  // owned by the ModelSource
  std::string path;                  // the model file used (for summaries)
  std::string note;  // e.g. "no female SMPL-X model in DIR; using SMPLX_NEUTRAL.npz"
};

// Bytes the model's arrays occupy: what a cached (or job-owned) model holds
// against the memory budget.
uint64_t modelBytes(const BodyModel& model);

class ModelSource {
 public:
  explicit ModelSource(std::string option) : option_(std::move(option)) {}
  bool isFolder() const;
  // The model for a decoded motion (null = no motion: a folder gives its most
  // complete neutral model). Errors name the model file that failed.
  Result<ModelPick> forMotion(const Motion* motion);
  // Serves `model` for `path` from now on (a model built in code, for tests
  // and tools: nothing is read). Errors: its arrays exceed the memory budget.
  Status add(const std::string& path, BodyModel model);

 private:
  Result<ModelPick> load(const std::string& path, const std::string& name);
  std::string option_;
  std::mutex mutex_;
  struct Cached {
    std::unique_ptr<BodyModel> model;
    MemoryCharge memory;  // the model's arrays, held against the budget while cached
  };
  std::map<std::string, Cached> cache_;
  std::vector<std::string> listing_;
  bool listed_ = false;
};

}  // namespace smpl
