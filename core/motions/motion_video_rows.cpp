#include "core/motions/motion_video_rows.h"

#include <cmath>
#include <cstdio>

#include "core/models/betas_rows.h"
#include "core/models/validate_inputs.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace video_rows {
namespace {

std::string shapeError(const std::string& context, const char* key, const Array& a,
                       const std::string& expected) {
  return context + ": '" + key + "' has shape " + shapeString(a.shape) + "; expected " + expected;
}

}  // namespace

Status rowsOf(const DataNode* node, const std::string& context, const char* key, Rows* out) {
  if (!node) return makeError(context + ": missing key '" + std::string(key) + "'");
  if (node->isArray()) {
    if (Status s = motion_detail::checkNumbers(node->array, context, key); !s) return s;
    out->leaf = &node->array;
    return Status();
  }
  if (!node->isList())
    return makeError(context + ": '" + key + "' is " + describeNode(*node) +
                     ", expected an array or a list of arrays");
  Result<Array> stacked = stackList(*node, context + ": '" + key + "'");
  if (!stacked) return stacked.error();
  out->leaf = nullptr;
  out->stacked = std::move(*stacked);
  return motion_detail::checkNumbers(out->stacked, context, key);
}

size_t countOf(const DataNode* node) {
  if (!node) return 0;
  if (node->isList()) return node->children.size();
  if (node->isArray() && !node->array.shape.empty())
    return static_cast<size_t>(node->array.shape[0]);
  return 0;
}

Result<const Array*> elementOf(const DataNode* node, size_t i, const std::string& context,
                               Array* scratch) {
  if (!node || i >= countOf(node)) return static_cast<const Array*>(nullptr);
  if (node->isList()) {
    const DataNode& c = node->children[i];
    return c.isArray() && !c.array.isString() ? &c.array : nullptr;
  }
  const Array& a = node->array;
  if (a.isString()) return static_cast<const Array*>(nullptr);
  const size_t each = a.data.size() / static_cast<size_t>(a.shape[0]);
  scratch->charge.release();
  if (Status s = scratch->charge.add(each * sizeof(double), context, "a row"); !s) return s.error();
  scratch->shape.assign(a.shape.begin() + 1, a.shape.end());
  scratch->dtype = a.dtype;
  scratch->data.assign(a.data.begin() + i * each, a.data.begin() + (i + 1) * each);
  return scratch;
}

Status putSmplPoses(const Array& a, const std::string& context, const char* key, Motion* m) {
  const auto& s = a.shape;
  const bool flat = s.size() == 2 && s[1] == 72;
  const bool triples = s.size() == 3 && s[1] == 24 && s[2] == 3;
  const bool matrices = s.size() == 4 && s[1] == 24 && s[2] == 3 && s[3] == 3;
  if ((!flat && !triples && !matrices) || s[0] < 1)
    return makeError(shapeError(context, key, a,
                                "(T,72) SMPL axis-angle or (T,24,3,3) rotation matrices, T >= 1"));
  if (Status st = motion_detail::checkNumbers(a, context, key); !st) return st;
  const int64_t t = s[0];
  m->layout = ModelKind::Smpl;
  if (Status st = motion_detail::allocateFrames(t, 24, context, m); !st) return st;
  for (int64_t f = 0; f < t; ++f)
    (matrices ? motion_detail::putMatrices : motion_detail::putAxisAngle)(
        a.data.data() + f * (matrices ? 216 : 72), 24, 0, &m->frames[f]);
  m->translation.assign(t, Eigen::Vector3d::Zero());
  return Status();
}

Status putTranslation(const Array& a, const std::string& context, const char* key, Motion* m) {
  const int64_t t = static_cast<int64_t>(m->frames.size());
  const auto& s = a.shape;
  const bool ok = (s.size() == 2 && s[0] == t && s[1] == 3) ||
                  (s.size() == 3 && s[0] == t && s[1] == 1 && s[2] == 3);
  if (!ok) return makeError(shapeError(context, key, a, "(" + std::to_string(t) + ",3)"));
  if (Status st = motion_detail::checkNumbers(a, context, key); !st) return st;
  m->translation.resize(t);
  for (int64_t f = 0; f < t; ++f)
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>(a.data.data() + 3 * f);
  return Status();
}

Status putBetas(const Array& a, const std::string& context, const char* key,
                const std::string& note_prefix, Motion* m) {
  if (Status st = motion_detail::checkNumbers(a, context, key); !st) return st;
  Result<BetasRows> rows = collapseBetasRows(a, context + ": '" + key + "'");
  if (!rows) return rows.error();
  m->betas = rows->betas;
  if (rows->averaged) m->notes.push_back(note_prefix + betasRowsNote(*rows));
  return Status();
}

Status putTrackBetas(const DataNode& track, const char* key, const std::string& context,
                     Motion* m) {
  if (!track.get(key)) return Status();
  Rows rows;
  if (Status s = rowsOf(track.get(key), context, key, &rows); !s) return s;
  const Array& b = rows.get();
  if (b.shape.size() != 2 || b.shape[0] != static_cast<int64_t>(m->frames.size()))
    return makeError(context + ": '" + key + "' has shape " + shapeString(b.shape) +
                     "; expected (" + std::to_string(m->frames.size()) + ",B) like the poses");
  return putBetas(b, context, key, m->track.empty() ? "" : "track " + m->track + ": ", m);
}

Result<std::vector<int64_t>> frameIds(const Array& a, size_t t, const std::string& context,
                                      const char* key) {
  if (a.isString() || static_cast<size_t>(a.size()) != t || a.data.size() != t)
    return makeError(shapeError(context, key, a, "(" + std::to_string(t) + ",) frame numbers"));
  if (Status st = checkIndices(a, context, key); !st) return st.error();
  return std::vector<int64_t>(a.data.begin(), a.data.end());
}

// "1e+16": a large id as printf's %.3g shows it.
static std::string aboutText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

Result<std::string> idText(double value, const std::string& context, const char* key) {
  // Array values arrive as doubles (core/array.h): above 9e15 neighbouring
  // integers are no longer distinct, so such an id is refused, never rounded.
  if (value >= 9.0e15 && value == std::floor(value) && std::isfinite(value))
    return makeError(context + ": '" + key + "' holds an id of about " + aboutText(value) +
                     ", beyond the largest this reader keeps exact in an array (9e15)");
  if (!(value >= 0 && value < 9.0e15) || value != std::floor(value))
    return makeError(context + ": '" + key + "' is not a non-negative integer id");
  return std::to_string(static_cast<int64_t>(value));
}

}  // namespace video_rows
}  // namespace smpl
