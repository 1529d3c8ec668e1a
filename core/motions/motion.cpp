// loadMotion: the container (motion_read.h), the layout row
// (motion_layout.h), its decode, then the frame rate and the value checks.
#include "core/motions/motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/io/file_io.h"
#include "core/joint_names.h"
#include "core/motions/motion_internal.h"
#include "core/motions/motion_layout.h"
#include "core/motions/motion_read.h"
#include "core/motions/unread_keys.h"
#include "core/motions/validate_motion.h"

namespace smpl {
namespace motion_detail {

Status allocateFrames(int64_t t, size_t joints, const std::string& path, Motion* m) {
  const uint64_t frame_bytes =
      sizeof(Rotations) + joints * sizeof(Eigen::Matrix3d) + sizeof(Eigen::Vector3d);
  if (Status st = m->charge.add(static_cast<uint64_t>(t) * frame_bytes, path,
                                std::to_string(t) + " frames");
      !st)
    return st;
  m->frames.assign(t, Rotations(joints, Eigen::Matrix3d::Identity()));
  return Status();
}

Status checkNumbers(const Array& a, const std::string& path, const char* key) {
  if (a.isString()) return makeError(path + ": '" + key + "' holds text, expected numbers");
  for (double v : a.data)
    if (!std::isfinite(v))
      return makeError(path + ": '" + key + "' contains NaN or infinite values");
  return Status();
}

Status readExpression(const Array& a, const std::string& path, const char* key, Motion* m) {
  if (Status st = checkNumbers(a, path, key); !st) return st;
  const int64_t t = static_cast<int64_t>(m->frames.size());
  const int64_t e = a.shape.empty() ? 1 : a.shape.back();
  const int64_t rows = e > 0 ? a.size() / e : 0;
  if (e < 1 || a.shape.size() > 2 || (rows != t && rows != 1))
    return makeError(path + ": '" + key + "' has shape " + shapeString(a.shape) + "; expected (" +
                     std::to_string(t) + ",E) expression coefficients");
  if (Status st = m->charge.add(static_cast<uint64_t>(t * e) * sizeof(double), path, key); !st)
    return st;
  m->expression.resize(t, e);
  for (int64_t f = 0; f < t; ++f)
    for (int64_t i = 0; i < e; ++i) m->expression(f, i) = a.data[(rows == 1 ? 0 : f) * e + i];
  return Status();
}

void putAxisAngle(const double* p, int count, int first, Rotations* out) {
  const Rotations r = rotationsFromAxisAngle(Eigen::Map<const Eigen::VectorXd>(p, 3 * count));
  for (int k = 0; k < count; ++k) (*out)[first + k] = r[k];
}

void putMatrices(const double* p, int count, int first, Rotations* out) {
  for (int k = 0; k < count; ++k)
    (*out)[first + k] = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p + 9 * k);
}

}  // namespace motion_detail

