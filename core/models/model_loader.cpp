#include "core/models/model_loader.h"

#include <algorithm>
#include <cmath>

#include "core/huge_pages.h"
#include "core/io/file_io.h"
#include "core/io/mapped_file.h"
#include "core/io/pickle/pickle.h"
#include "core/io/tree/data_tree.h"
#include "core/joint_names.h"
#include "core/models/npz_arrays.h"
#include "core/models/other_models.h"
#include "core/models/validate_inputs.h"
#include "core/parallel.h"

namespace smpl {
namespace {

// Shapes in errors use the numbers we expect where known, -1 where free.
std::string expectedString(const std::vector<int64_t>& shape) {
  std::string s = "(";
  for (size_t i = 0; i < shape.size(); ++i)
    s += (i ? "," : "") + (shape[i] < 0 ? std::string("*") : std::to_string(shape[i]));
  return s + (shape.size() == 1 ? ",)" : ")");
}

bool shapeMatches(const Array& a, const std::vector<int64_t>& expected) {
  if (a.shape.size() != expected.size()) return false;
  for (size_t i = 0; i < expected.size(); ++i)
    if (expected[i] >= 0 && a.shape[i] != expected[i]) return false;
  return true;
}

struct Arrays {
  const ArrayDict& dict;
  std::string context;

