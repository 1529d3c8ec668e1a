// PyMotion, _read_motion, the Motion class: see py_motion.h.
#include "python/bindings/py_motion.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/joint_names.h"
#include "exporter/animation.h"
#include "python/bindings/py_arrays.h"
#include "python/bindings/py_errors.h"
#include "python/bindings/py_settings.h"
#include "request/error_line.h"
#include "request/request_motions.h"

namespace pyb = pybind11;
using namespace pybind11::literals;

namespace smpl::py {
namespace {

Failure loadFailure(const std::string& source, const std::string& message) {
  return Failure{errorLine("loading", source, message), 2};
}

// The rotations of every frame in the model's joint order (the bake's
// mapping by joint name: a joint the motion lacks stays at rest), or in the
// motion's own order without a model.
void fillRotations(const BodyModel* model, PyMotion* p) {
  const Motion& m = *p->motion;
  std::vector<int> source_of_joint;
  if (model) {
    Result<MotionMapping> map = mapMotion(*model, m, p->source);
    if (!map) throw loadFailure(p->source, map.message());
    source_of_joint = map->source_of_joint;
    p->joint_names = model->joint_names;
  } else {
    const size_t k = m.frames.empty() ? 0 : m.frames[0].size();
    for (size_t j = 0; j < k; ++j) source_of_joint.push_back(static_cast<int>(j));
    p->joint_names = canonicalJointNames(m.layout);
    p->joint_names.resize(k);
  }
  const size_t k = source_of_joint.size();
  p->rotations.assign(m.frames.size() * k * 9, 0.0);
  for (size_t f = 0; f < m.frames.size(); ++f)
    for (size_t j = 0; j < k; ++j) {
      const int s = source_of_joint[j];
      const Eigen::Matrix3d r = s < 0 ? Eigen::Matrix3d::Identity() : m.frames[f][s];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) p->rotations[((f * k + j) * 3 + a) * 3 + b] = r(a, b);
    }
}

PyMotion readMotion(const pyb::object& value, const std::string& name,
                    const std::vector<std::string>& reading, const std::optional<PyModel>& model) {
  PyMotion p;
  p.reading = reading;
  p.model = model;
  const bool is_path = pyb::isinstance<pyb::str>(value);
  p.source = is_path ? value.cast<std::string>() : name;
  std::vector<std::string> args = {
      "--model", model ? model->path : "builtin", "--motion", p.source, "--out", "motion.glb"};
  args.insert(args.end(), reading.begin(), reading.end());
  const Settings s = settingsOf(args);
  if (s.request.track.kind == TrackChoice::Kind::All)
    throw usageFailure(
        "Error in arguments: read_motion reads one track: give track=ID or "
        "'longest' (the track ids are in the notes of a read)");
  std::optional<DataNode> tree;
  if (!is_path) tree = treeOf(value, name);
  pyb::gil_scoped_release release;
  Result<Motion> m = is_path ? decodeMotion(p.source, s.request)
                             : decodeMotionTree(std::move(*tree), p.source, s.request);
  if (!m) throw loadFailure(p.source, m.message());
  if (model)
    if (Status st = resolveMotionHands(*model->model, s.request, p.source, &*m); !st)
      throw loadFailure(p.source, st.message());
  p.motion = std::make_shared<const Motion>(std::move(*m));
  fillRotations(model ? model->model : nullptr, &p);
  return p;
}

pyb::object matrixOrNone(const Eigen::MatrixXd& m) {
  if (m.size() == 0) return pyb::none();
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = m;
  return newArray({m.rows(), m.cols()}, rows.data(), pyb::str("float64"));
}

}  // namespace

void registerMotion(pyb::module_& m) {
  pyb::class_<PyMotion>(m, "Motion", "One track of a motion, read once.")
      .def_property_readonly(
          "rotations",
          [](const PyMotion& p) {
            const ssize_t t = static_cast<ssize_t>(p.motion->frames.size());
            const ssize_t k = static_cast<ssize_t>(p.joint_names.size());
            return newArray({t, k, 3, 3}, p.rotations.data(), pyb::str("float64"));
          },
          "(T,K,3,3) float64 local joint rotations per frame, in the model's joint order "
          "(joints the motion lacks at rest), or the motion's own without a model.")
      .def_property_readonly(
          "trans",
          [](const PyMotion& p) {
            const std::vector<Eigen::Vector3d>& t = p.motion->translation;
            std::vector<double> flat;
            for (const Eigen::Vector3d& v : t) flat.insert(flat.end(), v.data(), v.data() + 3);
            return newArray({static_cast<ssize_t>(t.size()), 3}, flat.data(), pyb::str("float64"));
          },
          "(T,3) float64 root translations in metres, in the motion's world (zeros if absent).")
      .def_property_readonly(
          "betas",
          [](const PyMotion& p) -> pyb::object {
            const std::vector<double>& b = p.motion->betas;
            if (b.empty()) return pyb::none();
            return newArray({static_cast<ssize_t>(b.size())}, b.data(), pyb::str("float64"));
          },
          "(B,) float64 shape coefficients the motion carries, or None.")
      .def_property_readonly(
          "expression", [](const PyMotion& p) { return matrixOrNone(p.motion->expression); },
          "(T,E) float64 SMPL-X expression coefficients per frame, or None.")
      .def_property_readonly(
          "fps", [](const PyMotion& p) { return p.motion->fps; }, "Source frames per second.")
      .def_property_readonly(
          "layout", [](const PyMotion& p) { return p.motion->source_layout; },
          "The reader table's row that read it ('amass', 'gvhmr', ...; docs/motions.md).")
      .def_property_readonly(
          "notes", [](const PyMotion& p) { return p.motion->notes; },
          "What the reader assumed or averaged: the CLI's notes, one string each.")
      .def_property_readonly(
          "track", [](const PyMotion& p) { return p.motion->track; },
          "The person or track id in a multi-person file; '' if it has one.")
      .def_property_readonly(
          "gender", [](const PyMotion& p) { return p.motion->gender; }, "'' if absent.")
      .def_property_readonly(
          "joint_names", [](const PyMotion& p) { return p.joint_names; },
          "K names of the rotations' joints.")
      .def_property_readonly(
          "name", [](const PyMotion& p) { return p.motion->name; }, "The clip name (file stem).")
      .def_readonly("source", &PyMotion::source, "The file read, or the dict's name.")
      .def_readonly("reading_options", &PyMotion::reading,
                    "The reading options it was made with, as CLI arguments.")
      .def_property_readonly(
          "num_frames", [](const PyMotion& p) { return p.motion->frames.size(); }, "T.");
  m.def("_read_motion", &readMotion, "value"_a, "name"_a, "reading"_a, "model"_a);
}

}  // namespace smpl::py
