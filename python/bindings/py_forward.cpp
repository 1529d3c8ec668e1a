// forwardModel: see py_forward.h.
#include "python/bindings/py_forward.h"

#include <pybind11/numpy.h>

#include <map>
#include <memory>
#include <mutex>

#include "core/math/forward.h"
#include "core/math/forward_batch.h"
#include "core/parallel.h"
#include "python/bindings/py_arrays.h"
#include "python/bindings/py_errors.h"

namespace pyb = pybind11;

namespace smpl::py {
namespace {

std::string shapeText(const std::vector<ssize_t>& shape) {
  std::string s = "(";
  for (size_t i = 0; i < shape.size(); ++i) s += (i ? "," : "") + std::to_string(shape[i]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

// poses as T lists of K rotations: (T,K,3) / (T,3K) axis-angle or (T,K,3,3).
std::vector<Rotations> rotationsOf(const NumberView& p, int k) {
  const std::vector<ssize_t>& s = p.shape();
  const bool axis_angle =
      (s.size() == 3 && s[1] == k && s[2] == 3) || (s.size() == 2 && s[1] == 3 * k);
  const bool matrices = s.size() == 4 && s[1] == k && s[2] == 3 && s[3] == 3;
  if (!axis_angle && !matrices)
    throw usageFailure("poses: shape " + shapeText(s) + "; expected (T," + std::to_string(k) +
                       ",3) or (T," + std::to_string(3 * k) + ") axis-angle, or (T," +
                       std::to_string(k) + ",3,3) rotation matrices, in the model's " +
                       std::to_string(k) + " joints");
  std::vector<Rotations> frames(s[0], Rotations(k));
  const ssize_t per = axis_angle ? 3 : 9;
  for (ssize_t t = 0; t < s[0]; ++t)
    for (int j = 0; j < k; ++j) {
      const ssize_t at = (t * k + j) * per;
      if (axis_angle) {
        frames[t][j] = rodrigues(Eigen::Vector3d(p[at], p[at + 1], p[at + 2]));
      } else {
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) frames[t][j](r, c) = p[at + 3 * r + c];
      }
    }
  return frames;
}

// (C,) or (T,C) or (1,C) with C <= `most` as T rows (a missing value is None: zero columns).
Eigen::MatrixXd rowsOf(const pyb::object& value, ssize_t t, int most, const std::string& what,
                       const std::string& unit) {
  if (value.is_none()) return Eigen::MatrixXd::Zero(t, 0);
  NumberView v(value, what);
  const std::vector<ssize_t>& s = v.shape();
  const ssize_t rows = s.size() == 2 ? s[0] : 1, cols = s.empty() ? 1 : s.back();
  if (s.size() > 2 || (rows != t && rows != 1))
    throw usageFailure(what + ": shape " + shapeText(s) + "; expected (" + unit + ",) or (" +
                       std::to_string(t) + "," + unit + ")");
  if (cols > most)
    throw usageFailure(what + ": " + std::to_string(cols) + " values per frame; the model has " +
                       std::to_string(most));
  Eigen::MatrixXd out(t, cols);
  for (ssize_t r = 0; r < t; ++r)
    for (ssize_t c = 0; c < cols; ++c) out(r, c) = v[(rows == 1 ? 0 : r) * cols + c];
  return out;
}

bool sameRows(const Eigen::MatrixXd& m) {
  for (Eigen::Index r = 1; r < m.rows(); ++r)
    if (m.row(r) != m.row(0)) return false;
  return true;
}

// posedirs packed once per model for the batched pass (read by every call after).
const batch::PackedPosedirs& packedPosedirs(const BodyModel& model) {
  static std::mutex mutex;
  static std::map<const BodyModel*, std::unique_ptr<batch::PackedPosedirs>> packed;
  std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<batch::PackedPosedirs>& p = packed[&model];
  if (!p) p = std::make_unique<batch::PackedPosedirs>(packPosedirs(model));
  return *p;
}

// Posed joints of one frame: the translation of G_k (rest joints `j`, K x 3).
void chainJoints(const BodyModel& model, const Eigen::MatrixXd& j, const Rotations& r,
                 const Eigen::Vector3d& trans, double* out) {
  const int k = model.numJoints();
  std::vector<Eigen::Matrix3d> rot(k);
  std::vector<Eigen::Vector3d> pos(k);
  for (int i = 0; i < k; ++i) {
    const int p = model.parents[i];
    const Eigen::Vector3d rest = j.row(i).transpose();
    if (p < 0) {
      rot[i] = r[i], pos[i] = rest;
    } else {
      rot[i] = rot[p] * r[i];
      pos[i] = pos[p] + rot[p] * (rest - j.row(p).transpose());
    }
    for (int c = 0; c < 3; ++c) out[3 * i + c] = pos[i][c] + trans[c];
  }
}

struct Outputs {
  std::vector<double> vertices, joints;  // T x V x 3, T x K x 3
};

// One shape for every frame: the batched pass.
Status forwardShared(const BodyModel& model, const Eigen::MatrixXd& betas,
                     const Eigen::MatrixXd& expression, const std::vector<Rotations>& frames,
                     const Eigen::MatrixXd& trans, Outputs* out) {
  const ssize_t t = static_cast<ssize_t>(frames.size());
  const int v = model.numVertices(), k = model.numJoints();
  Result<ShapedBody> body = shapeBody(
      model, betas.rows() ? Eigen::VectorXd(betas.row(0).transpose()) : Eigen::VectorXd(),
      expression.rows() ? Eigen::VectorXd(expression.row(0).transpose()) : Eigen::VectorXd());
  if (!body) return body.error();
  BatchInput in;
  in.body = &*body;
  in.frames = &frames;
  in.threads = static_cast<int>(hardwareThreads());
  in.posedirs = &packedPosedirs(model);
  const Eigen::MatrixXd verts = forwardBatch(model, in);  // 3V x T
  runWorkers(in.threads, [&](int w, int workers) {
    for (ssize_t f = w; f < t; f += workers) {
      const Eigen::Vector3d tr = trans.row(f).transpose();
      double* to = out->vertices.data() + f * 3 * v;
      for (int i = 0; i < v; ++i)
        for (int c = 0; c < 3; ++c) to[3 * i + c] = verts(3 * i + c, f) + tr[c];
      chainJoints(model, body->joints, frames[f], tr, out->joints.data() + f * 3 * k);
    }
  });
  return Status();
}

// Betas or expression per frame: the double reference pass per frame.
Status forwardEach(const BodyModel& model, const Eigen::MatrixXd& betas,
                   const Eigen::MatrixXd& expression, const std::vector<Rotations>& frames,
                   const Eigen::MatrixXd& trans, Outputs* out) {
  const ssize_t t = static_cast<ssize_t>(frames.size());
  const int v = model.numVertices(), k = model.numJoints();
  std::vector<Status> status(t);
  runWorkers(static_cast<int>(hardwareThreads()), [&](int w, int workers) {
    for (ssize_t f = w; f < t; f += workers) {
      ForwardInput in;
      in.betas = betas.row(f).transpose();
      in.expression = expression.row(f).transpose();
      in.rotations = frames[f];
      in.translation = trans.row(f).transpose();
      Result<ForwardResult> r = forward(model, in);
      if (!r) {
        status[f] = r.error();
        continue;
      }
      for (int i = 0; i < v; ++i)
        for (int c = 0; c < 3; ++c) out->vertices[(f * v + i) * 3 + c] = r->vertices(i, c);
      for (int i = 0; i < k; ++i)
        for (int c = 0; c < 3; ++c) out->joints[(f * k + i) * 3 + c] = r->joints(i, c);
    }
  });
  for (const Status& st : status)
    if (!st) return st;
  return Status();
}

}  // namespace

pyb::tuple forwardModel(const PyModel& model, const pyb::object& betas, const pyb::object& poses,
                        const pyb::object& trans, const pyb::object& expression,
                        const pyb::object& dtype) {
  const BodyModel& m = *model.model;
  const int k = m.numJoints(), v = m.numVertices();
  NumberView pose_view(poses, "poses");
  if (pose_view.shape().empty()) throw usageFailure("poses: expected (T,K,3), got a number");
  const ssize_t t = pose_view.shape()[0];
  Eigen::MatrixXd b = rowsOf(betas, t, m.numBetas(), "betas", "B");
  Eigen::MatrixXd e = rowsOf(expression, t, m.numExpressions(), "expression", "E");
  if (!expression.is_none() && m.numExpressions() == 0)
    throw usageFailure("expression: the model " + m.name + " has no expression basis");
  Eigen::MatrixXd tr =
      trans.is_none() ? Eigen::MatrixXd::Zero(t, 3) : rowsOf(trans, t, 3, "trans", "3");
  if (tr.cols() != 3) throw usageFailure("trans: expected 3 values per frame (metres)");
  if (b.cols() == 0) b = Eigen::MatrixXd::Zero(t, 0);
  Outputs out;
  Status status;
  {
    pyb::gil_scoped_release release;
    const std::vector<Rotations> frames = rotationsOf(pose_view, k);
    out.vertices.resize(t * v * 3);
    out.joints.resize(t * k * 3);
    if (t > 0)
      status = sameRows(b) && sameRows(e) ? forwardShared(m, b, e, frames, tr, &out)
                                          : forwardEach(m, b, e, frames, tr, &out);
  }
  if (!status) throw usageFailure(status.message());
  return pyb::make_tuple(newArray({t, v, 3}, out.vertices.data(), dtype),
                         newArray({t, k, 3}, out.joints.data(), dtype));
}

}  // namespace smpl::py
