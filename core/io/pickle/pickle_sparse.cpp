// scipy.sparse matrices from their pickled __dict__ (data, indices, indptr,
// _shape; coo: row/col or coords) -> dense Arrays. Every index is validated
// before it is used, and the dense size is charged before it is allocated.
#include <cmath>

#include "core/io/pickle/pickle_internal.h"

namespace smpl {
namespace pickle {

namespace {

struct SparseParts {
  const Array* data = nullptr;
  const Array* indices = nullptr;  // csc/csr; coo: rows
  const Array* indptr = nullptr;   // csc/csr; coo: cols
  int64_t rows = 0, cols = 0;
};

const Array* arrayEntry(const Heap& heap, Ref state, const char* key) {
  Ref r;
  if (!dictGet(heap, state, key, &r)) return nullptr;
  const PyObj& o = heap.at(r);
  if (o.kind != Kind::NdArray || !o.array || o.array->isString()) return nullptr;
  return o.array.get();
}

bool shapeEntry(const Heap& heap, Ref state, int64_t* rows, int64_t* cols) {
  Ref r;
  if (!dictGet(heap, state, "_shape", &r) && !dictGet(heap, state, "shape", &r)) return false;
  const PyObj& t = heap.at(r);
  if (t.kind != Kind::Tuple || t.items.size() != 2) return false;
  const PyObj& m = heap.at(t.items[0]);
  const PyObj& n = heap.at(t.items[1]);
  if (m.kind != Kind::Int || n.kind != Kind::Int || m.i < 0 || n.i < 0) return false;
  *rows = m.i;
  *cols = n.i;
  return true;
}

std::string numberText(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<int64_t>(v));
  return std::to_string(v);
}

// A stored index: integral and in [0, limit).
bool validIndex(double v, int64_t limit) {
  return v >= 0 && v < static_cast<double>(limit) && v == std::floor(v);
}

Result<SparseParts> sparseParts(Heap& heap, Ref state, GlobalId format, const std::string& name) {
  SparseParts p;
  p.data = arrayEntry(heap, state, "data");
  if (format == GlobalId::Coo) {
    p.indices = arrayEntry(heap, state, "row");
    p.indptr = arrayEntry(heap, state, "col");
    Ref coords;
    if (!p.indices && dictGet(heap, state, "coords", &coords) &&
        heap.at(coords).kind == Kind::Tuple && heap.at(coords).items.size() == 2) {
      const PyObj& r = heap.at(heap.at(coords).items[0]);
      const PyObj& c = heap.at(heap.at(coords).items[1]);
      if (r.kind == Kind::NdArray && c.kind == Kind::NdArray) {
        p.indices = r.array.get();
        p.indptr = c.array.get();
      }
    }
  } else {
    p.indices = arrayEntry(heap, state, "indices");
    p.indptr = arrayEntry(heap, state, "indptr");
  }
  if (!p.data || !p.indices || !p.indptr || !shapeEntry(heap, state, &p.rows, &p.cols)) {
    return heap.fail(name + " state lacks data/indices/indptr/shape arrays");
  }
  if (p.data->isString() || p.indices->isString() || p.indptr->isString()) {
    return heap.fail(name + " holds string arrays");
  }
  if (p.data->data.size() != p.indices->data.size()) {
    return heap.fail(name + " has " + std::to_string(p.data->data.size()) + " values but " +
                     std::to_string(p.indices->data.size()) + " indices");
  }
  return p;
}

// csc: indptr over columns, indices are rows; csr: the transpose.
Status fillCompressed(Heap& heap, const SparseParts& p, bool csc, const std::string& name,
                      Array* out) {
  int64_t major = csc ? p.cols : p.rows, minor = csc ? p.rows : p.cols;
  const std::vector<double>& ptr = p.indptr->data;
  const std::vector<double>& idx = p.indices->data;
  if (static_cast<int64_t>(ptr.size()) != major + 1) {
    return heap.fail(name + " indptr has " + std::to_string(ptr.size()) + " entries, expected " +
                     std::to_string(major + 1));
  }
  if (ptr[0] != 0) return heap.fail(name + " indptr does not start at 0");
  for (int64_t j = 0; j < major; ++j) {
    if (!(ptr[j + 1] >= ptr[j]) || ptr[j + 1] != std::floor(ptr[j + 1])) {
      return heap.fail(name + " indptr is not monotone at " + std::to_string(j + 1));
    }
  }
  if (ptr[major] > static_cast<double>(idx.size())) {
    return heap.fail(name + " indptr ends at " + std::to_string(static_cast<int64_t>(ptr[major])) +
                     " but has " + std::to_string(idx.size()) + " indices");
  }
  for (int64_t j = 0; j < major; ++j) {
    for (int64_t k = static_cast<int64_t>(ptr[j]); k < static_cast<int64_t>(ptr[j + 1]); ++k) {
      if (!validIndex(idx[k], minor)) {
        return heap.fail(name + " index " + numberText(idx[k]) + " is out of range for dimension " +
                         std::to_string(minor));
      }
      int64_t i = static_cast<int64_t>(idx[k]);
      int64_t at = csc ? i * p.cols + j : j * p.cols + i;
      out->data[at] += p.data->data[k];  // duplicates sum, as scipy's toarray() does
    }
  }
  return Status::success();
}

Status fillCoo(Heap& heap, const SparseParts& p, const std::string& name, Array* out) {
  const std::vector<double>& rows = p.indices->data;
  const std::vector<double>& cols = p.indptr->data;
  if (cols.size() != rows.size()) return heap.fail(name + " row and col lengths differ");
  for (size_t k = 0; k < rows.size(); ++k) {
    if (!validIndex(rows[k], p.rows) || !validIndex(cols[k], p.cols)) {
      return heap.fail(name + " entry " + std::to_string(k) + " is out of range");
    }
    out->data[static_cast<int64_t>(rows[k]) * p.cols + static_cast<int64_t>(cols[k])] +=
        p.data->data[k];
  }
  return Status::success();
}

}  // namespace

Result<bool> sparseToDense(Heap& heap, Ref r, Array* out) {
  const PyObj& obj = heap.at(r);
  const std::string name = obj.text;
  GlobalId format = obj.global;
  Result<SparseParts> parts = sparseParts(heap, obj.state, format, name);
  if (!parts) return parts.error();
  const SparseParts& p = *parts;
  if (p.cols != 0 && p.rows > (int64_t(1) << 50) / p.cols) {
    return heap.fail(name + " shape (" + std::to_string(p.rows) + "," + std::to_string(p.cols) +
                     ") is too large");
  }
  PK_TRY(heap.charge(static_cast<uint64_t>(p.rows * p.cols) * sizeof(double), "dense matrix"));
  Array a;
  a.shape = {p.rows, p.cols};
  a.dtype = p.data->dtype;
  a.data.assign(static_cast<size_t>(p.rows * p.cols), 0.0);
  Status filled = format == GlobalId::Coo
                      ? fillCoo(heap, p, name, &a)
                      : fillCompressed(heap, p, format == GlobalId::Csc, name, &a);
  if (!filled) return filled.error();
  *out = std::move(a);
  return true;
}

}  // namespace pickle
}  // namespace smpl
