// A loaded n-dimensional array, independent of the container it came from
// (.npy, .npz, pickle). Numbers of every dtype are widened to double and stored
// in C (row-major) order, so downstream code never sees byte order, Fortran
// order or integer widths. Precision: integers beyond 2^53 are not exact, which
// no model array needs (the largest is kintree_table's 2^32-1 root marker).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/memory_budget.h"

namespace smpl {

struct Array {
  std::vector<int64_t> shape;        // empty for a 0-d array
  std::vector<double> data;          // numeric/bool values, C order; empty for strings
  std::vector<std::string> strings;  // string arrays ('U'/'S' dtypes), C order
  std::string dtype;                 // numpy descr as read, e.g. "<f8", "|b1", "<U6", "|O"
  // Object arrays ('|O', decoded by the data-only unpickler): elements that are
  // numbers go to `data`, strings to `strings`; a 0-d array holding a dict of
  // name -> number (e.g. SMPL-X's joint-name -> index map, AMASS's marker ->
  // vertex id) has keys[i] naming data[i], shape (n,).
  std::vector<std::string> keys;
  MemoryCharge charge;  // `data`/`strings` bytes held against the memory budget
  bool isObject() const { return dtype.size() >= 2 && dtype[1] == 'O'; }
  bool isString() const {
    return !isObject() &&
           (!strings.empty() || (dtype.size() >= 2 && (dtype[1] == 'U' || dtype[1] == 'S')));
  }
  int64_t size() const {
    int64_t n = 1;
    for (int64_t d : shape) n *= d;
    return n;
  }
};

// Name -> array, as in an .npz archive or the top-level dict of a model pickle.
using ArrayDict = std::map<std::string, Array>;

// "(6890,3,10)" — the way numpy prints shapes, used in every shape error.
std::string shapeString(const std::vector<int64_t>& shape);

}  // namespace smpl
