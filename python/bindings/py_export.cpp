// _export: see py_export.h.
#include "python/bindings/py_export.h"

#include <pybind11/stl.h>

#include "core/math/float_environment.h"
#include "core/math/simd_target.h"
#include "python/bindings/py_errors.h"
#include "python/bindings/py_model.h"
#include "python/bindings/py_motion.h"
#include "python/bindings/py_settings.h"
#include "request/run_request.h"

namespace pyb = pybind11;
using namespace pybind11::literals;

namespace smpl::py {
namespace {

// The notes the CLI prints for an export, in its order (cli/summary.cpp printNotes).
std::vector<std::string> notesOf(const ExportReport& r) {
  std::vector<std::string> notes;
  if (!r.model_note.empty()) notes.push_back(r.model_note);
  if (!r.betas_note.empty()) notes.push_back(r.betas_note);
  notes.insert(notes.end(), r.notes.begin(), r.notes.end());
  return notes;
}

pyb::tuple exportRequest(const std::vector<std::string>& args, const PyModel& model,
                         const std::optional<PyMotion>& motion, bool memory) {
  Settings s = settingsOf(args);
  ExportRequest& r = s.request;
  // The environment's SMPL_EXPORT_SIMD, read per export as the CLI reads it per run.
  if (Status st = useSimdTargetFromEnvironment(); !st)
    throw usageFailure("Error in environment: " + st.message());
  if (r.track.kind == TrackChoice::Kind::All)
    throw usageFailure(
        "Error in arguments: track='all' writes one file per track: read each "
        "track (read_motion(..., track=ID)) and export it");
  if (r.model != model.path) throw usageFailure("Error in arguments: the model is the Model's");
  std::vector<Motion> motions;
  if (motion) motions.push_back(*motion->motion);
  if (memory) {
    Result<ExportedBytes> out = [&] {
      pyb::gil_scoped_release release;
      DefaultFloatEnvironment rounding;  // the CLI's rounding, whatever the host process set
      return exportToMemory(r, std::move(motions), model.source.get());
    }();
    if (!out) throw failureOf(out.error());
    return pyb::make_tuple(pyb::bytes(out->bytes), notesOf(out->report));
  }
  Result<ExportReport> report = [&] {
    pyb::gil_scoped_release release;
    DefaultFloatEnvironment rounding;
    return exportDecoded(r, std::move(motions), model.source.get());
  }();
  if (!report) throw failureOf(report.error());
  return pyb::make_tuple(r.out, notesOf(*report));
}

}  // namespace

void registerExport(pyb::module_& m) {
  m.def("_export", &exportRequest, "args"_a, "model"_a, "motion"_a, "memory"_a);
}

}  // namespace smpl::py
