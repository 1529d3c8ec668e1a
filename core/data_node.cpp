#include "core/data_node.h"

namespace smpl {

const DataNode* DataNode::get(std::string_view key) const {
  if (kind != Kind::Dict) return nullptr;
  for (size_t i = keys.size(); i-- > 0;)
    if (keys[i] == key) {
      children[i].read = true;
      return &children[i];
    }
  return nullptr;
}

const Array* DataNode::leaf(std::string_view key) const {
  const DataNode* child = get(key);
  return child && child->kind == Kind::Array ? &child->array : nullptr;
}

ArrayDict arraysOf(const DataNode& dict) {
  ArrayDict arrays;
  if (dict.kind != DataNode::Kind::Dict) return arrays;
  for (size_t i = 0; i < dict.keys.size(); ++i) {
    if (dict.children[i].kind == DataNode::Kind::Array)
      arrays[dict.keys[i]] = dict.children[i].array;
    else
      arrays.erase(dict.keys[i]);  // a later non-array value replaces an earlier one
  }
  return arrays;
}

DataNode nodeOf(ArrayDict arrays) {
  DataNode node;
  node.kind = DataNode::Kind::Dict;
  for (auto& [key, array] : arrays) {
    DataNode leaf;
    leaf.kind = DataNode::Kind::Array;
    leaf.array = std::move(array);
    node.keys.push_back(key);
    node.children.push_back(std::move(leaf));
  }
  return node;
}

Status chargeNode(DataNode* node, uint64_t bytes, const std::string& context) {
  return node->array.charge.add(bytes, context, "the tree's nodes");
}

Result<Array> stackList(const DataNode& list, const std::string& context) {
  if (list.kind != DataNode::Kind::List)
    return makeError(context + ": " + describeNode(list) + ", expected a list of arrays");
  Array out;
  const std::vector<int64_t>* shape = nullptr;
  for (size_t i = 0; i < list.children.size(); ++i) {
    const DataNode& c = list.children[i];
    if (c.kind != DataNode::Kind::Array || c.array.isString() || !c.array.strings.empty())
      return makeError(context + ": element " + std::to_string(i) + " is " + describeNode(c) +
                       ", expected a numeric array");
    if (shape && c.array.shape != *shape)
      return makeError(context + ": element " + std::to_string(i) + " has shape " +
                       shapeString(c.array.shape) + "; element 0 has " + shapeString(*shape));
    shape = &c.array.shape;
  }
  out.shape = {static_cast<int64_t>(list.children.size())};
  if (!shape) {
    out.dtype = "<f8";
    return out;
  }
  out.shape.insert(out.shape.end(), shape->begin(), shape->end());
  out.dtype = list.children[0].array.dtype;
  const size_t each = list.children[0].array.data.size();
  if (Status st = out.charge.add(list.children.size() * each * sizeof(double), context,
                                 "stacking " + std::to_string(list.children.size()) + " arrays");
      !st)
    return st.error();
  out.data.reserve(list.children.size() * each);
  for (const DataNode& c : list.children)
    out.data.insert(out.data.end(), c.array.data.begin(), c.array.data.end());
  return out;
}

std::string describeNode(const DataNode& node, size_t max_keys) {
  switch (node.kind) {
    case DataNode::Kind::None:
      return "None";
    case DataNode::Kind::Array:
      return node.array.isString() ? "text" : "array " + shapeString(node.array.shape);
    case DataNode::Kind::List:
      return "list of " + std::to_string(node.children.size());
    case DataNode::Kind::Dict:
      break;
  }
  std::string text = "dict with keys ";
  for (size_t i = 0; i < node.keys.size() && i < max_keys; ++i)
    text += (i ? ", '" : "'") + node.keys[i] + "'";
  if (node.keys.size() > max_keys) text += ", ... (" + std::to_string(node.keys.size()) + " keys)";
  if (node.keys.empty()) text = "empty dict";
  return text;
}

}  // namespace smpl
