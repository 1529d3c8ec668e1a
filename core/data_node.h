// A container's contents as a tree, for inputs whose data is nested: a dict
// of per-track dicts (WHAM, a joblib pickle), per-frame lists of persons
// (4D-Humans / PHALP, EasyMocap JSON), dicts of tensors in a torch `.pt`
// (GVHMR), an `np.save`d dict in a `.npy` (TRAM), an object array inside an
// `.npz` (ROMP's `results`). Leaves are Arrays (core/array.h: numbers widened
// to double, C order); inner nodes are dicts (keys in file order) and lists.
// The container readers build it (core/io/tree/data_tree.h); the motion layouts
// read it (core/motions/motion_layout.h). It owns its data: each leaf holds
// its own memory charge (core/memory_budget.h).
//
//   const DataNode* body = root.get("smpl_params_global");
//   const Array* pose = body ? body->leaf("body_pose") : nullptr;  // (T,63)
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/array.h"
#include "core/result.h"

namespace smpl {

struct DataNode {
  enum class Kind {
    None,   // Python None, or a value that is not data (an object the readers do not rebuild)
    Array,  // a leaf: `array`
    Dict,   // keys[i] names children[i], in file order; integer keys as decimal text ("0", "12")
    List,   // children in order (a Python list or tuple, a JSON array that is not rectangular
            // numbers)
  };
  Kind kind = Kind::None;
  // A leaf's data; for a Dict or List, only `array.charge` is used: it holds
  // the node's own bytes (its children and keys, chargeNode below), so a
  // whole tree's memory is charged while it lives.
  Array array;
  std::vector<std::string> keys;
  std::vector<DataNode> children;
  // Set when a reader fetched this node by key (get, leaf): after a layout's
  // decode, a pose-like leaf never fetched is named in an "ignored" note
  // (core/motions/unread_keys.h) instead of being dropped in silence.
  mutable bool read = false;

  bool isDict() const { return kind == Kind::Dict; }
  bool isList() const { return kind == Kind::List; }
  bool isArray() const { return kind == Kind::Array; }
  // The child of a Dict named `key` (the last one, as a Python dict keeps the
  // last value of a repeated key), or nullptr (also for a List or a leaf).
  // Marks the child it returns as read.
  const DataNode* get(std::string_view key) const;
  // get(key) when it is an Array leaf, else nullptr.
  const Array* leaf(std::string_view key) const;
};

// The top-level Array leaves of a Dict node, by key (what the flat readers
// of model and motion files use); inner dicts and lists are left out. A node
// that is not a Dict gives an empty dict.
ArrayDict arraysOf(const DataNode& dict);

// Wraps a flat dict of arrays as a Dict node (keys sorted, as ArrayDict keeps them).
DataNode nodeOf(ArrayDict arrays);

// Charges `bytes` of a Dict's or List's own memory (children, keys) to the
// memory budget, held by node->array.charge; readers call it before they
// allocate them. Error: "<context>: the tree's nodes would need ...".
Status chargeNode(DataNode* node, uint64_t bytes, const std::string& context);

// A List of numeric Array leaves of one shape S -> one Array of shape (n, S...)
// (e.g. 4D-Humans' per-person lists of (1,3,3) global_orient), dtype of the
// first leaf, charged before it is allocated. An empty List gives shape (0).
// Errors name `context`: "x.pkl: element 2 is None, expected a numeric array",
// "x.pkl: element 1 has shape (23,3,3); element 0 has (1,3,3)".
Result<Array> stackList(const DataNode& list, const std::string& context);

// "dict with keys 'pose', 'trans', 'betas'", "list of 12", "array (T,72)",
// "None": what a node is, for errors and refusals. Keys and text from the
// file pass through printable() (core/io/printable.h) at the caller.
std::string describeNode(const DataNode& node, size_t max_keys = 12);

}  // namespace smpl