  const Array* find(const std::string& key) const {
    auto it = dict.find(key);
    return it == dict.end() ? nullptr : &it->second;
  }
  Result<const Array*> require(const std::string& key) const {
    const Array* a = find(key);
    if (!a) return makeError(context + ": missing key '" + key + "'");
    if (a->isObject())
      return makeError(context + ": '" + key + "' is an object array ('|O'); expected numbers");
    if (a->isString()) return makeError(context + ": '" + key + "' holds text, expected numbers");
    return a;
  }
  Status checkShape(const std::string& key, const Array& a,
                    const std::vector<int64_t>& expected) const {
    if (!shapeMatches(a, expected))
      return makeError(context + ": '" + key + "' has shape " + shapeString(a.shape) +
                       "; expected " + expectedString(expected));
    return checkFloatRange(a, context, key);
  }
  // Fetch key and check its shape in one step.
  Result<const Array*> get(const std::string& key, const std::vector<int64_t>& expected) const {
    Result<const Array*> a = require(key);
    if (!a) return a;
    if (Status s = checkShape(key, **a, expected); !s) return s.error();
    return a;
  }
};

// (rows*cols) C-order values -> matrix. posedirs (3N x 207): a strip of 8
// source rows (13 KB) stays in L1 while each destination column gets its 8
// contiguous values, so both sides stream; huge pages for the big ones. The
// strips are split over the cores (a copy: any split gives the same matrix);
// the model's load is otherwise serial.
Eigen::MatrixXd toMatrix(const Array& a, Eigen::Index rows, Eigen::Index cols) {
  constexpr Eigen::Index kStrip = 8;
  Eigen::MatrixXd m(rows, cols);
  adviseHugePages(m.data(), static_cast<size_t>(m.size()) * sizeof(double));
  const double* src = a.data.data();
  double* dst = m.data();
  const Eigen::Index strips = (rows + kStrip - 1) / kStrip;
  const int workers = int(std::min<Eigen::Index>(hardwareThreads(), m.size() / (1 << 20) + 1));
  runWorkers(workers, [&](int w, int count) {
    for (Eigen::Index s = strips * w / count; s < strips * (w + 1) / count; ++s) {
      const Eigen::Index r0 = s * kStrip, h = std::min(kStrip, rows - r0);
      for (Eigen::Index c = 0; c < cols; ++c)
        for (Eigen::Index r = r0; r < r0 + h; ++r) dst[c * rows + r] = src[r * cols + c];
    }
  });
  return m;
}

Result<std::vector<int>> parentsFromKintree(const Array& kintree, const std::string& context) {
  const int64_t k = kintree.shape[1];
  std::vector<int> parents(k);
  for (int64_t j = 0; j < k; ++j) {
    double p = kintree.data[j];
    if (j == 0) {
      parents[0] = -1;  // stored as 2^32-1 (uint32 -1) or -1
      continue;
    }
    if (p < 0 || p >= j || p != std::floor(p))
      return makeError(context + ": 'kintree_table' gives joint " + std::to_string(j) +
                       " the parent " + std::to_string(static_cast<long long>(p)) +
                       "; parents must precede their children");
    parents[j] = static_cast<int>(p);
  }
  return parents;
}

// SMPL-X packs shape then expression columns in one shapedirs (docs/file-contract.md).
void splitShapedirs(ModelKind kind, const Eigen::MatrixXd& all, BodyModel* m) {
  Eigen::Index shape_cols = all.cols();
  if (kind == ModelKind::SmplX) {
    if (all.cols() > 300)
      shape_cols = 300;  // v1.1: 300 shape + 100 expression
    else if (all.cols() == 20)
      shape_cols = 10;  // v1.0: 10 shape + 10 expression
  }
  m->shapedirs = all.leftCols(shape_cols);
  m->exprdirs = all.rightCols(all.cols() - shape_cols);
}

Status loadHands(const Arrays& in, BodyModel* m) {
  struct Key {
    const char* components;
    const char* mean;
    Eigen::MatrixXd* c;
    Eigen::VectorXd* mu;
  };
  const Key keys[] = {
      {"hands_componentsl", "hands_meanl", &m->hands_components_l, &m->hands_mean_l},
      {"hands_componentsr", "hands_meanr", &m->hands_components_r, &m->hands_mean_r},
      {"hands_components", "hands_mean", &m->hands_components_l, &m->hands_mean_l}};
  for (const Key& key : keys) {
    const Array* c = in.find(key.components);
    if (!c) continue;
    if (Status s = in.checkShape(key.components, *c, {-1, 45}); !s) return s;
    Result<const Array*> mu = in.get(key.mean, {45});
    if (!mu) return mu.error();
    *key.c = toMatrix(*c, c->shape[0], 45);
    *key.mu = Eigen::Map<const Eigen::VectorXd>((*mu)->data.data(), 45);
  }
  return Status();
}

// `vt` (U,2) + `ft` (F,3) as the SMPL-X release ships them: both or neither.
Status loadTexcoords(const Arrays& in, BodyModel* m) {
  const Array* vt = in.find("vt");
  const Array* ft = in.find("ft");
  if (!vt && !ft) return Status();
  if (!vt || !ft)
    return makeError(in.context + ": has '" + std::string(vt ? "vt" : "ft") + "' but not '" +
                     (vt ? "ft" : "vt") + "'; UVs need both");
  Result<const Array*> uv = in.get("vt", {-1, 2});
  if (!uv) return uv.error();
  Result<const Array*> f = in.get("ft", {m->faces.rows(), 3});
  if (!f) return f.error();
  const int64_t u = (*uv)->shape[0];
  if (Status st = checkTexCoords((*uv)->data.data(), (*uv)->data.size(), in.context, "'vt'"); !st)
    return st;
  for (double v : (*f)->data)
    if (v < 0 || v >= u || v != std::floor(v))
      return makeError(in.context + ": 'ft' has index " +
                       std::to_string(static_cast<long long>(v)) + "; expected integers in [0," +
                       std::to_string(u) + ") ('vt' has " + std::to_string(u) + " rows)");
  m->texcoords = toMatrix(**uv, u, 2);
  m->texcoord_faces = toMatrix(**f, (*f)->shape[0], 3).cast<int>();
  return Status();
}

Result<BodyModel> buildCore(const Arrays& in) {
  Result<const Array*> vt = in.get("v_template", {-1, 3});
  if (!vt) return vt.error();
  const int64_t n = (*vt)->shape[0];
  Result<const Array*> w = in.get("weights", {n, -1});
  if (!w) return w.error();
  const int64_t k = (*w)->shape[1];
  BodyModel m;
  if (!modelKindFromJointCount(static_cast<int>(k), &m.kind))
    return makeError(in.context + ": 'weights' has " + std::to_string(k) +
                     " joints; expected 24 (SMPL), 52 (SMPL-H), 55 (SMPL-X) or 16 (MANO)");
  Result<const Array*> kt = in.get("kintree_table", {2, k});
  Result<const Array*> sd = in.get("shapedirs", {n, 3, -1});
  Result<const Array*> pd = in.get("posedirs", {n, 3, 9 * (k - 1)});
  Result<const Array*> jr = in.get("J_regressor", {k, n});
  Result<const Array*> f = in.get("f", {-1, 3});
  for (const auto* r : {&kt, &sd, &pd, &jr, &f})
    if (!*r) return r->error();
  Result<std::vector<int>> parents = parentsFromKintree(**kt, in.context);
  if (!parents) return parents.error();
  m.parents = std::move(*parents);
  m.joint_names = canonicalJointNames(m.kind);
  m.v_template = toMatrix(**vt, n, 3);
  m.weights = toMatrix(**w, n, k);
  splitShapedirs(m.kind, toMatrix(**sd, 3 * n, (*sd)->shape[2]), &m);
  m.posedirs = toMatrix(**pd, 3 * n, 9 * (k - 1));
  m.j_regressor = toMatrix(**jr, k, n).sparseView();
  if (Status s = checkIndices(**f, in.context, "f"); !s) return s.error();
  m.faces = toMatrix(**f, (*f)->shape[0], 3).cast<int>();
  if (Status s = loadHands(in, &m); !s) return s.error();
  if (Status s = loadTexcoords(in, &m); !s) return s.error();
  return m;
}

}  // namespace

Result<BodyModel> buildModel(const ArrayDict& arrays, const std::string& context) {
  Result<BodyModel> m = buildCore(Arrays{arrays, context});
  if (!m) return m;
  m->name = baseName(context);
  if (Status s = validateModel(*m, context); !s) return s.error();
  return m;
}

Status validateModel(const BodyModel& m, const std::string& context) {
  const int n = m.numVertices(), k = m.numJoints();
  if (n == 0) return makeError(context + ": the model has no vertices");
  if (static_cast<int>(m.joint_names.size()) != k)
    return makeError(context + ": joint names do not match the joint count");
  if (m.parents.empty() || m.parents[0] != -1)
    return makeError(context + ": joint 0 must be the root");
  for (int j = 1; j < k; ++j)
    if (m.parents[j] < 0 || m.parents[j] >= j)
      return makeError(context + ": joint " + std::to_string(j) + " has an invalid parent");
  if (m.weights.rows() != n || m.weights.cols() != k || m.j_regressor.rows() != k ||
      m.j_regressor.cols() != n || m.shapedirs.rows() != 3 * n || m.exprdirs.rows() != 3 * n ||
      m.posedirs.rows() != 3 * n || m.posedirs.cols() != 9 * (k - 1) || m.faces.cols() != 3)
    return makeError(context + ": model arrays disagree in size");
  if (m.faces.size() > 0 && (m.faces.minCoeff() < 0 || m.faces.maxCoeff() >= n))
    return makeError(context + ": 'f' indexes vertex " + std::to_string(m.faces.maxCoeff()) +
                     " of " + std::to_string(n));
  for (int i = 0; i < n; ++i) {
    const double sum = m.weights.row(i).sum();
    if (m.weights.row(i).minCoeff() < -1e-6 || std::abs(sum - 1.0) > 1e-3)
      return makeError(context + ": 'weights' row " + std::to_string(i) + " sums to " +
                       std::to_string(sum) + "; skin weights must be non-negative and sum to 1");
  }
  return Status();
}

// The keys a model loader reads; every other member of an .npz is never decoded.
const std::vector<std::string>& modelKeys() {
  static const std::vector<std::string> keys = {"v_template",
                                                "weights",
                                                "kintree_table",
                                                "shapedirs",
                                                "posedirs",
                                                "J_regressor",
                                                "f",
                                                "hands_componentsl",
                                                "hands_meanl",
                                                "hands_componentsr",
                                                "hands_meanr",
                                                "hands_components",
                                                "hands_mean",
                                                "vt",
                                                "ft"};
  return keys;
}

namespace {

// An .npy given as a model: SUPR's released models are np.save'd dicts, so
// one with SUPR's arrays is named; any other keeps `refused` (the format error).
Error npyModelError(const std::string& path, const Error& refused) {
  Result<FileFormat> sniffed = checkInputFile(path, kNpyInput);
  if (!sniffed || *sniffed != FileFormat::Npy) return refused;
  Result<DataNode> tree = readDataTree(path);
  if (!tree || !tree->isDict()) return refused;
  ArrayDict arrays;
  for (size_t i = 0; i < tree->keys.size(); ++i)
    if (tree->children[i].kind == DataNode::Kind::Array)
      arrays[tree->keys[i]] = tree->children[i].array;
  if (Status s = refuseOtherModel(tree->keys, arrays, path); !s) return s.error();
  return refused;
}

}  // namespace

Result<BodyModel> loadModel(const std::string& path) {
  // From the first bytes and the size, before anything is read whole: a
  // model is an .npz or a pickle in a regular file (no pipes: both readers
  // map it), so /dev/stdin or a 3 GB sparse file is refused at once.
  Result<FileFormat> format = checkInputFile(path, kModelInput);
  if (!format) return npyModelError(path, format.error());
  Result<ArrayDict> arrays = makeError(path + ": not a model file");
  std::vector<std::string> keys;
  if (*format == FileFormat::Zip) {
    arrays = readNpzArrays(path, modelKeys(), path);  // lazy: only the model's keys are read
    if (Result<std::vector<std::string>> names = containerKeys(path)) keys = *names;
  } else {
    Result<MappedFile> bytes = MappedFile::open(path);  // no copy of the file
    if (!bytes) return bytes.error();
    arrays = parsePickle(bytes->data(), bytes->size(), path);
    if (Status st = bytes->intact(); !st) return st.error();  // the file shrank while read
  }
  if (!arrays) return arrays.error();
  if (keys.empty())
    for (const auto& [key, array] : *arrays) keys.push_back(key);
  if (Status s = refuseOtherModel(keys, *arrays, path); !s) return s.error();
  return buildModel(*arrays, path);
}

}  // namespace smpl
