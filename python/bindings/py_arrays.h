// numpy arrays in and out of the library's types. Inputs that are already
// float32 or float64 and C-contiguous are read in place (no copy); others
// are converted once by numpy. Outputs are numpy arrays that own their
// memory. Torch tensors arrive as numpy arrays (the shim calls
// detach().cpu().numpy() / __array__), so nothing here links torch.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "core/data_node.h"

namespace smpl::py {

// A read-only view of a float32/float64 array as doubles, in C order: the
// array itself when it already is one of those, else a float64 copy.
// Errors (Failure, usage): not numeric, NaN or infinite values (`what` names
// the argument: "poses").
class NumberView {
 public:
  NumberView(const pybind11::handle& object, const std::string& what);
  const std::vector<ssize_t>& shape() const { return shape_; }
  ssize_t size() const { return size_; }
  double operator[](ssize_t i) const { return f32_ ? double(f32_[i]) : f64_[i]; }

 private:
  pybind11::array array_;  // keeps the memory alive
  std::vector<ssize_t> shape_;
  ssize_t size_ = 1;
  const float* f32_ = nullptr;
  const double* f64_ = nullptr;
};

// A new numpy array of `shape` from doubles in C order, as float32 or
// float64 (`dtype` "float32" / "float64").
pybind11::array newArray(const std::vector<ssize_t>& shape, const double* data,
                         const pybind11::object& dtype);

// A Python value as the tree the container readers build (core/data_node.h):
// dict -> Dict (str keys, insertion order), list/tuple -> List, None ->
// None, anything numpy reads (arrays, numbers, strings) -> an Array leaf with
// numpy's dtype descr ("<f4"), values widened to double, text as strings.
// Errors (Failure, input): a non-str key, an object array, nesting deeper
// than 64 (`where` names the key path: "motion['poses']").
DataNode treeOf(const pybind11::handle& value, const std::string& where, int depth = 0);

}  // namespace smpl::py
