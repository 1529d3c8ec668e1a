// Helpers shared by the unit tests: fixture bytes and hand-made arrays.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "core/array.h"
#include "core/data_node.h"

namespace smpl::test {

// The whole file as bytes; a missing fixture is a test failure (not a skip).
inline std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "missing fixture " << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A float64 Array of `shape` holding `data` (C order).
inline Array numbers(std::vector<int64_t> shape, std::vector<double> data) {
  Array a;
  a.shape = std::move(shape);
  a.data = std::move(data);
  a.dtype = "<f8";
  return a;
}

// `a` as a DataNode leaf (the root of an .npy, or a dict's value).
inline DataNode leaf(Array a) {
  DataNode n;
  n.kind = DataNode::Kind::Array;
  n.array = std::move(a);
  return n;
}

}  // namespace smpl::test
