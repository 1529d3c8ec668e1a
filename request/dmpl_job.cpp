#include "request/dmpl_job.h"

#include <cstdio>
#include <filesystem>

#include "core/models/dmpl.h"
#include "core/os/path.h"
#include "exporter/dmpl_targets.h"
#include "request/check_request.h"
#include "request/error_line.h"

namespace smpl {
namespace {

Error failWith(const std::string& path, const std::string& message) {
  return makeError(errorLine("loading", path, message), ErrorKind::Load);
}

// The basis file: --dmpl FILE, or from --dmpl DIR by the first motion's gender.
Result<std::string> dmplPath(const ExportRequest& s, const std::vector<Motion>& motions,
                             ExportReport* report) {
  std::error_code ec;
  if (!std::filesystem::is_directory(os::fsPath(s.dmpl), ec)) return s.dmpl;
  std::string note;
  Result<std::string> found =
      findDmplBasis(s.dmpl, motions.empty() ? "" : motions[0].gender, &note);
  if (found && !note.empty()) report->notes.push_back(note);
  return found;
}

void noteIgnoredDmpls(const std::vector<Motion>& motions, ExportReport* report) {
  for (const Motion& m : motions)
    if (m.dmpls.rows() > 0 && m.dmpls.cwiseAbs().maxCoeff() > 0)
      report->notes.push_back(
          m.name + ": the motion has DMPL soft-tissue coefficients 'dmpls' (" +
          std::to_string(m.dmpls.cols()) +
          " per frame), not baked: add --dmpl FILE|DIR "
          "(the DMPL basis, e.g. AMASS dmpls/<gender>/model.npz) to bake them as morph targets");
}

}  // namespace

Result<PreparedDmpl> prepareDmpl(const BodyModel& model, const ExportRequest& s,
                                 const std::vector<Motion>& motions, ExportReport* report) {
  PreparedDmpl out;
  if (s.dmpl.empty()) {
    noteIgnoredDmpls(motions, report);
    return out;
  }
  Result<std::string> path = dmplPath(s, motions, report);
  if (!path) return failWith(s.dmpl, path.message());
  Result<DmplBasis> basis = loadDmplBasis(*path, model.numVertices());
  if (!basis) return failWith(*path, basis.message());
  const int total = static_cast<int>(basis->directions.cols());
  if (Status st = checkDmplCount(s, total); !st) return failWith(*path, st.message());
  std::vector<const Eigen::MatrixXd*> coefficients;
  for (size_t i = 0; i < motions.size(); ++i) {
    if (Status st = checkDmplCoefficients(motions[i], s.motions[i], total, *path); !st)
      return failWith(s.motions[i], st.message());
    if (motions[i].dmpls.rows() > 0)
      coefficients.push_back(&motions[i].dmpls);
    else
      report->notes.push_back(motions[i].name +
                              ": no 'dmpls' in the motion; its DMPL targets stay at rest");
  }
  if (!motions.empty() && coefficients.empty()) {
    report->notes.push_back(
        "--dmpl: no motion has 'dmpls' (DMPL coefficients): no DMPL targets exported");
    return out;
  }
  const int count = s.dmpl_count.value_or(total);
  basis->directions.conservativeResize(Eigen::NoChange, count);
  out.basis = std::make_unique<DmplBasis>(std::move(*basis));
  out.input = DmplInput{out.basis.get(), dmplLayout(count, coefficients), s.dmpl_regressed_joints};
  return out;
}

void noteDmplJointCost(const Asset& asset, ExportReport* report) {
  if (asset.metadata.dmpl.targets.empty()) return;
  for (const AnimationClip& clip : asset.animations) {
    char text[300];
    if (asset.metadata.dmpl.animate_joints)
      std::snprintf(text, sizeof text,
                    "%s: DMPL joints regressed per frame (published math); fixed joints would cost "
                    "up to %.3f mm",
                    clip.name.c_str(), clip.dmpl_joint_error * 1000);
    else
      std::snprintf(text, sizeof text,
                    "%s: DMPL with the betas-only skeleton (fixed joints) costs up to %.3f mm of "
                    "vertex error against the published math (--dmpl-joints regressed removes it)",
                    clip.name.c_str(), clip.dmpl_joint_error * 1000);
    report->notes.push_back(text);
  }
}

}  // namespace smpl
