// Any unpickled value -> DataNode, and parsePickleTree (plain pickles and
// joblib files). The rules (core/io/pickle/pickle_tree.h):
//   dict            -> Dict; keys str/bytes as text, int (and numpy integer)
//                      keys as decimal text, other keys skipped
//   list, tuple     -> an Array leaf when a rectangular nest of numbers
//                      (listToArray, as the flat reader), else a List whose
//                      unconvertible elements are None (positions stay)
//   ndarray, scipy sparse, chumpy Ch, str, bytes, numbers -> Array leaves
//   object ndarray  -> its element (0-d); all numbers or all strings -> one
//                      leaf; else Lists nested as its shape
//   None, classes, other objects -> None
// Sharing: an ndarray referenced once is moved into its leaf; one the memo
// shares is copied at each reference, and every copy, node and key is
// counted against the pickle's limit (heapByteLimit) before it is made, so a
// small file that repeats one object many times is refused, not expanded.
// Depth is bounded (kMaxDepth); a cycle (a list that contains itself) ends
// in None.
#include "core/io/pickle/pickle_tree.h"

#include "core/io/pickle/pickle_internal.h"
#include "core/io/printable.h"

namespace smpl {
namespace pickle {
namespace {

constexpr int kMaxDepth = 32;

bool isNumber(const PyObj& o) {
  return o.kind == Kind::Int || o.kind == Kind::Bool || o.kind == Kind::Float ||
         (o.kind == Kind::NdArray && o.array && o.array->shape.empty() &&
          o.array->data.size() == 1);
}

double numberValue(const PyObj& o) {
  if (o.kind == Kind::Float) return o.f;
  if (o.kind == Kind::NdArray) return o.array->data[0];
  return static_cast<double>(o.i);
}

// Bytes an Array holds (what its charge must cover).
uint64_t arrayBytes(const Array& a) {
  uint64_t n = a.data.size() * sizeof(double);
  for (const std::string& s : a.strings) n += sizeof(std::string) + s.size();
  return n;
}

class TreeBuilder {
 public:
  explicit TreeBuilder(Heap& heap) : heap_(heap), refs_(heap.size(), 0) {
    for (size_t r = 0; r < heap.size(); ++r) {  // references from other objects
      const PyObj& o = heap.at(static_cast<Ref>(r));
      for (Ref item : o.items) ++refs_[item];
      if (o.state) ++refs_[o.state];
    }
  }
  Status node(Ref r, int depth, DataNode* out);

 private:
  Status leaf(Ref r, DataNode* out, bool* got);
  Status dict(Ref r, int depth, DataNode* out);
  Status list(const std::vector<Ref>& items, int depth, DataNode* out);
  Status objectArray(Ref r, int depth, DataNode* out);
  Status nested(const std::vector<Ref>& items, const std::vector<int64_t>& shape, size_t level,
                size_t* next, int depth, DataNode* out);
  Status countNode(uint64_t extra) { return heap_.count(sizeof(DataNode) + extra, "tree node"); }
  bool keyText(Ref k, std::string* key) const;
  Error fail(const std::string& message) const { return heap_.fail(message + where()); }
  // An error of the pickle reader ("<context>: <problem>") with the path added.
  Error located(const Error& e) const {
    const std::string prefix = heap_.context() + ": ";
    if (e.message.compare(0, prefix.size(), prefix) != 0) return e;
    return fail(e.message.substr(prefix.size()));
  }
  std::string where() const { return path_.empty() ? "" : " at " + printable(path_, 200); }

