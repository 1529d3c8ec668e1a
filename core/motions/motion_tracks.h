// People and frames in a motion file:
// multi-person files decode to one Motion per track; --track picks among
// them, and a track's detections become a clip of consecutive frames.
//
// Rules (docs/motions.md "Tracks and frames"):
// - a track's clip runs from its first to its last source frame and starts at
//   time 0 there (Motion::first_frame records the source frame); a source
//   frame without a detection holds the previous one (a note counts them);
// - `longest` (the default) picks the track with the most detections, ties to
//   the lower id (numeric ids of any length compare as numbers); a note names the pick and
//   lists the others with their source frames;
// - `all` keeps every track (one output each, <out stem>.track<ID>.<ext>);
// - an id picks that track; an unknown id is an error listing the ids.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

struct TrackChoice {
  enum class Kind { Longest, All, Id };
  Kind kind = Kind::Longest;
  std::string id;  // Kind::Id
};

// "longest", "all" or an id (letters, digits, '-', '_', '.', '+'; at most 64).
// Errors: usage text naming --track.
Result<TrackChoice> parseTrackChoice(const std::string& text);

// Orders `m`'s rows by `frames` (their source frame numbers, one per row of
// frames/translation/expression/world_*), refuses a repeated frame, fills
// the frames between detections with the previous row (held_frames counts
// them) and sets first_frame. Errors name `path` and the track.
Status assembleTrack(const std::vector<int64_t>& frames, const std::string& path, Motion* m);

// The tracks `choice` keeps, each with its track note (when the file holds
// more than one). Errors: an unknown id ("<path>: no track 7 (tracks: 0, 1,
// 2)"), an id for a file without ids ("no track 3 (one person, no track ids)").
Result<std::vector<Motion>> selectTracks(MotionSet set, const TrackChoice& choice,
                                         const std::string& path);

}  // namespace smpl
