// Any unpickled value -> DataNode, and parsePickleTree (plain pickles and
// joblib files). The rules (core/io/pickle/pickle_tree.h):
//   dict            -> Dict; every key becomes text (keyText): str and bytes
//                      as they are, int (any size, numpy integer scalars
//                      too, never through a double) as exact decimal, bool
//                      as 1/0, float as its shortest round-trip text, None
//                      as "None", a tuple as its canonical repr "(1, 'a')";
//                      a key of another type is refused by name, and two
//                      different keys that give one text (1 and '1', b'x'
//                      and 'x') are refused naming both: a track is never
//                      dropped or merged in silence. A repeated key keeps
//                      its last value, as Python's dict does.
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

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>

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
  // A value and its subtree; under an object the memo shares (referenced
  // more than once), nothing is moved out: every visit copies.
  Status node(Ref r, int depth, DataNode* out) {
    const bool shared = refs_[r] > 1;
    shared_ += shared;
    Status st = visit(r, depth, out);
    shared_ -= shared;
    return st;
  }

 private:
  Status visit(Ref r, int depth, DataNode* out);
  Status leaf(Ref r, DataNode* out, bool* got);
  Status dict(Ref r, int depth, DataNode* out);
  Status list(const std::vector<Ref>& items, int depth, DataNode* out);
  Status objectArray(Ref r, int depth, DataNode* out);
  Status nested(const std::vector<Ref>& items, const std::vector<int64_t>& shape, size_t level,
                size_t* next, int depth, DataNode* out);
  Status countNode(uint64_t extra) { return heap_.count(sizeof(DataNode) + extra, "tree node"); }
  Status keyText(Ref k, int depth, std::string* key, std::string* repr) const;
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
  int shared_ = 0;    // shared objects on the path from the root to the value visited
  std::string path_;  // "[0]['smpl'][2]": where the builder is, for errors
};

// Array-like values (toArray); the array of an ndarray referenced once is
// moved, not copied. `*got` false: not array-like.
Status TreeBuilder::leaf(Ref r, DataNode* out, bool* got) {
  PyObj& o = heap_.at(r);
  Array a;
  if (o.kind == Kind::NdArray && o.array && refs_[r] <= 1 && shared_ == 0) {
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

Status TreeBuilder::visit(Ref r, int depth, DataNode* out) {
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
  std::unordered_map<std::string, size_t> seen;  // key text -> index in out->keys
  std::vector<std::string> reprs;                // each key as the file has it, for refusals
  std::string key, repr;
  for (size_t i = 0; st && i + 1 < items.size(); i += 2) {
    st = keyText(items[i], 0, &key, &repr);
    if (st) st = heap_.count(2 * sizeof(std::string) + key.size() + repr.size(), "dict key");
    if (st) st = chargeNode(out, key.size(), heap_.context());
    if (!st) break;
    const auto [at, fresh] = seen.emplace(key, out->keys.size());
    if (!fresh && reprs[at->second] != repr) {
      st = fail("dict keys " + printable(reprs[at->second], 100) + " and " + printable(repr, 100) +
                " both read as the name '" + printable(key, 100) +
                "' (one would hide the other); give the keys distinct names");
      break;
    }
    path_ += "['" + key + "']";
    DataNode child;
    st = node(items[i + 1], depth + 1, &child);
    path_.resize(mark);
    if (!fresh) {  // the same key again: Python's dict keeps the last value
      out->children[at->second] = std::move(child);
      continue;
    }
    out->keys.push_back(key);
    reprs.push_back(repr);
    out->children.push_back(std::move(child));
  }
  ancestors_.pop_back();
  return st;
}

namespace {

// Shortest text that reads back as `v` ("0.1", "1e+20", "2.0", "nan"): a
// float key's name. A whole number keeps ".0" so it never reads as an int's.
std::string floatText(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  char buf[40];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  std::string text = buf;
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

}  // namespace

// A dict key's name (`key`) and how the file wrote it (`repr`, Python's
// spelling, for refusals): str -> as is ('a'); bytes -> as is (b'a'; Python
// 2 pickles write str keys as bytes); int, numpy integer -> exact decimal;
// bool -> 1/0 (True == 1 in a Python dict); float -> floatText; None ->
// "None"; tuple -> "(1, 'a')" from its elements' reprs. Other types (frozenset,
// objects) are refused naming the type.
Status TreeBuilder::keyText(Ref k, int depth, std::string* key, std::string* repr) const {
  const PyObj& o = heap_.at(k);
  if (o.kind == Kind::Str || o.kind == Kind::Bytes) {
    stringValue(heap_, k, key);
    *repr = (o.kind == Kind::Bytes ? "b'" : "'") + *key + "'";
  } else if (o.kind == Kind::Bool) {
    *key = o.i ? "1" : "0";
    *repr = o.i ? "True" : "False";
  } else if (o.kind == Kind::Int) {
    *key = *repr = std::to_string(o.i);
  } else if (o.kind == Kind::Float || (o.kind == Kind::NdArray && isNumber(o))) {
    // An int beyond int64 and a numpy integer keep their exact text.
    *key = !o.exact.empty() ? o.exact : floatText(numberValue(o));
    *repr = *key;
  } else if (o.kind == Kind::None) {
    *key = *repr = "None";
  } else if (o.kind == Kind::Tuple && depth < kMaxDepth) {
    std::string item, item_repr;
    *key = "(";
    for (size_t i = 0; i < o.items.size(); ++i) {
      PK_TRY(keyText(o.items[i], depth + 1, &item, &item_repr));
      *key += (i ? ", " : "") + item_repr;
      PK_TRY(heap_.check(key->size(), "dict key"));
    }
    *key += o.items.size() == 1 ? ",)" : ")";
    *repr = *key;
  } else {
    return fail("a dict key of type " + typeName(heap_, k) +
                " cannot name anything (keys are read as str, bytes, int, float, None or tuples "
                "of them)");
  }
  return Status::success();
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
