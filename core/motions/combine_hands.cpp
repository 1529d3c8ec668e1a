#include "core/motions/combine_hands.h"

#include <algorithm>
#include <array>

#include "core/io/printable.h"
#include "core/joint_names.h"

namespace smpl {
namespace {

constexpr int kFingers = 15;  // finger joints per hand (MANO joints 1..15)

// The body joints of one side, as indices into the body clip's layout.
struct SideJoints {
  int first_finger = -1;          // <side>_index1: 15 finger joints from here, MANO order
  int wrist = -1;                 // <side>_wrist
  std::array<int, 7> chain = {};  // pelvis .. <side>_elbow: the wrist's parent chain, root first
};

int jointIndex(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

SideJoints sideJoints(ModelKind layout, const std::string& side) {
  const std::vector<std::string>& names = canonicalJointNames(layout);
  SideJoints s;
  s.first_finger = jointIndex(names, side + "_index1");
  s.wrist = jointIndex(names, side + "_wrist");
  const std::string chain[7] = {"pelvis",         "spine1",           "spine2",       "spine3",
                                side + "_collar", side + "_shoulder", side + "_elbow"};
  for (int k = 0; k < 7; ++k) s.chain[k] = jointIndex(names, chain[k]);
  return s;
}

std::string trackName(const HandTrack& h) {
  std::string name = h.path;
  if (!h.motion->track.empty()) name += ": track " + printable(h.motion->track, 64);
  return name;
}

std::string frameSpan(int64_t first, size_t count) {
  return std::to_string(first) + "-" + std::to_string(first + static_cast<int64_t>(count) - 1);
}

// Per body frame, the track's frame that drives it, or -1 (no frame of the track).
Result<std::vector<int64_t>> matchFrames(const HandTrack& h, const Motion& body,
                                         const std::string& body_path) {
  const Motion& hand = *h.motion;
  const size_t t = body.frames.size(), n = hand.frames.size();
  std::vector<int64_t> match(t, -1);
  if (hand.track.empty()) {  // no frame numbers: by index
    if (n != t)
      return makeError(trackName(h) + ": " + std::to_string(n) +
                       " hand frames for the body clip's " + std::to_string(t) + " (" + body_path +
                       "): a hand track without frame numbers is matched by index and must have "
                       "the body clip's length");
    for (size_t i = 0; i < t; ++i) match[i] = static_cast<int64_t>(i);
    return match;
  }
  const int64_t offset = hand.first_frame - body.first_frame;  // body index of the track's frame 0
  if (offset < 0 || offset + static_cast<int64_t>(n) > static_cast<int64_t>(t))
    return makeError(trackName(h) + ": source frames " + frameSpan(hand.first_frame, n) +
                     " are not all in the body clip's " + frameSpan(body.first_frame, t) + " (" +
                     body_path + "): frames are matched by number");
  for (size_t j = 0; j < n; ++j)
    if (hand.held.empty() || !hand.held[j]) match[offset + j] = static_cast<int64_t>(j);
  return match;
}

Status checkTrack(const HandTrack& h) {
  const Motion& m = *h.motion;
  if (m.layout != ModelKind::Mano || m.frames.empty() || m.frames[0].size() != 1 + kFingers)
    return makeError(trackName(h) + ": not a hand track (a " + modelKindName(m.layout) +
                     " motion): --hands takes MANO hand tracks (HaMeR, WiLoR)");
  if (m.hand != "left" && m.hand != "right")
    return makeError(trackName(h) +
                     ": a MANO track without a side (no is_right): --hands cannot tell which hand "
                     "it drives");
  return Status();
}

Status checkWrist(const HandTrack& h, const Motion& body, const std::string& body_path) {
  if (body.world != MotionWorld::CameraYDown || !body.world_rotation.empty())
    return makeError(body_path +
                     ": --hands-wrist needs the body clip in the camera frame of the hand track "
                     "(give --source-params incam for the body's camera-frame parameters)");
  if (h.motion->world != MotionWorld::CameraYDown || !h.motion->world_rotation.empty())
    return makeError(trackName(h) +
                     ": --hands-wrist needs the hand track in a camera frame (its global_orient "
                     "in the body clip's camera)");
  return Status();
}

// (R_chain[0] ... R_chain[6]): the elbow's global rotation from the body's local rotations.
Eigen::Matrix3d chainRotation(const Rotations& r, const SideJoints& s) {
  Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
  for (int k : s.chain) g = g * r[k];
  return g;
}

std::string trackNote(const HandTrack& h, bool wrist, size_t missing, size_t frames) {
  std::string note = trackName(h) + ": the " + h.motion->hand + " hand's " +
                     (wrist ? "wrist and fingers" : "fingers") +
                     " (absolute MANO rotations, no hands_mean added)";
  if (wrist)
    note +=
        ", the wrist as Mano2Smpl-X sets it: (the elbow's global rotation)^T x the track's "
        "global_orient";
  note += "; its translation, betas and rate are not used";
  if (missing > 0)
    note += "; " + std::to_string(missing) + " of " + std::to_string(frames) +
            " frames have no frame of this track and keep the body clip's hand";
  return note;
}

// Track `h`'s frames into `body` at the matched frames; the note.
void combineOne(const HandTrack& h, const std::vector<int64_t>& match, bool wrist, Motion* body) {
  const SideJoints s = sideJoints(body->layout, h.motion->hand);
  size_t missing = 0;
  for (size_t i = 0; i < body->frames.size(); ++i) {
    if (match[i] < 0) {
      ++missing;
      continue;
    }
    const Rotations& hand = h.motion->frames[static_cast<size_t>(match[i])];
    Rotations& r = body->frames[i];
    for (int k = 0; k < kFingers; ++k) r[s.first_finger + k] = hand[1 + k];
    if (wrist) r[s.wrist] = chainRotation(r, s).transpose() * hand[0];
  }
  body->notes.push_back(trackNote(h, wrist, missing, body->frames.size()));
}

}  // namespace

Status combineHands(const std::vector<HandTrack>& hands, bool wrist, const std::string& body_path,
                    Motion* body) {
  if (body->layout != ModelKind::SmplX && body->layout != ModelKind::SmplH)
    return makeError(body_path + ": --hands drives the fingers of an SMPL-X or SMPL-H " +
                     "body clip; this clip is " + modelKindName(body->layout) +
                     " (no finger joints)");
  const HandTrack* seen[2] = {nullptr, nullptr};  // left, right
  for (const HandTrack& h : hands) {
    if (Status st = checkTrack(h); !st) return st;
    const HandTrack*& other = seen[h.motion->hand == "right"];
    if (other)
      return makeError(trackName(h) + ": a second " + h.motion->hand + " hand (the first: " +
                       trackName(*other) + "): give one hand track per side");
    other = &h;
  }
  std::vector<std::pair<const HandTrack*, std::vector<int64_t>>> matched;  // checked first
  for (const HandTrack* h : seen) {
    if (!h) continue;
    Result<std::vector<int64_t>> match = matchFrames(*h, *body, body_path);
    if (!match) return match.error();
    if (wrist)
      if (Status st = checkWrist(*h, *body, body_path); !st) return st;
    matched.emplace_back(h, std::move(*match));
  }
  for (const auto& [h, match] : matched) combineOne(*h, match, wrist, body);
  return Status();
}

}  // namespace smpl
