#include "request/motion_notes.h"

namespace smpl {

AnimationOptions framesFor(const AnimationOptions& animation, const Motion& m, std::string* note) {
  AnimationOptions frames = animation;
  const int total = static_cast<int>(m.frames.size());
  if (frames.end_frame > total && frames.first_frame < total) {
    if (note)
      *note = m.name + ": --frames " + std::to_string(frames.first_frame) + ":" +
              std::to_string(frames.end_frame) + " ends after the motion's " +
              std::to_string(total) + " frames; baked frames " +
              std::to_string(frames.first_frame) + ":" + std::to_string(total);
    frames.end_frame = total;
  }
  return frames;
}

void noteMotions(const std::vector<Motion>& motions, const std::vector<std::string>& frame_notes,
                 bool betas_given, const Asset& asset, ExportReport* report) {
  for (size_t i = 0; i < motions.size(); ++i) {
    const Motion& m = motions[i];
    for (const std::string& note : m.notes)  // a betas note matters only where those betas are used
      if (note.rfind("betas:", 0) != 0 || (!betas_given && i == 0))
        report->notes.push_back(m.name + ": " + note);
    if (i < frame_notes.size() && !frame_notes[i].empty()) report->notes.push_back(frame_notes[i]);
    if (i >= asset.animations.size()) continue;
    const AnimationClip& clip = asset.animations[i];
    if (!clip.dropped_joints.empty())
      report->notes.push_back(m.name + ": " + std::to_string(clip.dropped_joints.size()) + " " +
                              modelKindName(m.layout) + " joints not in the model were dropped (" +
                              clip.dropped_joints.front() + ", ...)");
    for (const std::string& note : clip.notes) report->notes.push_back(note);
    report->frames += static_cast<int>(clip.times.size());
  }
}

}  // namespace smpl