namespace {

// The source rate: --source-fps, else the stored one, else a default; a
// note says what was assumed or overridden (single frames need no rate).
void settleFps(const MotionOptions& o, double fallback, const char* why, Motion* m) {
  char text[200];
  if (o.source_fps) {
    if (m->fps > 0 && std::abs(m->fps - *o.source_fps) > 1e-9) {
      std::snprintf(text, sizeof text, "the stored rate %g fps is overridden by --source-fps %g",
                    m->fps, *o.source_fps);
      m->notes.push_back(text);
    }
    m->fps = *o.source_fps;
    m->fps_assumed = false;
    return;
  }
  if (m->fps > 0) return;
  m->fps = fallback;
  m->fps_assumed = true;
  if (m->frames.size() < 2) return;
  std::snprintf(text, sizeof text, "%s; assumed %g fps (state the rate with --source-fps R)", why,
                fallback);
  m->notes.push_back(text);
}

// The file's stem: the clip name of each track.
std::string stemOf(const std::string& path) {
  std::string name = baseName(path);
  return name.substr(0, name.rfind('.'));
}

// The row's decode of `root`, then each track's name, rate, world note and checks.
// Every note of the file and of its tracks.
std::vector<std::string> allNotes(const MotionSet& set) {
  std::vector<std::string> notes = set.notes;
  for (const Motion& m : set.tracks) notes.insert(notes.end(), m.notes.begin(), m.notes.end());
  return notes;
}

Result<MotionSet> decodeFile(const DataNode& root, const MotionLayout* row,
                             const std::vector<UndecodedMember>& undecoded, const std::string& path,
                             const MotionOptions& options) {
  if (!row) return makeError(path + ": " + unmatchedMessage(root));
  MotionSet set;
  clearReadMarks(root);  // the rows' `matches` fetched keys too
  if (Status s = row->decode(root, LayoutInput{path, options}, &set); !s) return s.error();
  if (std::string note = unreadKeysNote(root, undecoded, row->name, allNotes(set)); !note.empty())
    set.notes.push_back(note);
  // One frame of a --motion-sequence may hold no one (Multi-HMR: an image without a detection).
  if (set.tracks.empty() && !options.frame_file) return makeError(path + ": no motion in the file");
  for (Motion& m : set.tracks) {
    m.name = stemOf(path);
    if (m.source_layout.empty()) m.source_layout = row->name;  // a decode may name a variant
    settleFps(options, row->fps_fallback, row->fps_why, &m);
    if (m.world == MotionWorld::CameraYDown && !options.up_given)
      m.notes.push_back(
          (m.world_why.empty() ? std::string("the poses are in a camera frame") : m.world_why) +
          " (x right, y down, z forward): turned upright by a half turn about x "
          "(--up -y); --up y keeps the file's axes");
    if (Status st = checkMotionValues(&m, path); !st) return st.error();
  }
  return set;
}

}  // namespace

Result<MotionSet> loadMotionSet(const std::string& path, const MotionOptions& options) {
  Result<MotionFile> file = readMotionFile(path);
  if (!file) return file.error();
  return decodeFile(file->root, file->layout, file->undecoded, path, options);
}

Result<MotionSet> loadMotionSetFromTree(DataNode root, unsigned containers, const std::string& path,
                                        const MotionOptions& options) {
  const MotionLayout* row = root.isDict() ? findLayout(root, containers) : nullptr;
  std::vector<UndecodedMember> undecoded;
  if (row && containers == kNpzFile) {  // an .npz decodes only the row's keys, in its order
    for (size_t i = 0; i < root.keys.size(); ++i)
      if (std::find(row->keys.begin(), row->keys.end(), root.keys[i]) == row->keys.end())
        undecoded.push_back({root.keys[i], root.children[i].array.shape});
    DataNode keys;
    keys.kind = DataNode::Kind::Dict;
    for (const std::string& key : row->keys)
      for (size_t i = root.keys.size(); i-- > 0;)  // the last of a repeated key, as get()
        if (root.keys[i] == key) {
          keys.keys.push_back(key);
          keys.children.push_back(std::move(root.children[i]));
          break;
        }
    root = std::move(keys);
  }
  return decodeFile(root, row, undecoded, path, options);
}

Result<Motion> loadMotion(const std::string& path, const MotionOptions& options) {
  Result<MotionSet> set = loadMotionSet(path, options);
  if (!set) return set.error();
  Motion m = std::move(set->tracks.front());
  m.notes.insert(m.notes.begin(), set->notes.begin(), set->notes.end());
  return m;
}

void releaseFrames(Motion* m) {
  std::vector<Rotations>().swap(m->frames);
  std::vector<Eigen::Vector3d>().swap(m->translation);
  std::vector<Eigen::Matrix3d>().swap(m->world_rotation);
  std::vector<Eigen::Vector3d>().swap(m->world_translation);
  std::vector<bool>().swap(m->held);
  m->dmpls.resize(0, 0);
  m->expression.resize(0, 0);
  m->charge.release();
}

Result<bool> hasPoseData(const std::string& path) {
  Result<MotionFile> file = probeMotionFile(path);
  if (!file) return file.error();
  return file->layout != nullptr || !isShapeOnly(file->root);
}

}  // namespace smpl
