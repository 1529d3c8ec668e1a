#include "core/motions/motion_hamer.h"

#include "core/math/mirror_model.h"
#include "core/models/betas_rows.h"
#include "core/motions/motion_internal.h"

namespace smpl {
namespace {

using motion_detail::has;

const char kParams[] = "pred_mano_params";

// `name` at the top level, inside the pred_mano_params dict, or flattened
// as "pred_mano_params.<name>" (the node, any kind), or nullptr.
const DataNode* param(const DataNode& d, const std::string& name) {
  if (const DataNode* top = d.get(name)) return top;
  if (const DataNode* nested = d.get(kParams); nested && nested->isDict())
    if (const DataNode* inner = nested->get(name)) return inner;
  return d.get(std::string(kParams) + "." + name);
}

bool matchesHamer(const DataNode& root) {
  if (!root.isDict() || has(root, "body_pose")) return false;
  if (param(root, "hand_pose") && param(root, "global_orient")) return true;
  const DataNode* nested = root.get(kParams);
  return nested && nested->kind == DataNode::Kind::None;  // an .npz member, not decoded yet
}

// The arrays of one HaMeR output, N rows each.
struct HandRows {
  const Array *orient = nullptr, *pose = nullptr, *betas = nullptr, *side = nullptr,
              *trans = nullptr;
  int64_t n = 0;
};

Result<const Array*> numbers(const DataNode& d, const std::string& name, const std::string& path) {
  const DataNode* node = param(d, name);
  if (!node) return static_cast<const Array*>(nullptr);
  if (!node->isArray())
    return makeError(path + ": '" + name + "' is " + describeNode(*node) + ", expected numbers");
  if (Status st = motion_detail::checkNumbers(node->array, path, name.c_str()); !st)
    return st.error();
  return &node->array;
}

Status shapeError(const std::string& path, const char* key, const Array& a, const char* want) {
  return makeError(path + ": '" + key + "' has shape " + shapeString(a.shape) + "; expected " +
                   want);
}

Result<HandRows> rowsOf(const DataNode& d, const std::string& path) {
  HandRows h;
  const char* names[] = {"global_orient", "hand_pose", "betas"};
  const Array** slots[] = {&h.orient, &h.pose, &h.betas};
  for (int i = 0; i < 3; ++i) {
    Result<const Array*> a = numbers(d, names[i], path);
    if (!a) return a.error();
    if (!*a) return makeError(path + ": missing key '" + names[i] + "' (HaMeR's pred_mano_params)");
    *slots[i] = *a;
  }
  const auto& p = h.pose->shape;
  if (p.size() != 4 || p[0] < 1 || p[1] != 15 || p[2] != 3 || p[3] != 3)
    return shapeError(path, "hand_pose", *h.pose, "(N,15,3,3) rotation matrices").error();
  h.n = p[0];
  const auto& o = h.orient->shape;
  if (o != std::vector<int64_t>{h.n, 1, 3, 3} && o != std::vector<int64_t>{h.n, 3, 3})
    return shapeError(path, "global_orient", *h.orient,
                      ("(" + std::to_string(h.n) + ",1,3,3) rotation matrices").c_str())
        .error();
  const auto& b = h.betas->shape;
  if (b.size() != 2 || b[0] != h.n || b[1] < 1)
    return shapeError(path, "betas", *h.betas, ("(" + std::to_string(h.n) + ",10)").c_str())
        .error();
  for (const char* key : {"is_right", "right"}) {
    Result<const Array*> a = numbers(d, key, path);
    if (!a) return a.error();
    if (*a && (*a)->size() != h.n)
      return shapeError(path, key, **a, ("(" + std::to_string(h.n) + ",)").c_str()).error();
    if (*a && !h.side) h.side = *a;
  }
  for (const char* key : {"pred_cam_t_full", "pred_cam_t"}) {
    Result<const Array*> a = numbers(d, key, path);
    if (!a) return a.error();
    if (*a && (*a)->shape != std::vector<int64_t>{h.n, 3})
      return shapeError(path, key, **a, ("(" + std::to_string(h.n) + ",3)").c_str()).error();
    if (*a && !h.trans) h.trans = *a;
  }
  return h;
}

bool isRight(const HandRows& h, int64_t i) { return !h.side || h.side->data[i] > 0.5; }

// The notes every hand of the file shares: translation source, missing side.
std::vector<std::string> fileNotes(const DataNode& d, const HandRows& h) {
  std::vector<std::string> notes = {
      "read as HaMeR output (right-hand MANO rotation matrices; a left hand is the right hand "
      "mirrored, x negated)"};
  if (!h.side) notes.push_back("no 'is_right' or 'right': the hands are read as right hands");
  if (!h.trans)
    notes.push_back("no 'pred_cam_t_full' or 'pred_cam_t': the translation is zero");
  else if (!param(d, "pred_cam_t_full"))
    notes.push_back(
        "pred_cam_t is the crop camera's translation (focal 5000 px at 256 px): the hand's depth "
        "is not the image's");
  return notes;
}

// Row i as frame f of `m` (its side's own pose: S R S for a left hand).
void putRow(const HandRows& h, int64_t i, size_t f, Motion* m) {
  Rotations& r = m->frames[f];
  motion_detail::putMatrices(h.orient->data.data() + 9 * i, 1, 0, &r);
  motion_detail::putMatrices(h.pose->data.data() + 135 * i, 15, 1, &r);
  if (!isRight(h, i))
    for (Eigen::Matrix3d& joint : r) joint = mirrorRotation(joint);
  m->translation[f] =
      h.trans ? Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(h.trans->data.data() + 3 * i))
              : Eigen::Vector3d::Zero();
}

// A hand of `frames` rows, its side and camera frame set.
Status startHand(int64_t frames, bool right, const std::string& path, Motion* m) {
  m->layout = ModelKind::Mano;
  if (Status st = motion_detail::allocateFrames(frames, 16, path, m); !st) return st;
  m->translation.assign(frames, Eigen::Vector3d::Zero());
  m->hand = right ? "right" : "left";
  m->world = MotionWorld::CameraYDown;
  m->world_why = "HaMeR's pred_cam_t_full places the hand in the camera: a camera frame";
  m->fps = 0.0;
  return Status();
}

// One file, one hand through time: rows are frames.
Status oneHand(const DataNode& d, const HandRows& h, const std::string& path, MotionSet* out) {
  for (int64_t i = 1; i < h.n; ++i)
    if (isRight(h, i) != isRight(h, 0))
      return makeError(path +
                       ": 'is_right' mixes left and right hands in one file without a frame "
                       "index: save one hand per file, or one file per frame for "
                       "--motion-sequence");
  Motion m;
  if (Status st = startHand(h.n, isRight(h, 0), path, &m); !st) return st;
  for (int64_t i = 0; i < h.n; ++i) putRow(h, i, static_cast<size_t>(i), &m);
  Result<BetasRows> betas = collapseBetasRows(*h.betas, path);
  if (!betas) return betas.error();
  m.betas = betas->betas;
  m.notes = fileNotes(d, h);
  if (betas->averaged) m.notes.push_back(betasRowsNote(*betas));
  out->tracks.push_back(std::move(m));
  return Status();
}

// One frame of a sequence: each row is a hand, track 2k + is_right.
Status frameHands(const DataNode& d, const HandRows& h, const std::string& path, MotionSet* out) {
  int64_t rank[2] = {0, 0};
  std::vector<std::string> notes = fileNotes(d, h);
  for (int64_t i = 0; i < h.n; ++i)
    if (rank[isRight(h, i)]++ == 1)
      notes.push_back(
          "HaMeR does not track hands: in each frame the k-th left hand (in row order) joins "
          "track 2k and the k-th right hand track 2k+1, so the tracks of several hands of one "
          "side may swap persons");
  rank[0] = rank[1] = 0;
  for (int64_t i = 0; i < h.n; ++i) {
    const bool right = isRight(h, i);
    Motion m;
    if (Status st = startHand(1, right, path, &m); !st) return st;
    m.track = std::to_string(2 * rank[right]++ + (right ? 1 : 0));
    putRow(h, i, 0, &m);
    const int64_t b = h.betas->shape[1];
    m.betas.assign(h.betas->data.begin() + i * b, h.betas->data.begin() + (i + 1) * b);
    m.notes = notes;
    out->tracks.push_back(std::move(m));
  }
  return Status();
}

Status decodeHamer(const DataNode& d, const LayoutInput& in, MotionSet* out) {
  Result<HandRows> h = rowsOf(d, in.path);
  if (!h) return h.error();
  return in.options.frame_file ? frameHands(d, *h, in.path, out) : oneHand(d, *h, in.path, out);
}

}  // namespace

const MotionLayout& hamerLayout() {
  static const MotionLayout row{
      "hamer",
      "HaMeR hands (MANO global_orient, hand_pose, betas; is_right)",
      kAnyContainer,
      matchesHamer,
      {"global_orient", "hand_pose", "betas", "is_right", "right", "pred_cam_t_full", "pred_cam_t",
       "pred_mano_params", "pred_mano_params.global_orient", "pred_mano_params.hand_pose",
       "pred_mano_params.betas"},
      decodeHamer};
  return row;
}

}  // namespace smpl
