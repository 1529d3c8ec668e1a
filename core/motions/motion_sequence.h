// --motion-sequence DIR: a folder of per-frame files (SMPLer-X `00012_0.npz`:
// frame 12, person 0; EasyMocap `000012.json`: frame 12, its persons inside;
// HaMeR `000012.pkl`: frame 12, its hands as rows) joined into one motion
// per person, in frame order.
//
// Files: the regular files directly in DIR whose stem is `<frame>` or
// `<frame>_<person>` (digits) and whose extension is a motion extension of
// the reader table; other files are ignored (a note counts them). An entry
// named like that which is no regular file (a folder, a FIFO, a device, a
// link loop or a link to any of them: only stat(2)ed, never opened) or whose
// number has more than 12 digits fails the sequence, named, unless
// options.skip_bad_frames (then a note names each one skipped). Every file
// is read by loadMotionSet (each of its rows is frame <frame> + row); all must
// be the same layout; one that cannot be read fails the whole sequence, named.
// A person is the file's suffix, else the file's own track id; rows of one
// person become one track (motion_tracks.h assembleTrack: gaps hold the
// previous frame; a gap holding more than options.max_held_frames is an
// error naming the two frames). No per-frame file stores a rate: 30 fps unless
// --source-fps, with the usual note. Notes that every file repeats are kept once.
#pragma once

#include <string>

#include "core/motions/motion.h"
#include "core/result.h"

namespace smpl {

Result<MotionSet> loadMotionSequence(const std::string& dir,
                                     const MotionOptions& options = MotionOptions());

// The frame number and person suffix of a per-frame file name ("00012_0.npz"
// -> 12, "0"; "000012.json" -> 12, ""); false if the stem is not of that form.
bool parseFrameName(const std::string& file_name, int64_t* frame, std::string* person);

}  // namespace smpl