  Heap& heap_;
  std::vector<uint32_t> refs_;  // how many objects refer to each object
  std::vector<Ref> ancestors_;
  std::string path_;  // "[0]['smpl'][2]": where the builder is, for errors
};

// Array-like values (toArray); the array of an ndarray referenced once is
// moved, not copied. `*got` false: not array-like.
Status TreeBuilder::leaf(Ref r, DataNode* out, bool* got) {
  PyObj& o = heap_.at(r);
  Array a;
  if (o.kind == Kind::NdArray && o.array && refs_[r] <= 1) {
    a = std::move(*o.array);
    o.array.reset();
    o.kind = Kind::None;  // moved: a second visit (the tree root twice) sees None
  } else {
    Result<bool> converted = toArray(heap_, r, &a);
    if (!converted) return located(converted.error());
    *got = *converted;
    if (!*got) return Status::success();
    const uint64_t need = arrayBytes(a), held = a.charge.bytes();
    if (need > held)
      if (Status st = a.charge.add(need - held, heap_.context(), "the arrays read"); !st) return st;
  }
  out->kind = DataNode::Kind::Array;
  out->array = std::move(a);
  *got = true;
  return Status::success();
}

Status TreeBuilder::node(Ref r, int depth, DataNode* out) {
  PK_TRY(countNode(0));
  *out = DataNode();
  for (Ref a : ancestors_)
    if (a == r) return Status::success();  // a cycle: None
  if (depth > kMaxDepth)
    return fail("data nested deeper than " + std::to_string(kMaxDepth) + " levels");
  const PyObj& o = heap_.at(r);
  if (o.kind == Kind::Dict) return dict(r, depth, out);
  if (o.kind == Kind::NdArray && o.object_array) return objectArray(r, depth, out);
  if (o.kind == Kind::Set) return list(std::vector<Ref>(o.items), depth, out);
  if ((o.kind == Kind::List || o.kind == Kind::Tuple) && o.items.empty()) {
    out->kind = DataNode::Kind::List;  // [] is an empty list, not an array of numbers
    return Status::success();
  }
  bool got = false;
  PK_TRY(leaf(r, out, &got));
  if (got || (o.kind != Kind::List && o.kind != Kind::Tuple)) return Status::success();
  ancestors_.push_back(r);
  Status st = list(std::vector<Ref>(heap_.at(r).items), depth, out);
  ancestors_.pop_back();
  return st;
}

Status TreeBuilder::list(const std::vector<Ref>& items, int depth, DataNode* out) {
  out->kind = DataNode::Kind::List;
  PK_TRY(chargeNode(out, items.size() * sizeof(DataNode), heap_.context()));
  out->children.resize(items.size());
  const size_t mark = path_.size();
  for (size_t i = 0; i < items.size(); ++i) {
    path_ += "[" + std::to_string(i) + "]";
    PK_TRY(node(items[i], depth + 1, &out->children[i]));
    path_.resize(mark);
  }
  return Status::success();
}

Status TreeBuilder::dict(Ref r, int depth, DataNode* out) {
  out->kind = DataNode::Kind::Dict;
  ancestors_.push_back(r);
  const std::vector<Ref> items = heap_.at(r).items;
  const size_t mark = path_.size(), entries = items.size() / 2;
  Status st = chargeNode(out, entries * (sizeof(DataNode) + sizeof(std::string)), heap_.context());
  if (st) {
    out->keys.reserve(entries);
    out->children.reserve(entries);
  }
  std::string key;
  for (size_t i = 0; st && i + 1 < items.size(); i += 2) {
    if (!keyText(items[i], &key)) continue;  // float, tuple, ... keys: not names
    st = heap_.count(sizeof(std::string) + key.size(), "dict key");
    if (st) st = chargeNode(out, key.size(), heap_.context());
    if (!st) break;
    path_ += "['" + key + "']";
    DataNode child;
    st = node(items[i + 1], depth + 1, &child);
    path_.resize(mark);
    out->keys.push_back(key);
    out->children.push_back(std::move(child));
  }
  ancestors_.pop_back();
  return st;
}

// str/bytes keys as they are, int and numpy integer keys as decimal text.
bool TreeBuilder::keyText(Ref k, std::string* key) const {
  const PyObj& o = heap_.at(k);
  if (stringValue(heap_, k, key)) return true;
  if (o.kind == Kind::Int || o.kind == Kind::Bool) {
    *key = std::to_string(o.i);
    return true;
  }
  if (o.kind == Kind::NdArray && isNumber(o) && o.array->dtype.size() > 1 &&
      (o.array->dtype[1] == 'i' || o.array->dtype[1] == 'u')) {
    *key = std::to_string(static_cast<int64_t>(numberValue(o)));
    return true;
  }
  return false;
}

// Nested Lists following an object array's shape.
Status TreeBuilder::nested(const std::vector<Ref>& items, const std::vector<int64_t>& shape,
                           size_t level, size_t* next, int depth, DataNode* out) {
  if (level == shape.size()) return node(items[(*next)++], depth, out);
  PK_TRY(countNode(0));
  out->kind = DataNode::Kind::List;
  PK_TRY(chargeNode(out, static_cast<uint64_t>(shape[level]) * sizeof(DataNode), heap_.context()));
  out->children.resize(static_cast<size_t>(shape[level]));
  const size_t mark = path_.size();
  for (int64_t i = 0; i < shape[level]; ++i) {
    path_ += "[" + std::to_string(i) + "]";
    PK_TRY(nested(items, shape, level + 1, next, depth + 1, &out->children[i]));
    path_.resize(mark);
  }
  return Status::success();
}

Status TreeBuilder::objectArray(Ref r, int depth, DataNode* out) {
  const std::vector<Ref> items = heap_.at(r).items;
  const std::vector<int64_t> shape = heap_.at(r).object_shape;
  if (shape.empty()) return items.empty() ? Status::success() : node(items[0], depth, out);
  bool numbers = true, strings = true;
  std::string text;
  for (Ref item : items) {
    numbers &= isNumber(heap_.at(item));
    strings &= heap_.at(item).kind == Kind::Str || heap_.at(item).kind == Kind::Bytes;
  }
  if (items.empty() || !(numbers || strings)) {
    if (shape.size() > static_cast<size_t>(kMaxDepth))
      return fail("object array of " + std::to_string(shape.size()) + " dimensions");
    ancestors_.push_back(r);
    size_t next = 0;
    Status st = nested(items, shape, 0, &next, depth, out);
    ancestors_.pop_back();
    return st;
  }
  Array a;
  a.dtype = "|O";
  a.shape = shape;
  uint64_t bytes = 0;
  for (Ref item : items)
    bytes += numbers ? sizeof(double) : sizeof(std::string) + heap_.at(item).bytes().size();
  PK_TRY(heap_.count(bytes, "object array"));
  if (Status st = a.charge.add(bytes, heap_.context(), "the arrays read"); !st) return st;
  for (Ref item : items) {
    if (numbers) {
      a.data.push_back(numberValue(heap_.at(item)));
    } else {
      a.strings.emplace_back(heap_.at(item).bytes());
    }
  }
  out->kind = DataNode::Kind::Array;
  out->array = std::move(a);
  return Status::success();
}

}  // namespace

Result<DataNode> toTree(Heap& heap, Ref root) {
  TreeBuilder builder(heap);
  DataNode tree;
  if (Status st = builder.node(root, 0, &tree); !st) return st.error();
  return tree;
}

}  // namespace pickle

bool isLegacyTorchFile(const uint8_t* data, size_t size) {
  // torch's legacy format starts with pickle.dump(MAGIC_NUMBER, protocol=2):
  // PROTO 2, LONG1 of 10 bytes, 0x1950a86a20f9469cfc6c little-endian
  // (torch/serialization.py _legacy_save).
  static const uint8_t kMagic[] = {0x80, 0x02, 0x8a, 0x0a, 0x6c, 0xfc, 0x9c,
                                   0x46, 0xf9, 0x20, 0x6a, 0xa8, 0x50, 0x19};
  return size >= sizeof(kMagic) && std::equal(kMagic, kMagic + sizeof(kMagic), data);
}

Result<DataNode> parsePickleTree(const uint8_t* data, size_t size, const std::string& context,
                                 const PickleLimits& limits) {
  using namespace pickle;
  if (isLegacyTorchFile(data, size)) return makeError(context + ": " + kLegacyTorchMessage);
  VmOptions options;
  options.tree = true;
  Heap heap(context, limits, size, std::move(options));
  Result<Ref> root = runPickle(heap, data, size, limits);
  if (!root) return root.error();
  return toTree(heap, *root);
}

}  // namespace smpl
