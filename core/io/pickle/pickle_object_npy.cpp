// parseObjectNpy: the payload of an object-dtype .npy member (np.save with
// allow_pickle writes pickle.dump(array, protocol=3)) run through the
// data-only VM, then the array's elements turned into one Array: numbers and
// strings element-wise, or for a 0-d array its one value (an array-like, or a
// dict of string -> number such as a joint-name -> index map).
// parseNpyTree: the same payload as a tree (pickle_tree.h), e.g. TRAM's and
// MDM's np.save of a dict; a numeric .npy as one leaf.
#include "core/io/npy.h"
#include "core/io/pickle/pickle_internal.h"
#include "core/io/pickle/pickle_tree.h"

namespace smpl {
namespace pickle {
namespace {

bool numberOf(const PyObj& o, double* v) {
  if (o.kind == Kind::Int || o.kind == Kind::Bool) return *v = static_cast<double>(o.i), true;
  if (o.kind == Kind::Float) return *v = o.f, true;
  if (o.kind == Kind::NdArray && o.array && o.array->shape.empty() && o.array->data.size() == 1)
    return *v = o.array->data[0], true;  // numpy scalar
  return false;
}

// {name: number, ...} -> keys + data, in insertion order (a later duplicate wins).
Result<Array> dictToArray(Heap& heap, Ref dict) {
  const std::vector<Ref> items = heap.at(dict).items;
  Array a;
  a.dtype = "|O";
  std::string key;
  for (size_t i = 0; i + 1 < items.size(); i += 2) {
    double v = 0;
    if (!stringValue(heap, items[i], &key) || !numberOf(heap.at(items[i + 1]), &v))
      return heap.fail("object array holds a dict of " + typeName(heap, items[i]) + " -> " +
                       typeName(heap, items[i + 1]) + "; expected str -> number");
    PK_TRY(heap.charge(key.size() + sizeof(double) + sizeof(std::string), "dict entry"));
    a.keys.push_back(key);
    a.data.push_back(v);
  }
  a.shape = {static_cast<int64_t>(a.keys.size())};
  return a;
}

// Element-wise: all numbers, or all strings.
Result<Array> elementsToArray(Heap& heap, const PyObj& root) {
  Array a;
  a.dtype = "|O";
  a.shape = root.object_shape;
  std::string text;
  for (Ref r : root.items) {
    double v = 0;
    if (numberOf(heap.at(r), &v) && a.strings.empty()) {
      a.data.push_back(v);
    } else if (stringValue(heap, r, &text) && a.data.empty()) {
      PK_TRY(heap.charge(text.size() + sizeof(std::string), "string"));
      a.strings.push_back(text);
    } else {
      return heap.fail("object array element is a " + typeName(heap, r) +
                       "; expected all numbers or all strings");
    }
  }
  return a;
}

}  // namespace
}  // namespace pickle

Result<Array> parseObjectNpy(const uint8_t* data, size_t size, const std::string& context,
                             const PickleLimits& limits) {
  using namespace pickle;
  Result<NpyHeaderInfo> h = parseNpyHeader(data, size, context);
  if (!h) return h.error();
  if (!isObjectDescr(h->descr))
    return makeError(context + ": dtype '" + h->descr + "' is not an object array");
  Heap heap(context, limits, size);
  Result<Ref> root = runPickle(heap, data + h->data_offset, size - h->data_offset, limits);
  if (!root) return root.error();
  const PyObj& o = heap.at(*root);
  if (o.kind != Kind::NdArray || !o.object_array)
    return heap.fail("object .npy data is a " + typeName(heap, *root) +
                     ", expected an object ndarray");
  if (o.object_shape != h->shape)
    return heap.fail("object array shape " + shapeString(o.object_shape) +
                     " disagrees with the header's " + shapeString(h->shape));
  if (o.object_shape.empty()) {  // 0-d: one Python value
    const Ref value = o.items.at(0);
    if (heap.at(value).kind == Kind::Dict) return dictToArray(heap, value);
    Array a;
    Result<bool> got = toArray(heap, value, &a);
    if (!got) return got.error();
    if (!*got)
      return heap.fail("object array holds a " + typeName(heap, value) + "; expected data");
    return a;
  }
  return elementsToArray(heap, o);
}

Result<DataNode> parseNpyTree(const uint8_t* data, size_t size, const std::string& context,
                              const PickleLimits& limits) {
  using namespace pickle;
  Result<NpyHeaderInfo> h = parseNpyHeader(data, size, context);
  if (!h) return h.error();
  if (!isObjectDescr(h->descr)) {
    Result<Array> a = parseNpy(data, size, context);
    if (!a) return a.error();
    DataNode leaf;
    leaf.kind = DataNode::Kind::Array;
    leaf.array = std::move(*a);
    return leaf;
  }
  VmOptions options;
  options.tree = true;
  Heap heap(context, limits, size, std::move(options));
  Result<Ref> root = runPickle(heap, data + h->data_offset, size - h->data_offset, limits);
  if (!root) return root.error();
  const PyObj& o = heap.at(*root);
  if (o.kind != Kind::NdArray || !o.object_array)
    return heap.fail("object .npy data is a " + typeName(heap, *root) +
                     ", expected an object ndarray");
  if (o.object_shape != h->shape)
    return heap.fail("object array shape " + shapeString(o.object_shape) +
                     " disagrees with the header's " + shapeString(h->shape));
  return toTree(heap, *root);
}

}  // namespace smpl
