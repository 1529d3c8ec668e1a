// NumberView, newArray, treeOf: see py_arrays.h.
#include "python/bindings/py_arrays.h"

#include <cmath>
#include <cstring>

#include "cli/exit_code.h"
#include "python/bindings/py_errors.h"

namespace pyb = pybind11;
using namespace pybind11::literals;

namespace smpl::py {
namespace {

Failure inputFailure(const std::string& message) { return Failure{message, kExitLoad}; }

pyb::module_ numpy() { return pyb::module_::import("numpy"); }

}  // namespace

NumberView::NumberView(const pyb::handle& object, const std::string& what) {
  pyb::object np = numpy();
  array_ = pyb::reinterpret_borrow<pyb::array>(np.attr("asarray")(object));
  const char kind = array_.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw usageFailure(what + ": expected numbers, got an array of dtype " +
                       std::string(pyb::str(array_.dtype())));
  const bool c_order = array_.flags() & pyb::array::c_style;
  const bool f32 = array_.dtype().is(pyb::dtype::of<float>());
  const bool f64 = array_.dtype().is(pyb::dtype::of<double>());
  if (!c_order || !(f32 || f64))  // one conversion; float32/float64 C arrays are read in place
    array_ = pyb::reinterpret_borrow<pyb::array>(
        np.attr("ascontiguousarray")(array_, "dtype"_a = np.attr("float64")));
  if (array_.dtype().is(pyb::dtype::of<float>()))
    f32_ = static_cast<const float*>(array_.data());
  else
    f64_ = static_cast<const double*>(array_.data());
  for (ssize_t d = 0; d < array_.ndim(); ++d)
    shape_.push_back(array_.shape(d)), size_ *= shape_.back();
  for (ssize_t i = 0; i < size_; ++i)
    if (!std::isfinite((*this)[i])) throw usageFailure(what + ": NaN or infinite values");
}

pyb::array newArray(const std::vector<ssize_t>& shape, const double* data,
                    const pyb::object& dtype) {
  ssize_t size = 1;
  for (ssize_t d : shape) size *= d;
  const std::string name = pyb::str(numpy().attr("dtype")(dtype));
  if (name == "float64") {
    pyb::array_t<double> out(shape);
    if (size) std::memcpy(out.mutable_data(), data, size * sizeof(double));
    return out;
  }
  if (name != "float32") throw usageFailure("dtype: expected float32 or float64, got " + name);
  pyb::array_t<float> out(shape);
  float* to = out.mutable_data();
  for (ssize_t i = 0; i < size; ++i) to[i] = static_cast<float>(data[i]);
  return out;
}

DataNode treeOf(const pyb::handle& value, const std::string& where, int depth) {
  if (depth > 64) throw inputFailure(where + ": nested deeper than 64 levels");
  DataNode node;
  if (value.is_none()) return node;
  if (pyb::isinstance<pyb::dict>(value)) {
    node.kind = DataNode::Kind::Dict;
    for (auto item : pyb::reinterpret_borrow<pyb::dict>(value)) {
      if (!pyb::isinstance<pyb::str>(item.first))
        throw inputFailure(where + ": keys must be strings, got " +
                           std::string(pyb::str(pyb::repr(item.first))));
      const std::string key = item.first.cast<std::string>();
      node.keys.push_back(key);
      node.children.push_back(treeOf(item.second, where + "['" + key + "']", depth + 1));
    }
    return node;
  }
  if (pyb::isinstance<pyb::list>(value) || pyb::isinstance<pyb::tuple>(value)) {
    // A list of numbers is an array (numpy reads it as one); else a List node.
    pyb::sequence items = pyb::reinterpret_borrow<pyb::sequence>(value);
    bool nested = false;
    for (auto item : items)
      nested = nested || pyb::isinstance<pyb::dict>(item) || item.is_none() ||
               pyb::isinstance<pyb::array>(item);
    if (nested || items.size() == 0) {
      node.kind = DataNode::Kind::List;
      for (size_t i = 0; i < items.size(); ++i)
        node.children.push_back(treeOf(items[i], where + "[" + std::to_string(i) + "]", depth + 1));
      return node;
    }
  }
  pyb::array a = pyb::reinterpret_borrow<pyb::array>(numpy().attr("asarray")(value));
  node.kind = DataNode::Kind::Array;
  node.array.dtype = pyb::str(a.dtype().attr("str"));
  for (ssize_t d = 0; d < a.ndim(); ++d) node.array.shape.push_back(a.shape(d));
  const char kind = a.dtype().kind();
  if (kind == 'U' || kind == 'S') {
    for (auto s : numpy().attr("ravel")(a)) {
      pyb::object text = pyb::reinterpret_borrow<pyb::object>(s);
      if (kind == 'S') text = text.attr("decode")("latin-1");
      node.array.strings.push_back(text.cast<std::string>());
    }
    return node;
  }
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw inputFailure(where + ": an array of dtype " + std::string(pyb::str(a.dtype())) +
                       " (give numbers, text, dicts or lists)");
  pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast> d(a);
  node.array.data.assign(d.data(), d.data() + d.size());
  return node;
}

}  // namespace smpl::py
