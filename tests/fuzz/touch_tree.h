// Shared by the tree fuzzers: visit every node and value of a DataNode so a
// bad shape/size pairing or a dangling view would show up under ASan.
#pragma once

#include <vector>

#include "core/data_node.h"

namespace smpl::fuzz {

inline void touch(const DataNode& root) {
  double sum = 0;
  std::vector<const DataNode*> stack{&root};  // iterative: trees are at most 32 deep anyway
  while (!stack.empty()) {
    const DataNode* n = stack.back();
    stack.pop_back();
    sum += static_cast<double>(n->array.size()) + static_cast<double>(n->keys.size());
    for (double v : n->array.data) sum += v;
    for (const auto& s : n->array.strings) sum += static_cast<double>(s.size());
    if (n->children.size() != n->keys.size() && n->kind == DataNode::Kind::Dict) __builtin_trap();
    for (const DataNode& c : n->children) stack.push_back(&c);
  }
  volatile double sink = sum;
  (void)sink;
}

}  // namespace smpl::fuzz
