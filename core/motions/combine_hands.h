// A body clip's fingers (and optionally wrists) driven by MANO hand tracks
// (--hands FILE, --hands-wrist; docs/motions.md "Combining hand tracks").
//
// A hand track is a MANO motion with its side (Motion::hand; HaMeR's
// is_right): frames[f] holds 16 local rotations, [0] the hand's global
// orientation and [1..15] the 15 finger joints in MANO order (index, middle,
// pinky, ring, thumb; three each), which is the order of the SMPL-X and
// SMPL-H finger joints of that side. The rotations are the side's own pose
// (a left hand's are already S R S, S = diag(-1,1,1), as the HaMeR reader
// un-mirrors them) and absolute: MANO adds no mean pose to rotation input, so
// they replace the body's finger rotations as they are, whatever the body
// model's hands_mean (the body's own hands are resolved first).
//
// Frames: a track with a track id (one from per-frame files or a
// multi-track file) is matched by source frame number (Motion::first_frame;
// held frames count as missing); a track without one by index, and its
// length must be the body clip's. A body frame without a frame of the track
// keeps the body clip's hand, with a note counting them.
//
// Wrist (`wrist`): as Mano2Smpl-X (VincentHu19/Mano2Smpl-X mano2smplx.py)
// computes it, with both in one camera frame:
//   wrist_local = (R_pelvis R_spine1 R_spine2 R_spine3 R_collar R_shoulder R_elbow)^T G_hand
// with the body's local rotations along the parent chain up to the elbow of
// that side and G_hand the track's global orientation.
#pragma once

#include <string>
#include <vector>

#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

// One hand track to combine: `motion` (layout Mano, hand "left" or "right",
// 16 rotations per frame) read from `path` (named in errors and notes).
struct HandTrack {
  const Motion* motion = nullptr;
  std::string path;
};

// Puts the tracks' finger rotations (and with `wrist` the wrist rotations
// above) into `body` (layout SMPL-X or SMPL-H, its hands already resolved),
// frame by frame, and adds one note per track. At most one track per side.
// Errors (one line, naming the file): a body without finger joints, a track
// that is not a sided MANO hand, two tracks of one side, a track whose frames
// do not fit the body clip's (length by index, frame numbers by id), and for
// `wrist` a body or track not in a camera frame (world_why) or a body with a
// per-frame frame change.
Status combineHands(const std::vector<HandTrack>& hands, bool wrist, const std::string& body_path,
                    Motion* body);

}  // namespace smpl
