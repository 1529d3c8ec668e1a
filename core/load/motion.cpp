#include "core/load/motion.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/io/file_io.h"
#include "core/io/npz.h"
#include "core/io/pickle/pickle.h"
#include "core/io/printable.h"
#include "core/joint_names.h"
#include "core/load/betas_rows.h"
#include "core/load/motion_aist.h"
#include "core/load/motion_fit.h"
#include "core/load/motion_internal.h"
#include "core/load/motion_smplcodec.h"
#include "core/load/npz_arrays.h"
#include "core/load/validate_inputs.h"

namespace smpl {
namespace motion_detail {

Format detectFormat(const ArrayDict& d) {
  if (find(d, "bodyPose")) return Format::SmplCodec;
  if (find(d, "smpl_poses")) return Format::Aist;
  if (find(d, "poses") || find(d, "root_orient")) return Format::Poses;
  if (find(d, "body_pose") || find(d, "global_orient")) return Format::Fit;
  return Format::NoPoses;
}

const Array* find(const ArrayDict& d, const char* key) {
  auto it = d.find(key);
  return it == d.end() ? nullptr : &it->second;
}

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
using motion_detail::find;
using motion_detail::Format;

// Nested rectangular JSON number arrays -> Array (shape inferred, C order).
Status jsonToArray(const nlohmann::json& j, Array* out, size_t depth = 0) {
  if (j.is_number()) {
    if (depth == 0) out->shape.clear();
    out->data.push_back(j.get<double>());
    return Status();
  }
  if (!j.is_array() || depth > 4) return makeError("expected nested arrays of numbers");
  const int64_t n = static_cast<int64_t>(j.size());
  if (out->shape.size() == depth)
    out->shape.push_back(n);
  else if (out->shape[depth] != n)
    return makeError("ragged array");
  for (const auto& item : j)
    if (Status s = jsonToArray(item, out, depth + 1); !s) return s;
  return Status();
}

Result<ArrayDict> readJsonArrays(const std::vector<uint8_t>& bytes, const std::string& path) {
  // A parsed JSON value takes 16 bytes and a number at least 2 characters ("0,"),
  // and each number is then copied into a double: at most 12 bytes per byte of text.
  MemoryCharge parse;
  if (Status st = parse.add(bytes.size() * 12, path, "parsing the JSON"); !st) return st.error();
  nlohmann::json j =
      nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return makeError(path + ": not a JSON object");
  ArrayDict arrays;
  for (const auto& [key, value] : j.items()) {
    Array a;
    if (value.is_string()) {
      a.dtype = "<U";
      a.strings = {value.get<std::string>()};
    } else if (Status s = jsonToArray(value, &a); !s) {
      return makeError(path + ": '" + printable(key, 64) + "': " + s.message());
    } else if (a.size() != static_cast<int64_t>(a.data.size())) {
      return makeError(path + ": '" + printable(key, 64) + "': ragged array");
    }
    arrays[key] = std::move(a);
  }
  return arrays;
}

// Concatenate SMPL-X AMASS split keys into one (T,165) pose array.
Result<Array> joinSplitPoses(const ArrayDict& d, const std::string& path) {
  const char* keys[] = {"root_orient", "pose_body", "pose_jaw", "pose_eye", "pose_hand"};
  const int64_t widths[] = {3, 63, 3, 6, 90};
  const Array* root = find(d, "root_orient");
  const int64_t t = root->shape.empty() ? 0 : root->shape[0];
  Array joined;
  joined.shape = {t, 165};
  if (Status st = joined.charge.add(static_cast<uint64_t>(t) * 165 * sizeof(double), path,
                                    "joining the pose keys");
      !st)
    return st.error();
  joined.data.assign(t * 165, 0.0);
  int64_t column = 0;
  for (int i = 0; i < 5; ++i) {
    const Array* a = find(d, keys[i]);
    if (a && (a->shape.size() != 2 || a->shape[0] != t || a->shape[1] != widths[i]))
      return makeError(path + ": '" + keys[i] + "' has shape " + shapeString(a->shape) +
                       "; expected (" + std::to_string(t) + "," + std::to_string(widths[i]) + ")");
    for (int64_t f = 0; a && f < t; ++f)
      for (int64_t c = 0; c < widths[i]; ++c)
        joined.data[f * 165 + column + c] = a->data[f * widths[i] + c];
    column += widths[i];
  }
  return joined;
}

// poses -> per-frame rotations; accepts (T,3J), (T,J,3) and (T,J,3,3).
Status decodeRotations(const Array& poses, const std::string& path, Motion* m) {
  const auto& s = poses.shape;
  const bool matrices = s.size() == 4 && s[2] == 3 && s[3] == 3;
  const bool triples = (s.size() == 2 && s[1] % 3 == 0) || (s.size() == 3 && s[2] == 3);
  if (!matrices && !triples)
    return makeError(path + ": 'poses' has shape " + shapeString(s) +
                     "; expected (T,3J), (T,J,3) or (T,J,3,3)");
  const int64_t t = s[0], j = matrices || s.size() == 3 ? s[1] : s[1] / 3;
  if (t == 0) return makeError(path + ": 'poses' has no frames");
  if (!modelKindFromJointCount(static_cast<int>(j), &m->layout))
    return makeError(path + ": 'poses' has " + std::to_string(j) +
                     " joints; expected 24 (SMPL), 52 (SMPL-H), 55 (SMPL-X) or 16 (MANO)");
  for (double v : poses.data)
    if (!std::isfinite(v)) return makeError(path + ": 'poses' contains NaN or infinite values");
  const uint64_t frame_bytes =
      sizeof(Rotations) + j * sizeof(Eigen::Matrix3d) + sizeof(Eigen::Vector3d);
  if (Status st = m->charge.add(static_cast<uint64_t>(t) * frame_bytes, path,
                                std::to_string(t) + " frames");
      !st)
    return st;
  m->frames.resize(t);
  const int64_t stride = matrices ? 9 * j : 3 * j;
  for (int64_t f = 0; f < t; ++f) {
    const double* p = poses.data.data() + f * stride;
    if (!matrices) {
      m->frames[f] = rotationsFromAxisAngle(Eigen::Map<const Eigen::VectorXd>(p, 3 * j));
      continue;
    }
    m->frames[f].resize(j);
    for (int64_t k = 0; k < j; ++k)
      m->frames[f][k] = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(p + 9 * k);
  }
  return Status();
}

// AMASS `dmpls` (T,D): soft-tissue coefficients (core/load/dmpl.h). Needed
// only with a DMPL basis, so a malformed array does not fail the load: the
// problem is kept in m->dmpls_problem for the exporter to report when used.
Status decodeDmpls(const ArrayDict& d, const std::string& path, Motion* m) {
  const Array* a = find(d, "dmpls");
  if (!a) return Status();
  const int64_t t = static_cast<int64_t>(m->frames.size());
  if (a->isString() || a->shape.size() != 2 || a->shape[0] != t || a->shape[1] < 1) {
    m->dmpls_problem = path + ": 'dmpls' has shape " + shapeString(a->shape) + "; expected (" +
                       std::to_string(t) + ",D) to match 'poses'";
    return Status();
  }
  if (Status st = motion_detail::checkNumbers(*a, path, "dmpls"); !st) {
    m->dmpls_problem = st.message();
    return Status();
  }
  if (Status st = m->charge.add(static_cast<uint64_t>(a->size()) * sizeof(double), path, "dmpls");
      !st)
    return st;
  m->dmpls =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          a->data.data(), a->shape[0], a->shape[1]);
  return Status();
}

Status decodeExtras(const ArrayDict& d, const std::string& path, Motion* m) {
  const size_t t = m->frames.size();
  m->translation.assign(t, Eigen::Vector3d::Zero());
  if (const Array* trans = find(d, "trans")) {
    if (trans->shape.size() != 2 || trans->shape[0] != static_cast<int64_t>(t) ||
        trans->shape[1] != 3)
      return makeError(path + ": 'trans' has shape " + shapeString(trans->shape) + "; expected (" +
                       std::to_string(t) + ",3) to match 'poses'");
    for (size_t f = 0; f < t; ++f)
      m->translation[f] = Eigen::Map<const Eigen::Vector3d>(trans->data.data() + 3 * f);
    for (double v : trans->data)
      if (!std::isfinite(v)) return makeError(path + ": 'trans' contains NaN or infinite values");
  }
  if (const Array* betas = find(d, "betas");
      betas && !betas->isString()) {  // per-frame rows: betas_rows.h
    Result<BetasRows> rows = collapseBetasRows(*betas, path);
    if (!rows) return rows.error();
    m->betas = rows->betas;
    if (rows->averaged) m->notes.push_back(betasRowsNote(*rows));
  }
  if (const Array* gender = find(d, "gender"); gender && !gender->strings.empty())
    m->gender = gender->strings[0];
  if (Status st = decodeDmpls(d, path, m); !st) return st;
  m->fps = 0.0;
  for (const char* key : {"mocap_framerate", "mocap_frame_rate", "fps"}) {
    const Array* rate = find(d, key);
    if (!rate || rate->isString() || rate->data.size() != 1) continue;
    if (Status st = checkFrameRate(rate->data[0], path, "'" + std::string(key) + "'"); !st)
      return st;
    m->fps = rate->data[0];
    m->amass = m->amass || std::string(key) != "fps";
    break;
  }
  m->amass = m->amass || find(d, "gender") || find(d, "root_orient");
  return Status();
}

// AMASS and plain files: `poses` or the AMASS SMPL-X split keys.
Status decodePoses(const ArrayDict& d, const std::string& path, Motion* m) {
  Array poses;
  if (const Array* p = find(d, "poses")) {
    poses = *p;
  } else {
    Result<Array> joined = joinSplitPoses(d, path);
    if (!joined) return joined.error();
    poses = std::move(*joined);
  }
  if (poses.isString()) return makeError(path + ": 'poses' holds text, expected numbers");
  if (Status s = decodeRotations(poses, path, m); !s) return s;
  return decodeExtras(d, path, m);
}

// The source rate: --source-fps, else the stored one, else a default; a
// note says what was assumed or overridden (single frames need no rate).
void settleFps(const MotionOptions& o, double fallback, const char* why, Motion* m) {
  char text[200];
  if (o.source_fps > 0) {
    if (m->fps > 0 && std::abs(m->fps - o.source_fps) > 1e-9) {
      std::snprintf(text, sizeof text, "the stored rate %g fps is overridden by --source-fps %g",
                    m->fps, o.source_fps);
      m->notes.push_back(text);
    }
    m->fps = o.source_fps;
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

// The keys the motion readers read from an .npz (NpzArchive is lazy: nothing
// else is decoded).
const std::vector<std::string>& motionKeys() {
  static const std::vector<std::string> keys = {
      "poses", "root_orient", "pose_body", "pose_jaw", "pose_eye", "pose_hand", "trans", "betas",
      "gender", "dmpls", "mocap_framerate", "mocap_frame_rate", "fps", "surface_model_type",
      // SMPLCodec
      "smplVersion", "shapeParameters", "frameCount", "frameRate", "bodyTranslation", "bodyPose",
      "headPose", "leftHandPose", "rightHandPose", "expressionParameters", "globalOrient",
      // fits
      "global_orient", "body_pose", "left_hand_pose", "right_hand_pose", "jaw_pose", "leye_pose",
      "reye_pose", "expression", "transl", "frame_rate",
      // AIST++
      "smpl_poses", "smpl_trans", "smpl_scaling"};
  return keys;
}

}  // namespace

namespace {

// A zip (npz) by its first bytes, without reading the file.
bool isZip(const std::string& path) {
  char magic[2] = {0, 0};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  const size_t n = std::fread(magic, 1, 2, f);
  std::fclose(f);
  return n == 2 && magic[0] == 'P' && magic[1] == 'K';
}

}  // namespace

Result<ArrayDict> readMotionArrays(const std::string& path) {
  if (isZip(path)) return readNpzArrays(path, motionKeys());  // lazy: only the keys the readers use
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  const std::vector<uint8_t>& b = *bytes;
  if (!b.empty() && (b[0] == 0x80 || b[0] == '(' || b[0] == '}' || b[0] == ']'))
    return parsePickle(b.data(), b.size(), path);
  const size_t first = std::min(
      b.size(), static_cast<size_t>(
                    std::find_if(b.begin(), b.end(), [](uint8_t c) { return !std::isspace(c); }) -
                    b.begin()));
  if (hasSuffix(path, ".json") || (first < b.size() && b[first] == '{'))
    return readJsonArrays(b, path);
  return parseNpz(b.data(), b.size(), path);  // its error says what a zip needed
}

Result<bool> hasPoseData(const std::string& path) {
  if (isZip(path)) {  // the member names decide; nothing is decoded
    Result<NpzArchive> npz = NpzArchive::open(path);
    if (!npz) return npz.error();
    ArrayDict names;
    for (const std::string& key : npz->keys()) names[key] = Array();
    return motion_detail::detectFormat(names) != Format::NoPoses;
  }
  Result<ArrayDict> arrays = readMotionArrays(path);
  if (!arrays) return arrays.error();
  return motion_detail::detectFormat(*arrays) != Format::NoPoses;
}

Result<Motion> loadMotion(const std::string& path, double fps_fallback) {
  MotionOptions options;
  options.fps_fallback = fps_fallback;
  return loadMotion(path, options);
}

Result<Motion> loadMotion(const std::string& path, const MotionOptions& options) {
  Result<ArrayDict> arrays = readMotionArrays(path);
  if (!arrays) return arrays.error();
  const ArrayDict& d = *arrays;
  Motion m;
  m.name = baseName(path);
  m.name = m.name.substr(0, m.name.rfind('.'));
  Status s;
  double fallback = options.fps_fallback;
  const char* why = "no frame rate is stored";
  switch (motion_detail::detectFormat(d)) {
    case Format::Poses:
      s = decodePoses(d, path, &m);
      break;
    case Format::SmplCodec:
      s = motion_detail::decodeSmplCodec(d, path, &m);
      break;
    case Format::Fit:
      s = motion_detail::decodeFit(d, path, &m);
      break;
    case Format::Aist:
      s = motion_detail::decodeAist(d, path, &m);
      fallback = 60.0;
      why = "AIST++ stores no frame rate; its documentation gives 60 fps";
      break;
    case Format::NoPoses:
      return makeError(
          path +
          ": missing key 'poses': no pose data (none of 'poses', 'root_orient', 'bodyPose', "
          "'body_pose', 'global_orient', 'smpl_poses'): a shape file, not a motion");
  }
  if (!s) return s.error();
  settleFps(options, fallback, why, &m);
  if (Status st = checkMotionValues(&m, path); !st) return st.error();
  return m;
}

}  // namespace smpl
