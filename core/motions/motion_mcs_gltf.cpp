#include "core/motions/motion_mcs_gltf.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/io/base64.h"
#include "core/math/rotation.h"

namespace smpl {
namespace mcs {
namespace {

constexpr int64_t kMaxCount = 100000000;  // accessor counts and lengths beyond any scene file

std::string at(const char* kind, int64_t i) { return std::string(kind) + " " + std::to_string(i); }

// The List `key` of the root and its child i as a Dict, or the error.
Result<const DataNode*> item(const DataNode& root, const char* key, const char* kind, int64_t i,
                             const std::string& context) {
  const DataNode* d = element(root.get(key), i);
  if (!d || !d->isDict())
    return makeError(context + ": " + at(kind, i) + " is missing (no '" + key + "[" +
                     std::to_string(i) + "]' object)");
  return d;
}

// The text of a Dict's string member, or "".
std::string text(const DataNode& d, const char* key) {
  const Array* a = d.leaf(key);
  return a && a->strings.size() == 1 ? a->strings[0] : std::string();
}

Result<std::vector<double>> numbers(const DataNode& d, const char* key, size_t n,
                                    const std::string& context) {
  const Array* a = d.leaf(key);
  if (!a || a->isString() || a->data.size() != n)
    return makeError(context + ": '" + key + "' is not " + std::to_string(n) + " numbers");
  for (double v : a->data)
    if (!std::isfinite(v)) return makeError(context + ": '" + key + "' is not finite");
  return a->data;
}

// Values of one channel (a sampler's input times and output rows).
struct Channel {
  std::vector<double> times, values;
  int width = 0;
};

Result<Channel> channel(const DataNode& root, const DataNode& animation, int64_t sampler, int width,
                        const std::string& context) {
  const DataNode* s = element(animation.get("samplers"), sampler);
  if (!s || !s->isDict()) return makeError(context + ": " + at("sampler", sampler) + " is missing");
  const std::string interpolation = text(*s, "interpolation");
  if (!interpolation.empty() && interpolation != "LINEAR")
    return makeError(context + ": the camera's sampler is " + interpolation +
                     "; only LINEAR is read");
  Result<int64_t> input = integer(*s, "input", -1, context + ": " + at("sampler", sampler));
  if (!input) return input.error();
  Result<int64_t> output = integer(*s, "output", -1, context + ": " + at("sampler", sampler));
  if (!output) return output.error();
  Channel c;
  c.width = width;
  Result<std::vector<double>> t = accessorFloats(root, *input, 1, context);
  if (!t) return t.error();
  Result<std::vector<double>> v = accessorFloats(root, *output, width, context);
  if (!v) return v.error();
  c.times = std::move(*t);
  c.values = std::move(*v);
  if (c.times.empty() || c.values.size() != c.times.size() * width)
    return makeError(context + ": the camera's sampler has " + std::to_string(c.times.size()) +
                     " times for " + std::to_string(c.values.size() / width) + " values");
  for (size_t i = 1; i < c.times.size(); ++i)
    if (!(c.times[i] > c.times[i - 1]))
      return makeError(context + ": the camera's key times do not increase (key " +
                       std::to_string(i) + ")");
  return c;
}

Eigen::Quaterniond quaternion(const double* xyzw) {
  Eigen::Quaterniond q(xyzw[3], xyzw[0], xyzw[1], xyzw[2]);
  return q.norm() > 1e-12 ? q.normalized() : Eigen::Quaterniond::Identity();
}

// The channel at time t: the key itself within 1e-4 frame, else the blend of
// the two keys around it (lerp; slerp for width 4).
Eigen::VectorXd sample(const Channel& c, double t, double frame_time) {
  const auto key = [&](size_t i) {
    return Eigen::Map<const Eigen::VectorXd>(c.values.data() + i * c.width, c.width);
  };
  size_t k = std::upper_bound(c.times.begin(), c.times.end(), t) - c.times.begin();
  if (k > 0 && std::abs(c.times[k - 1] - t) <= 1e-4 * frame_time) return key(k - 1);
  if (k < c.times.size() && std::abs(c.times[k] - t) <= 1e-4 * frame_time) return key(k);
  if (k == 0) return key(0);
  if (k == c.times.size()) return key(k - 1);
  const double w = (t - c.times[k - 1]) / (c.times[k] - c.times[k - 1]);
  if (c.width != 4) return (1 - w) * key(k - 1) + w * key(k);
  const Eigen::Quaterniond q =
      slerp(quaternion(&c.values[(k - 1) * 4]), w, quaternion(&c.values[k * 4]));
  Eigen::VectorXd out(4);
  out << q.x(), q.y(), q.z(), q.w();
  return out;
}

// The index of the first node with a camera, or -1.
int64_t cameraNode(const DataNode& root) {
  const DataNode* nodes = root.get("nodes");
  for (int64_t i = 0; nodes && nodes->isList() && i < int64_t(nodes->children.size()); ++i)
    if (nodes->children[i].isDict() && nodes->children[i].get("camera")) return i;
  return -1;
}

// True when a node holding `node` among its children has a transform of its
// own (the camera's pose would then be relative to it).
bool parentMoves(const DataNode& root, int64_t node) {
  const DataNode* nodes = root.get("nodes");
  for (const DataNode& n : nodes->children) {
    const Array* kids = n.isDict() ? n.leaf("children") : nullptr;
    if (!kids || std::find(kids->data.begin(), kids->data.end(), double(node)) == kids->data.end())
      continue;
    for (const char* key : {"translation", "rotation", "scale", "matrix"})
      if (n.get(key)) return true;
  }
  return false;
}

// The sampler index of the channel animating `node`'s `path`, and its animation.
const DataNode* findChannel(const DataNode& root, int64_t node, const char* path,
                            int64_t* sampler) {
  const DataNode* animations = root.get("animations");
  for (int64_t a = 0;
       animations && animations->isList() && a < int64_t(animations->children.size()); ++a) {
    const DataNode& anim = animations->children[a];
    const DataNode* channels = anim.isDict() ? anim.get("channels") : nullptr;
    for (int64_t c = 0; channels && channels->isList() && c < int64_t(channels->children.size());
         ++c) {
      const DataNode& ch = channels->children[c];
      const DataNode* target = ch.isDict() ? ch.get("target") : nullptr;
      if (!target || !target->isDict() || text(*target, "path") != path) continue;
      const Array* n = target->leaf("node");
      const Array* s = ch.leaf("sampler");
      if (n && n->data.size() == 1 && n->data[0] == double(node) && s && s->data.size() == 1 &&
          s->data[0] >= 0 && s->data[0] < double(kMaxCount)) {
        *sampler = static_cast<int64_t>(s->data[0]);
        return &anim;
      }
    }
  }
  return nullptr;
}

}  // namespace

const DataNode* element(const DataNode* list, int64_t i) {
  if (!list || !list->isList() || i < 0 || i >= int64_t(list->children.size())) return nullptr;
  return &list->children[i];
}

Result<int64_t> integer(const DataNode& dict, const char* key, int64_t fallback,
                        const std::string& context) {
  const DataNode* node = dict.get(key);
  if (!node && fallback >= 0) return fallback;
  const Array* a = dict.leaf(key);
  if (!a || a->isString() || a->data.size() != 1 || !(a->data[0] >= 0) ||
      a->data[0] != std::floor(a->data[0]) || a->data[0] > 9.0e15)
    return makeError(context + ": '" + key + "' is " +
                     (node ? "not a non-negative integer" : "missing"));
  return static_cast<int64_t>(a->data[0]);
}

Result<std::vector<uint8_t>> bufferViewBytes(const DataNode& root, int64_t view,
                                             const std::string& context) {
  Result<const DataNode*> v = item(root, "bufferViews", "bufferView", view, context);
  if (!v) return v.error();
  const std::string vctx = context + ": " + at("bufferView", view);
  Result<int64_t> buffer = integer(**v, "buffer", -1, vctx);
  if (!buffer) return buffer.error();
  Result<int64_t> offset = integer(**v, "byteOffset", 0, vctx);
  if (!offset) return offset.error();
  Result<int64_t> length = integer(**v, "byteLength", -1, vctx);
  if (!length) return length.error();
  Result<const DataNode*> b = item(root, "buffers", "buffer", *buffer, context);
  if (!b) return b.error();
  const std::string bctx = context + ": " + at("buffer", *buffer);
  Result<int64_t> declared = integer(**b, "byteLength", -1, bctx);
  if (!declared) return declared.error();
  const std::string uri = text(**b, "uri");
  const size_t comma = uri.find(',');
  if (uri.rfind("data:", 0) != 0 || comma == std::string::npos ||
      uri.substr(0, comma).find(";base64") == std::string::npos)
    return makeError(bctx + ": not an embedded base64 data URI (external files are not read)");
  // Decoding is bounded by the text already read (3 bytes per 4 characters);
  // the declared lengths are then checked against what it holds.
  Result<std::vector<uint8_t>> bytes = decodeBase64(std::string_view(uri).substr(comma + 1), bctx);
  if (!bytes) return bytes.error();
  if (uint64_t(*declared) > bytes->size())
    return makeError(bctx + " declares " + std::to_string(*declared) +
                     " bytes; its data URI holds " + std::to_string(bytes->size()));
  if (uint64_t(*offset) + uint64_t(*length) > uint64_t(*declared))
    return makeError(vctx + ": bytes " + std::to_string(*offset) + ".." +
                     std::to_string(*offset + *length) + " lie outside buffer " +
                     std::to_string(*buffer) + " (" + std::to_string(*declared) + " bytes)");
  return std::vector<uint8_t>(bytes->begin() + *offset, bytes->begin() + *offset + *length);
}

Result<std::vector<double>> accessorFloats(const DataNode& root, int64_t index, int components,
                                           const std::string& context) {
  Result<const DataNode*> a = item(root, "accessors", "accessor", index, context);
  if (!a) return a.error();
  const std::string actx = context + ": " + at("accessor", index);
  const char* type = components == 1 ? "SCALAR" : components == 3 ? "VEC3" : "VEC4";
  Result<int64_t> component = integer(**a, "componentType", -1, actx);
  if (!component) return component.error();
  if (*component != 5126 || text(**a, "type") != type)
    return makeError(actx + ": expected float (5126) " + type + " values");
  Result<int64_t> count = integer(**a, "count", -1, actx);
  if (!count) return count.error();
  Result<int64_t> offset = integer(**a, "byteOffset", 0, actx);
  if (!offset) return offset.error();
  Result<int64_t> view = integer(**a, "bufferView", -1, actx);
  if (!view) return view.error();
  Result<const DataNode*> v = item(root, "bufferViews", "bufferView", *view, context);
  if (!v) return v.error();
  const int64_t element_size = 4 * components;
  Result<int64_t> stride = integer(**v, "byteStride", element_size, actx);
  if (!stride) return stride.error();
  if (*count < 1 || *count > kMaxCount || *stride < element_size)
    return makeError(actx + ": count " + std::to_string(*count) + ", stride " +
                     std::to_string(*stride) + " are out of range");
  Result<std::vector<uint8_t>> bytes = bufferViewBytes(root, *view, context);
  if (!bytes) return bytes.error();
  if (uint64_t(*offset) + uint64_t(*stride) * uint64_t(*count - 1) + uint64_t(element_size) >
      bytes->size())
    return makeError(actx + ": " + std::to_string(*count) + " " + type +
                     " values do not fit its buffer view (" + std::to_string(bytes->size()) +
                     " bytes)");
  std::vector<double> out;
  out.reserve(size_t(*count) * components);
  for (int64_t i = 0; i < *count; ++i)
    for (int c = 0; c < components; ++c) {
      float f;
      std::memcpy(&f, bytes->data() + *offset + i * *stride + 4 * c, 4);
      if (!std::isfinite(f)) return makeError(actx + ": NaN or infinite values");
      out.push_back(f);
    }
  return out;
}

Result<SceneCamera> readCamera(const DataNode& root, double fps, int64_t num_frames,
                               const std::string& context, std::vector<std::string>* notes) {
  SceneCamera cam;
  const int64_t node = cameraNode(root);
  if (node < 0) {
    notes->push_back("no camera node in the scene: no scene camera");
    return cam;
  }
  const DataNode& n = root.get("nodes")->children[node];
  if (parentMoves(root, node))
    notes->push_back(
        "ignored: the transform of the camera node's parent (the camera's pose is "
        "read as it stands in the node)");
  const std::string nctx = context + ": " + at("node", node);
  Result<int64_t> which = integer(n, "camera", -1, nctx);
  if (!which) return which.error();
  if (const DataNode* c = element(root.get("cameras"), *which); c && c->isDict())
    if (const DataNode* p = c->get("perspective"); p && p->isDict()) {
      const Array* yfov = p->leaf("yfov");
      const Array* aspect = p->leaf("aspectRatio");
      if (yfov && yfov->data.size() == 1 && yfov->data[0] > 0 && yfov->data[0] < M_PI)
        cam.yfov = yfov->data[0];
      if (aspect && aspect->data.size() == 1 && aspect->data[0] > 0 && aspect->data[0] < 1e6)
        cam.aspect = aspect->data[0];
    }
  std::vector<double> t0 = {0, 0, 0}, r0 = {0, 0, 0, 1};
  if (n.get("translation")) {
    Result<std::vector<double>> t = numbers(n, "translation", 3, nctx);
    if (!t) return t.error();
    t0 = *t;
  }
  if (n.get("rotation")) {
    Result<std::vector<double>> r = numbers(n, "rotation", 4, nctx);
    if (!r) return r.error();
    r0 = *r;
  }
  Channel position{{0.0}, t0, 3}, rotation{{0.0}, r0, 4};
  int64_t s = 0;
  bool animated = false;
  if (const DataNode* anim = findChannel(root, node, "translation", &s)) {
    Result<Channel> c = channel(root, *anim, s, 3, context);
    if (!c) return c.error();
    position = std::move(*c);
    animated = true;
  }
  if (const DataNode* anim = findChannel(root, node, "rotation", &s)) {
    Result<Channel> c = channel(root, *anim, s, 4, context);
    if (!c) return c.error();
    rotation = std::move(*c);
    animated = true;
  }
  const double dt = 1.0 / fps;
  int64_t first = 0, last = std::max<int64_t>(num_frames, 1) - 1;
  if (animated) {
    const double start = std::max(position.times.front(), rotation.times.front());
    const double end = std::max(position.times.back(), rotation.times.back());
    first = static_cast<int64_t>(std::ceil(start * fps - 1e-4));
    last = static_cast<int64_t>(std::floor(end * fps + 1e-4));
    if (last - first + 1 > kMaxCount || first < 0)
      return makeError(context + ": the camera's keys span frames " + std::to_string(first) + ".." +
                       std::to_string(last));
  }
  const Eigen::Matrix3d gltf_to_cv = Eigen::Vector3d(1, -1, -1).asDiagonal();
  cam.first_frame = first;
  for (int64_t f = first; f <= last; ++f) {
    const Eigen::VectorXd p = sample(position, f * dt, dt), q = sample(rotation, f * dt, dt);
    cam.position.push_back(p);
    cam.rotation.push_back(quaternion(q.data()).toRotationMatrix() * gltf_to_cv);
  }
  notes->push_back("scene camera from " + at("node", node) + " (" +
                   (animated ? "animated" : "static") + ", frames " + std::to_string(first) + "-" +
                   std::to_string(last) + ")");
  return cam;
}

}  // namespace mcs
}  // namespace smpl
