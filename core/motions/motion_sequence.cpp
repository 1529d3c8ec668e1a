#include "core/motions/motion_sequence.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "core/io/file_io.h"
#include "core/io/printable.h"
#include "core/models/betas_rows.h"
#include "core/motions/motion_layout.h"
#include "core/motions/motion_tracks.h"
#include "core/os/path.h"

namespace smpl {
namespace fs = std::filesystem;
namespace {

bool allDigits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// Frame numbers up to 12 digits: a trillion frames, far within int64_t.
constexpr size_t kMaxFrameDigits = 12;

bool digits(const std::string& s) { return allDigits(s) && s.size() <= kMaxFrameDigits; }

// The stem of `name` when it is named like a per-frame file: a motion
// extension and `<digits>` or `<digits>_<digits>` of any length; "" if not.
std::string frameStem(const std::string& name) {
  const size_t dot = name.find('.');
  if (dot == std::string::npos || hasSuffix(name, ".smpl.json")) return "";
  const std::string ext = name.substr(name.rfind('.'));
  const std::vector<std::string> known = motionFileExtensions();
  if (std::find(known.begin(), known.end(), ext) == known.end()) return "";
  const std::string stem = name.substr(0, name.rfind('.'));
  const size_t underscore = stem.find('_');
  if (!allDigits(stem.substr(0, underscore))) return "";
  if (underscore != std::string::npos && !allDigits(stem.substr(underscore + 1))) return "";
  return stem;
}

struct FrameFile {
  int64_t frame = 0;
  std::string person, path;
};

const char* describeType(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::not_found:
      return "a link to nothing";
    default:
      return "not a file";
  }
}

// Why the entry `path`, named like a frame (`stem`), cannot be one of the
// sequence's frames, or "" when it can. Only its type is examined (stat(2)
// through links, never open(2)): a FIFO would block the read and a device
// never ends.
std::string badFrameReason(const fs::path& path, const std::string& stem) {
  const std::string number = stem.substr(0, stem.find('_'));
  const std::string person =
      stem.find('_') == std::string::npos ? "" : stem.substr(stem.find('_') + 1);
  if (number.size() > kMaxFrameDigits || person.size() > kMaxFrameDigits)
    return "a frame or person number of " + std::to_string(std::max(number.size(), person.size())) +
           " digits (at most " + std::to_string(kMaxFrameDigits) + ")";
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // follows links: a link to a file is a frame
  if (ec && st.type() != fs::file_type::not_found) return "cannot be examined: " + ec.message();
  if (st.type() == fs::file_type::regular) return "";
  return std::string("not a regular file (") + describeType(st.type()) + ")";
}

// The per-frame files of `dir`, by frame then person; `ignored` counts the
// entries not named like frames. An entry named like a frame that is no
// readable file is an error naming it, or with options.skip_bad_frames a note
// in `skipped`.
Result<std::vector<FrameFile>> listFrames(const std::string& dir, const MotionOptions& options,
                                          size_t* ignored, std::vector<std::string>* skipped) {
  std::error_code ec;
  if (!fs::is_directory(os::fsPath(dir), ec))
    return makeError(dir + ": not a directory (--motion-sequence)", ErrorKind::Load);
  std::vector<FrameFile> files;
  for (auto it = fs::directory_iterator(os::fsPath(dir), ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    FrameFile f;
    f.path = os::utf8(it->path());
    const std::string stem = frameStem(os::utf8(it->path().filename()));
    if (stem.empty()) {
      ++*ignored;
      continue;
    }
    if (const std::string why = badFrameReason(it->path(), stem); !why.empty()) {
      if (!options.skip_bad_frames)
        return makeError(f.path + ": named like a frame of the sequence but " + why +
                             " (remove it, or give --skip-bad-frames to skip it with a note)",
                         ErrorKind::Load);
      skipped->push_back("skipped " + f.path + ": " + why + " (--skip-bad-frames)");
      continue;
    }
    if (!parseFrameName(os::utf8(it->path().filename()), &f.frame, &f.person)) {
      ++*ignored;
      continue;
    }
    files.push_back(f);
  }
  if (ec) return makeError(dir + ": cannot list: " + ec.message(), ErrorKind::Load);
  if (files.empty())
    return makeError(dir + ": no per-frame motion files (<frame>.<ext> or <frame>_<person>.<ext>)",
                     ErrorKind::Load);
  std::sort(files.begin(), files.end(), [](const FrameFile& a, const FrameFile& b) {
    return a.frame != b.frame ? a.frame < b.frame : a.person < b.person;
  });
  std::sort(skipped->begin(), skipped->end());  // listing order is the file system's
  return files;
}

// A gap between two detections of one person holds copies of the frame
// before it (assembleTrack); more than options.max_held_frames of them is an
// error before any is made (three files numbered 0, 1 and 10^6 would be a
// million frames).
Status checkGaps(std::vector<int64_t> frames, const std::string& dir, const std::string& person,
                 const MotionOptions& options) {
  std::sort(frames.begin(), frames.end());
  for (size_t i = 1; i < frames.size(); ++i) {
    const int64_t held = frames[i] - frames[i - 1] - 1;
    if (held > options.max_held_frames)
      return makeError(
          dir + ": " + (person.empty() ? "" : "person " + printable(person, 64) + ": ") +
              "no file between frames " + std::to_string(frames[i - 1]) + " and " +
              std::to_string(frames[i]) + ": the gap would hold " + std::to_string(held) +
              " copies of frame " + std::to_string(frames[i - 1]) + " (at most " +
              std::to_string(options.max_held_frames) + "; --max-held-frames N allows up to " +
              std::to_string(kMaxHeldFramesLimit) + ")",
          ErrorKind::Load);
  }
  return Status();
}

// Appends `from`'s rows to `to` (same layout and joint count).
Status appendRows(const Motion& from, const std::string& path, Motion* to) {
  if (to->frames.empty()) {
    Motion copy = from;
    copy.notes.clear();
    *to = std::move(copy);
    return Status();
  }
  if (from.layout != to->layout || from.frames[0].size() != to->frames[0].size())
    return makeError(path + ": a " + modelKindName(from.layout) + " pose among " +
                     modelKindName(to->layout) + " poses of the sequence");
  if (from.hands.left.empty() != to->hands.left.empty() ||
      from.hands.right.empty() != to->hands.right.empty())
    return makeError(path + ": hand poses in some files of the sequence and not in others");
  if (Status st = to->charge.add(from.charge.bytes(), path, "the sequence's frames"); !st)
    return st;
  to->frames.insert(to->frames.end(), from.frames.begin(), from.frames.end());
  to->translation.insert(to->translation.end(), from.translation.begin(), from.translation.end());
  to->world_rotation.insert(to->world_rotation.end(), from.world_rotation.begin(),
                            from.world_rotation.end());
  to->world_translation.insert(to->world_translation.end(), from.world_translation.begin(),
                               from.world_translation.end());
  to->hands.left.insert(to->hands.left.end(), from.hands.left.begin(), from.hands.left.end());
  to->hands.right.insert(to->hands.right.end(), from.hands.right.begin(), from.hands.right.end());
  if (from.expression.rows() > 0 || to->expression.rows() > 0) {
    const Eigen::Index cols = std::max(from.expression.cols(), to->expression.cols());
    Eigen::MatrixXd joined =
        Eigen::MatrixXd::Zero(to->expression.rows() + from.frames.size(), cols);
    joined.topLeftCorner(to->expression.rows(), to->expression.cols()) = to->expression;
    if (from.expression.rows() > 0)
      joined.bottomLeftCorner(from.expression.rows(), from.expression.cols()) = from.expression;
    to->expression = std::move(joined);
  }
  return Status();
}

struct Person {
  Motion motion;
  std::vector<int64_t> frames;
  std::vector<std::vector<double>> betas;  // per file
};

// The folder's name: the clip name of its tracks.
std::string folderName(const std::string& dir) {
  fs::path p = os::fsPath(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return os::utf8(p.filename());
}

// The betas of one person over the files: identical -> that row, else their
// mean with a note (core/models/betas_rows.h).
Status settleBetas(const Person& p, const std::string& dir, Motion* m) {
  if (p.betas.empty()) return Status();
  size_t width = 0;
  for (const auto& b : p.betas) width = std::max(width, b.size());
  Array rows;
  rows.shape = {static_cast<int64_t>(p.betas.size()), static_cast<int64_t>(width)};
  rows.dtype = "<f8";
  for (const auto& b : p.betas) {
    rows.data.insert(rows.data.end(), b.begin(), b.end());
    rows.data.resize(rows.data.size() + width - b.size(), 0.0);
  }
  Result<BetasRows> r = collapseBetasRows(rows, dir);
  if (!r) return r.error();
  m->betas = r->betas;
  if (r->averaged) m->notes.push_back("track " + m->track + ": " + betasRowsNote(*r));
  return Status();
}

}  // namespace

bool parseFrameName(const std::string& name, int64_t* frame, std::string* person) {
  const std::string stem = frameStem(name);
  const size_t underscore = stem.find('_');
  const std::string first = stem.substr(0, underscore);
  const std::string rest = underscore == std::string::npos ? "" : stem.substr(underscore + 1);
  if (!digits(first) || (underscore != std::string::npos && !digits(rest))) return false;
  *frame = std::stoll(first);
  *person = rest;
  return true;
}

Result<MotionSet> loadMotionSequence(const std::string& dir, const MotionOptions& options) {
  size_t ignored = 0;
  std::vector<std::string> skipped;
  Result<std::vector<FrameFile>> files = listFrames(dir, options, &ignored, &skipped);
  if (!files) return files.error();
  std::map<std::string, Person> people;
  std::vector<std::string> notes;
  std::set<std::string> seen_notes;
  std::string layout;
  MotionOptions per_file = options;
  per_file.frame_file = true;  // a file's rows are that frame's hands or persons (HaMeR)
  for (const FrameFile& f : *files) {
    Result<MotionSet> set = loadMotionSet(f.path, per_file);
    if (!set) return set.error();
    for (const std::string& n : set->notes)  // the file's notes ("read as ..."), once
      if (seen_notes.insert(n).second) notes.push_back(n);
    for (Motion& m : set->tracks) {
      if (layout.empty()) layout = m.source_layout;
      if (m.source_layout != layout)
        return makeError(f.path + ": a " + m.source_layout + " file among " + layout +
                         " files of the sequence " + dir);
      for (const std::string& n : m.notes)
        if (n.find("assumed") == std::string::npos && seen_notes.insert(n).second)
          notes.push_back(n);
      const std::string key = f.person.empty()  ? m.track
                              : m.track.empty() ? f.person
                                                : f.person + "_" + m.track;
      Person& p = people[key];
      for (size_t r = 0; r < m.frames.size(); ++r) p.frames.push_back(f.frame + m.first_frame + r);
      if (!m.betas.empty()) p.betas.push_back(m.betas);
      if (Status st = appendRows(m, f.path, &p.motion); !st) return st.error();
      p.motion.track = key;
    }
  }
  if (people.empty())
    return makeError(dir + ": no person in any of its " + std::to_string(files->size()) + " files",
                     ErrorKind::Load);
  MotionSet out;
  out.notes = notes;
  char text[200];
  std::snprintf(text, sizeof text, "%zu files joined (frames %lld-%lld)%s", files->size(),
                static_cast<long long>(files->front().frame),
                static_cast<long long>(files->back().frame),
                ignored ? (", " + std::to_string(ignored) + " other files ignored").c_str() : "");
  out.notes.insert(out.notes.begin(), text);
  out.notes.insert(out.notes.begin() + 1, skipped.begin(), skipped.end());
  for (auto& [key, p] : people)
    if (Status st = checkGaps(p.frames, dir, key, options); !st) return st.error();
  for (auto& [key, p] : people) {
    Motion& m = p.motion;
    m.name = folderName(dir);
    if (Status st = assembleTrack(p.frames, dir, &m); !st) return st.error();
    if (Status st = settleBetas(p, dir, &m); !st) return st.error();
    if (!options.source_fps && m.fps_assumed && m.frames.size() > 1) {
      std::snprintf(text, sizeof text,
                    "no frame rate is stored; assumed %g fps (state the rate with --source-fps R)",
                    m.fps);
      m.notes.push_back(text);
    }
    out.tracks.push_back(std::move(m));
  }
  return out;
}

}  // namespace smpl
