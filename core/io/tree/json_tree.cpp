// parseJsonTree: nlohmann::ordered_json (keys in file order) -> DataNode.
// The nesting depth is measured on the raw text before parsing, so neither
// the parser's DOM nor the conversion below can recurse deeply.
#include "core/io/tree/json_tree.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace smpl {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kMaxDepth = 32;

// Deepest nesting of [ and { outside strings.
int nestingDepth(const uint8_t* p, size_t n) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t c = p[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

bool isNumeric(const Json& v) { return v.is_number() || v.is_boolean(); }

// True if `v` is a rectangular nest of numbers of `shape` from `level` on.
bool hasShape(const Json& v, const std::vector<int64_t>& shape, size_t level) {
  if (level == shape.size()) return isNumeric(v);
  if (!v.is_array() || static_cast<int64_t>(v.size()) != shape[level]) return false;
  for (const Json& e : v)
    if (!hasShape(e, shape, level + 1)) return false;
  return true;
}

void flatten(const Json& v, Array* out, bool* any_float, bool* all_bool) {
  if (!v.is_array()) {
    *any_float |= v.is_number_float();
    *all_bool &= v.is_boolean();
    out->data.push_back(v.is_boolean() ? (v.get<bool>() ? 1.0 : 0.0) : v.get<double>());
    return;
  }
  for (const Json& e : v) flatten(e, out, any_float, all_bool);
}

class Converter {
 public:
  explicit Converter(const std::string& context) : context_(context) {}
  Status node(const Json& v, DataNode* out);

 private:
  Status numbers(const Json& v, bool* got, DataNode* out);
  Status text(const std::string& s, DataNode* out);
  const std::string& context_;
};

// A rectangular nest of numbers (a non-empty array) as one leaf.
Status Converter::numbers(const Json& v, bool* got, DataNode* out) {
  std::vector<int64_t> shape;
  const Json* cur = &v;
  for (; cur->is_array() && !cur->empty(); cur = &(*cur)[0])
    shape.push_back(static_cast<int64_t>(cur->size()));
  if (cur->is_array()) shape.push_back(0);
  *got = hasShape(v, shape, 0);
  if (!*got) return Status();
  Array a;
  a.shape = shape;
  const uint64_t count = static_cast<uint64_t>(a.size());
  if (Status st = a.charge.add(count * sizeof(double), context_, "the JSON's arrays"); !st)
    return st;
  a.data.reserve(static_cast<size_t>(count));
  bool any_float = false, all_bool = true;
  flatten(v, &a, &any_float, &all_bool);
  a.dtype = any_float || count == 0 ? "<f8" : all_bool ? "|b1" : "<i8";
  out->kind = DataNode::Kind::Array;
  out->array = std::move(a);
  return Status();
}

Status Converter::text(const std::string& s, DataNode* out) {
  Array a;
  if (Status st = a.charge.add(sizeof(std::string) + s.size(), context_, "the JSON's strings"); !st)
    return st;
  size_t chars = 0;  // numpy's <Un counts code points
  for (char c : s) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  a.dtype = "<U" + std::to_string(chars);
  a.strings.push_back(s);
  out->kind = DataNode::Kind::Array;
  out->array = std::move(a);
  return Status();
}

Status Converter::node(const Json& v, DataNode* out) {
  *out = DataNode();
  if (v.is_null()) return Status();
  if (v.is_string()) return text(v.get_ref<const std::string&>(), out);
  if (isNumeric(v)) {
    Array a;
    a.data.push_back(v.is_boolean() ? (v.get<bool>() ? 1.0 : 0.0) : v.get<double>());
    a.dtype = v.is_boolean() ? "|b1" : v.is_number_float() ? "<f8" : "<i8";
    if (Status st = a.charge.add(sizeof(double), context_, "the JSON's arrays"); !st) return st;
    out->kind = DataNode::Kind::Array;
    out->array = std::move(a);
    return Status();
  }
  if (v.is_array() && !v.empty()) {
    bool got = false;
    if (Status st = numbers(v, &got, out); !st || got) return st;
  }
  if (v.is_array()) {
    out->kind = DataNode::Kind::List;
    if (Status st = chargeNode(out, v.size() * sizeof(DataNode), context_); !st) return st;
    out->children.resize(v.size());
    for (size_t i = 0; i < v.size(); ++i)
      if (Status st = node(v[i], &out->children[i]); !st) return st;
    return Status();
  }
  out->kind = DataNode::Kind::Dict;  // an object
  uint64_t bytes = v.size() * (sizeof(DataNode) + sizeof(std::string));
  for (const auto& item : v.items()) bytes += item.key().size();
  if (Status st = chargeNode(out, bytes, context_); !st) return st;
  out->keys.reserve(v.size());
  out->children.reserve(v.size());
  for (const auto& item : v.items()) {
    out->keys.push_back(item.key());
    out->children.emplace_back();
    if (Status st = node(item.value(), &out->children.back()); !st) return st;
  }
  return Status();
}

}  // namespace

Result<DataNode> parseJsonTree(const uint8_t* data, size_t size, const std::string& context) {
  MemoryCharge parse;
  if (Status st = parse.add(static_cast<uint64_t>(size) * 12, context, "parsing the JSON"); !st)
    return st.error();
  if (nestingDepth(data, size) > kMaxDepth)
    return makeError(context + ": JSON nested deeper than " + std::to_string(kMaxDepth) +
                     " levels");
  Json j;
  try {
    j = Json::parse(data, data + size);
  } catch (const Json::parse_error& e) {
    return makeError(context + ": not valid JSON (" +
                     (e.byte > size ? std::string("truncated")
                                    : "syntax error at byte " + std::to_string(e.byte)) +
                     ")");
  } catch (const Json::out_of_range&) {  // a number beyond double's range (1e999)
    return makeError(context + ": not valid JSON (a number out of range)");
  } catch (const Json::exception&) {
    return makeError(context + ": not valid JSON");
  }
  DataNode tree;
  if (Status st = Converter(context).node(j, &tree); !st) return st.error();
  return tree;
}

}  // namespace smpl
