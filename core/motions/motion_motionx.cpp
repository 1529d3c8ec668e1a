#include "core/motions/motion_motionx.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/models/betas_rows.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

// Where the blocks of one row sit: 322 columns with the face, 172 without.
struct Columns {
  int64_t width, trans, betas, expression, face_shape;  // expression/face_shape -1: absent
};
constexpr Columns kFull{322, 309, 312, 159, 209};
constexpr Columns kShort{172, 159, 162, -1, -1};
constexpr int64_t kExpression = 50, kFaceShape = 100, kBetas = 10;

bool matchesMotionx(const DataNode& root) {
  if (!root.isArray()) return false;
  const auto& s = root.array.shape;
  return s.size() == 2 && (s[1] == kFull.width || s[1] == kShort.width);
}

// Columns [first, first + n) of every row, as a (T,n) array (betas, expression).
Array block(const Array& a, int64_t first, int64_t n) {
  Array out;
  const int64_t t = a.shape[0], w = a.shape[1];
  out.shape = {t, n};
  out.dtype = "<f8";
  out.data.reserve(static_cast<size_t>(t * n));
  for (int64_t f = 0; f < t; ++f)
    out.data.insert(out.data.end(), a.data.begin() + f * w + first,
                    a.data.begin() + f * w + first + n);
  return out;
}

void poseRow(const double* p, Rotations* out) {
  motion_detail::putAxisAngle(p, 22, 0, out);        // root, body 1-21
  motion_detail::putAxisAngle(p + 66, 30, 25, out);  // left hand 25-39, right hand 40-54
  motion_detail::putAxisAngle(p + 156, 1, 22, out);  // jaw; eyes (23, 24) stay at rest
}

// Face expression (T,50) into m->expression; the FLAME face shape noted when non-zero.
Status readFace(const Array& a, const Columns& c, const std::string& path, Motion* m) {
  if (c.expression < 0) return Status();
  const Array psi = block(a, c.expression, kExpression);
  if (Status st = motion_detail::readExpression(psi, path, "face_expr", m); !st) return st;
  double largest = 0.0;
  const int64_t t = a.shape[0];
  for (int64_t f = 0; f < t; ++f)
    for (int64_t i = 0; i < kFaceShape; ++i)
      largest = std::max(largest, std::abs(a.data[f * c.width + c.face_shape + i]));
  char text[200];
  if (largest > 0) {
    std::snprintf(text, sizeof text,
                  "face_shape (100 FLAME shape coefficients, largest |value| %.3g) has no SMPL-X "
                  "counterpart: ignored",
                  largest);
    m->notes.push_back(text);
  }
  m->notes.push_back(
      "face_expr holds 50 SMPL-X expression coefficients per frame (Motion-X's own renderer "
      "uses the first 10)");
  return Status();
}

Status decodeMotionx(const DataNode& root, const std::string& path, Motion* m) {
  const Array& a = root.array;
  const Columns& c = a.shape[1] == kFull.width ? kFull : kShort;
  const int64_t t = a.shape[0];
  if (t < 1)
    return makeError(path + ": the Motion-X array has shape " + shapeString(a.shape) +
                     "; expected (T," + std::to_string(c.width) + ") with T >= 1");
  if (Status st = motion_detail::checkNumbers(a, path, "the Motion-X array"); !st) return st;
  m->layout = ModelKind::SmplX;
  if (Status st = motion_detail::allocateFrames(t, 55, path, m); !st) return st;
  m->translation.resize(t);
  for (int64_t f = 0; f < t; ++f) {
    const double* row = a.data.data() + f * c.width;
    poseRow(row, &m->frames[f]);
    m->translation[f] = Eigen::Map<const Eigen::Vector3d>(row + c.trans);
  }
  Result<BetasRows> betas = collapseBetasRows(block(a, c.betas, kBetas), path);
  if (!betas) return betas.error();
  m->betas = betas->betas;
  if (betas->averaged) m->notes.push_back(betasRowsNote(*betas));
  m->world = MotionWorld::Y;
  m->fps = 0.0;  // not stored: the row's 30 fps, with the documented-rate note
  m->notes.insert(m->notes.begin(),
                  "read as Motion-X smplx_" + std::to_string(c.width) +
                      " (SMPL-X axis-angle, absolute hands as flat_hand_mean=True, eyes at "
                      "rest, Y-up world)");
  return readFace(a, c, path, m);
}

}  // namespace

const MotionLayout& motionxLayout() {
  static const MotionLayout row{
      "motionx", "Motion-X smplx_322 / smplx_172 (one (T,322) or (T,172) array)",
      kNpyFile,  matchesMotionx,
      {},        motion_detail::oneTrack<decodeMotionx>,
      30.0,      "Motion-X stores no frame rate; its documentation gives 30 fps"};
  return row;
}

}  // namespace smpl
