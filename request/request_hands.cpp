#include "request/request_hands.h"

#include <algorithm>
#include <filesystem>

#include "core/motions/combine_hands.h"
#include "core/motions/motion_sequence.h"
#include "core/os/path.h"

namespace smpl {
namespace {

// The tracks of one --hands path: a folder of per-frame files (HaMeR's demo
// writes one per image, both hands as rows; the request's --skip-bad-frames
// and --max-held-frames) or one file.
// Its world and rate are the body clip's: no notes about them (up_given).
Result<MotionSet> decodeHandFile(const std::string& path, const ExportRequest& r) {
  MotionOptions options = r.reading;
  options.up_given = true;
  options.source_fps.reset();  // the body clip's rate and world, not the body file's options
  options.source_params = SourceParams::Default;
  std::error_code ec;
  if (std::filesystem::is_directory(os::fsPath(path), ec)) return loadMotionSequence(path, options);
  return loadMotionSet(path, options);
}

bool hasFingers(const BodyModel& model) {
  const auto& names = model.joint_names;
  return std::find(names.begin(), names.end(), "left_index1") != names.end();
}

// A hand file's notes for the body clip, each named after the file. Left
// out: the assumed rate (the track's frames follow the body clip's) and the
// frames held between detections (--hands keeps the body's hand there
// instead; combineHands counts them), as loadMotionSequence leaves out the
// per-file rate notes.
void addHandNotes(const std::string& path, const MotionSet& set, Motion* body) {
  std::vector<std::string> notes = set.notes;
  for (const Motion& m : set.tracks)
    for (const std::string& note : m.notes)
      if (note.find("assumed") == std::string::npos &&
          note.find(": source frames without a detection: ") == std::string::npos &&
          std::find(notes.begin(), notes.end(), note) == notes.end())
        notes.push_back(note);
  for (const std::string& note : notes) body->notes.push_back(path + ": " + note);
}

}  // namespace

Status applyRequestHands(const BodyModel& model, const ExportRequest& r,
                         const std::string& body_path, Motion* body, std::string* about) {
  if (r.hands.empty()) return Status();
  *about = r.model;
  if (!hasFingers(model))
    return makeError("the model " + model.name +
                     " has no finger joints: --hands needs an SMPL-X or SMPL-H model");
  std::vector<MotionSet> sets;
  for (const std::string& path : r.hands) {
    *about = path;
    Result<MotionSet> set = decodeHandFile(path, r);
    if (!set) return set.error();
    sets.push_back(std::move(*set));
  }
  std::vector<HandTrack> tracks;
  for (size_t i = 0; i < sets.size(); ++i)
    for (const Motion& m : sets[i].tracks) tracks.push_back(HandTrack{&m, r.hands[i]});
  Status st = combineHands(tracks, r.hands_wrist, body_path, body);
  if (!st) {
    *about = body_path;  // combineHands names the file its error is about
    for (const std::string& path : r.hands)
      if (st.message().compare(0, path.size() + 1, path + ":") == 0) *about = path;
    return st;
  }
  for (size_t i = 0; i < sets.size(); ++i) addHandNotes(r.hands[i], sets[i], body);
  *about = body_path;
  return Status();
}

}  // namespace smpl
