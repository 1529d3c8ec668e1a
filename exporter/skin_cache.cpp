#include "exporter/skin_cache.h"

#include "exporter/export_skin.h"

namespace smpl {
namespace {

// Bytes of a mesh's arrays (the cache's memory charge).
uint64_t meshBytes(const SkinnedMesh& m) {
  uint64_t floats =
      uint64_t(m.positions.size() + m.normals.size() + m.weights.size() + m.uvs.size());
  for (const MorphTarget& t : m.morph_targets) floats += uint64_t(t.deltas.size());
  return floats * sizeof(float) +
         (uint64_t(m.joints.size()) + uint64_t(m.triangles.size()) + m.source_vertex.size()) *
             sizeof(int);
}

}  // namespace

SkinCache::Key SkinCache::keyOf(const BodyModel& model, const ExportOptions& o) {
  std::vector<double> betas = o.betas, expression = o.expression;  // as shapeBody pads them
  betas.resize(size_t(model.numBetas()), 0.0);
  expression.resize(size_t(model.numExpressions()), 0.0);
  return Key{&model,
             std::move(betas),
             std::move(expression),
             influencesFor(model, o),
             int(o.skin_weights),
             refitsCorrectives(o),
             o.uv_obj,
             int(o.encoding),
             o.correctives,
             o.corrective_basis,
             o.shape_keys,
             o.expression_keys};
}

std::shared_ptr<const FittedSkin> SkinCache::get(const BodyModel& model, const ExportOptions& o,
                                                 const std::function<FittedSkin()>& fit) {
  const Key key = keyOf(model, o);
  std::promise<std::shared_ptr<const FittedSkin>> promise;
  std::unique_lock<std::mutex> lock(mutex_);
  auto it = entries_.find(key);
  if (it != entries_.end()) {
    ++reused_;
    const std::shared_future<std::shared_ptr<const FittedSkin>> ready = it->second;
    lock.unlock();  // wait for the caller computing it outside the lock
    return ready.get();
  }
  ++computed_;
  entries_.emplace(key, promise.get_future().share());
  order_.push_back(key);
  while (order_.size() > capacity_) {  // callers holding an evicted one keep it alive
    entries_.erase(order_.front());
    order_.pop_front();
  }
  lock.unlock();
  std::shared_ptr<FittedSkin> fitted;
  try {
    fitted = std::make_shared<FittedSkin>(fit());
  } catch (...) {
    promise.set_exception(std::current_exception());
    forget(key);
    throw;
  }
  const uint64_t bytes =
      uint64_t(fitted->skin.joints.size()) * sizeof(int) +
      uint64_t(fitted->skin.weights.size() + fitted->refit->rows.size()) * sizeof(double) +
      fitted->refit->block.size() * sizeof(int) + meshBytes(fitted->mesh);
  if (!fitted->memory.add(bytes, model.name, "the fitted skin kept for the next motion"))
    forget(key);  // over budget: used by this export only
  promise.set_value(fitted);
  return fitted;
}

void SkinCache::forget(const Key& key) {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.erase(key);
  for (auto it = order_.begin(); it != order_.end(); ++it)
    if (*it == key) {
      order_.erase(it);
      break;
    }
}

int SkinCache::computed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return computed_;
}

int SkinCache::reused() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return reused_;
}

}  // namespace smpl
