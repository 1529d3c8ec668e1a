// readNpzTree: one leaf or subtree per member asked for.
#include "core/io/tree/npz_tree.h"

#include <set>

#include "core/io/pickle/pickle_tree.h"
#include "core/io/printable.h"

namespace smpl {
namespace {

Result<DataNode> member(const NpzArchive& npz, const std::string& key) {
  Result<bool> object = npz.isObjectArray(key);
  if (!object) return object.error();
  if (*object) {
    Result<ZipBytes> bytes = npz.memberView(key);
    if (!bytes) return bytes.error();
    Result<DataNode> tree = parseNpyTree(bytes->data, bytes->size,
                                         npz.context() + "/" + printable(npz.memberName(key)));
    if (Status st = npz.intact(); !st) return st.error();  // a stored member is read in place
    return tree;
  }
  Result<Array> array = npz.get(key);
  if (!array) return array.error();
  DataNode leaf;
  leaf.kind = DataNode::Kind::Array;
  leaf.array = std::move(*array);
  return leaf;
}

}  // namespace

Result<DataNode> readNpzTree(const NpzArchive& npz, const std::vector<std::string>& keys) {
  std::vector<std::string> wanted;
  std::set<std::string> seen;
  for (const std::string& key : keys.empty() ? npz.keys() : keys)
    if (npz.has(key) && seen.insert(key).second) wanted.push_back(key);
  DataNode tree;
  tree.kind = DataNode::Kind::Dict;
  uint64_t bytes = wanted.size() * (sizeof(DataNode) + sizeof(std::string));
  for (const std::string& key : wanted) bytes += key.size();
  if (Status st = chargeNode(&tree, bytes, npz.context()); !st) return st.error();
  for (const std::string& key : wanted) {
    Result<DataNode> child = member(npz, key);
    if (!child) return child.error();
    tree.keys.push_back(key);
    tree.children.push_back(std::move(*child));
  }
  return tree;
}

}  // namespace smpl
