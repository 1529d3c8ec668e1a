// parsePickle: run the data-only VM, then turn the top-level dict's
// array-like values (ndarray, scipy sparse, chumpy Ch, nested number lists,
// strings, numbers) into Arrays. Conversion recursion is bounded, so cyclic
// or deeply nested graphs end in "not array-like" instead of a stack overflow.
#include <cmath>

#include "core/huge_pages.h"
#include "core/io/pickle/pickle_internal.h"
#include "core/io/printable.h"

namespace smpl {
namespace pickle {

namespace {

constexpr int kMaxDepth = 32;

Result<bool> convert(Heap& heap, Ref r, Array* out, int depth);

Result<bool> copyArray(Heap& heap, const Array& a, Array* out) {
  PK_TRY(heap.charge(a.data.size() * sizeof(double) + a.strings.size() * sizeof(std::string),
                     "array copy"));
  // The heap keeps its array (the memo may hand it to several keys): a copy,
  // into a buffer advised onto huge pages before its first write.
  Array copy;
  copy.shape = a.shape;
  copy.dtype = a.dtype;
  copy.strings = a.strings;
  copy.keys = a.keys;
  copy.charge = a.charge;
  copy.data.reserve(a.data.size());
  adviseHugePages(copy.data.data(), a.data.size() * sizeof(double));
  copy.data.assign(a.data.begin(), a.data.end());
  *out = std::move(copy);
  return true;
}

// ---- nested lists of numbers ------------------------------------------------

bool isNumber(const PyObj& o) {
  return o.kind == Kind::Int || o.kind == Kind::Bool || o.kind == Kind::Float;
}
bool isSequence(const PyObj& o) { return o.kind == Kind::List || o.kind == Kind::Tuple; }

// Walk a rectangular nest of lists; false if ragged or not all numbers.
bool flattenNumbers(const Heap& heap, Ref r, const std::vector<int64_t>& shape, size_t level,
                    Array* out, bool* any_float, bool* all_bool) {
  const PyObj& o = heap.at(r);
  if (level == shape.size()) {
    if (!isNumber(o)) return false;
    *any_float |= o.kind == Kind::Float;
    *all_bool &= o.kind == Kind::Bool;
    out->data.push_back(o.kind == Kind::Float ? o.f : static_cast<double>(o.i));
    return true;
  }
  if (!isSequence(o) || static_cast<int64_t>(o.items.size()) != shape[level]) return false;
  for (Ref item : o.items) {
    if (!flattenNumbers(heap, item, shape, level + 1, out, any_float, all_bool)) return false;
  }
  return true;
}

Result<bool> listToArray(Heap& heap, Ref r, Array* out) {
  std::vector<int64_t> shape;
  int64_t count = 1;
  Ref cur = r;
  while (isSequence(heap.at(cur))) {
    if (shape.size() >= static_cast<size_t>(kMaxDepth)) return false;
    int64_t n = static_cast<int64_t>(heap.at(cur).items.size());
    shape.push_back(n);
    if (n != 0 && count > (int64_t(1) << 40) / n) return heap.fail("nested list is too large");
    count *= n;
    if (n == 0) break;
    cur = heap.at(cur).items[0];
  }
  PK_TRY(heap.charge(static_cast<uint64_t>(count) * sizeof(double), "list array"));
  Array a;
  a.shape = shape;
  a.data.reserve(count);
  bool any_float = false, all_bool = true;
  if (!flattenNumbers(heap, r, shape, 0, &a, &any_float, &all_bool)) return false;
  a.dtype = any_float || count == 0 ? "<f8" : all_bool ? "|b1" : "<i8";
  *out = std::move(a);
  return true;
}

// ---- chumpy -------------------------------------------------------------------

// Ch.__getstate__ is the instance __dict__ minus caches: the value of a plain
// Ch is its 'x' term (an ndarray). Derived nodes keep other terms; take the
// first ndarray there.
Result<bool> chToArray(Heap& heap, Ref r, Array* out, int depth) {
  const PyObj& ch = heap.at(r);
  Ref state = ch.state;
  Ref x;
  if (dictGet(heap, state, "x", &x)) {
    Result<bool> got = convert(heap, x, out, depth + 1);
    if (!got || *got) return got;
  }
  if (heap.at(state).kind == Kind::Dict) {
    std::vector<Ref> items = heap.at(state).items;
    for (size_t i = 1; i < items.size(); i += 2) {
      const PyObj& v = heap.at(items[i]);
      if (v.kind == Kind::NdArray && v.array) return copyArray(heap, *v.array, out);
    }
  }
  if (!ch.items.empty()) return convert(heap, ch.items[0], out, depth + 1);  // Ch(x) via REDUCE
  return false;
}

}  // namespace

// Defined in pickle_sparse.cpp.
Result<bool> sparseToDense(Heap& heap, Ref r, Array* out);

namespace {

Result<bool> convert(Heap& heap, Ref r, Array* out, int depth) {
  if (depth > kMaxDepth) return false;
  const PyObj& o = heap.at(r);
  Array a;
  switch (o.kind) {
    case Kind::NdArray:
      if (!o.array) return false;
      return copyArray(heap, *o.array, out);
    case Kind::Instance:
      if (o.global == GlobalId::Ch) return chToArray(heap, r, out, depth);
      if (o.global == GlobalId::Csc || o.global == GlobalId::Csr || o.global == GlobalId::Coo) {
        return sparseToDense(heap, r, out);
      }
      return false;
    case Kind::List:
    case Kind::Tuple:
      return listToArray(heap, r, out);
    case Kind::Str:
    case Kind::Bytes: {
      const std::string_view text = o.bytes();
      PK_TRY(heap.charge(text.size(), "string"));
      a.strings.emplace_back(text);
      size_t chars = 0;  // numpy's <Un counts code points, not UTF-8 bytes
      for (char c : text) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      a.dtype =
          o.kind == Kind::Str ? "<U" + std::to_string(chars) : "|S" + std::to_string(text.size());
      break;
    }
    case Kind::Int:
      a.data.push_back(static_cast<double>(o.i));
      a.dtype = "<i8";
      break;
    case Kind::Bool:
      a.data.push_back(static_cast<double>(o.i));
      a.dtype = "|b1";
      break;
    case Kind::Float:
      a.data.push_back(o.f);
      a.dtype = "<f8";
      break;
    default:
      return false;
  }
  *out = std::move(a);
  return true;
}

}  // namespace

Result<bool> toArray(Heap& heap, Ref r, Array* out) { return convert(heap, r, out, 0); }

}  // namespace pickle

Result<ArrayDict> parsePickle(const uint8_t* data, size_t size, const std::string& context,
                              const PickleLimits& limits) {
  using namespace pickle;
  Heap heap(context, limits, size);
  Result<Ref> root = runPickle(heap, data, size, limits);
  if (!root) return root.error();
  if (heap.at(*root).kind != Kind::Dict) {
    return heap.fail("pickle top level is " + typeName(heap, *root) +
                     ", expected a dict of model arrays");
  }
  ArrayDict result;
  std::vector<Ref> items = heap.at(*root).items;
  std::string key;
  for (size_t i = 0; i + 1 < items.size(); i += 2) {
    if (!stringValue(heap, items[i], &key)) continue;
    Array a;
    Result<bool> got = toArray(heap, items[i + 1], &a);
    if (!got) return makeError(got.message() + " (key '" + printable(key, 100) + "')");
    if (*got) {
      result[key] = std::move(a);
    } else {
      result.erase(key);  // a later non-array value replaces an earlier one, as in a Python dict
    }
  }
  return result;
}

}  // namespace smpl
