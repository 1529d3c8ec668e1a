// The fitted skin of one subject, computed once and shared by the exports
// that need the same one (in batch mode the motions of one subject
// reuse the weight fit, the corrective refit and the mesh with its morph
// targets instead of redoing them per motion). The skin (exportSkin) and the
// refit (refitCorrectives) depend only on the model, the subject's betas and
// expression, --max-influences, --skin-weights and whether the correctives
// are refitted; the mesh and its targets also on the UV layout (--uv), the
// correctives' encoding and basis and the shape and expression key counts:
// all of these are the key.
// Bounded: the `capacity` most recently added subjects are kept (a batch in
// folder order meets each subject's motions one after another), each charged
// to the memory budget (core/memory_budget.h); one that does not fit is
// computed and used but not kept. Thread-safe: batch workers that need the
// same subject at once wait for the one computing it.
//
//   SkinCache skins(4);
//   Result<Asset> asset = exportAsset(model, options, motions, nullptr, &skins);
#pragma once

#include <deque>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

#include "core/body_model.h"
#include "core/math/corrective_refit.h"
#include "core/math/skin_weights.h"
#include "core/memory_budget.h"
#include "exporter/pipeline.h"

namespace smpl {

// What buildAsset needs of the fit: the N x M skin, the refit (empty when
// the options do not refit the correctives) and, unless the correctives are
// a basis (whose fit can fail: built per export), the finished mesh with its
// morph targets and the targets' layouts (AssetMetadata::correctives).
struct FittedSkin {
  SparseSkin skin;
  std::shared_ptr<const CorrectiveRefit> refit = std::make_shared<CorrectiveRefit>();  // never null
  bool has_mesh = false;  // `mesh` and `correctives` below were built with the fit
  SkinnedMesh mesh;
  std::vector<CorrectiveLayout> correctives;
  MemoryCharge memory;  // the arrays above, while the cache keeps them
};

class SkinCache {
 public:
  explicit SkinCache(size_t capacity) : capacity_(capacity) {}
  // The fitted skin of `model` (a model that outlives the cache: the
  // ModelSource's) with `options`, from `fit` the first time. Exceptions of
  // `fit` (std::bad_alloc) reach this caller and every caller waiting for it;
  // the key is then not kept.
  std::shared_ptr<const FittedSkin> get(const BodyModel& model, const ExportOptions& options,
                                        const std::function<FittedSkin()>& fit);
  int computed() const;  // fits run through this cache
  int reused() const;    // calls served from it

 private:
  // Model, betas, expression, influences, skin method, refit; UV layout,
  // encoding, correctives, basis size, shape keys, expression keys.
  using Key = std::tuple<const BodyModel*, std::vector<double>, std::vector<double>, int, int, bool,
                         std::string, int, bool, int, int, int>;
  static Key keyOf(const BodyModel& model, const ExportOptions& options);
  void forget(const Key& key);
  size_t capacity_;
  mutable std::mutex mutex_;
  std::map<Key, std::shared_future<std::shared_ptr<const FittedSkin>>> entries_;
  std::deque<Key> order_;  // oldest first
  int computed_ = 0, reused_ = 0;
};

}  // namespace smpl
