// The BVH writer (bvh_writer.h): HIERARCHY from the skeleton, MOTION from the
// asset's one clip (or the rest pose).
#include "writers/bvh/bvh_writer.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "exporter/validate_asset.h"
#include "writers/bvh/bvh_euler.h"

namespace smpl {
namespace {

constexpr double kRadiansToDegrees = 57.295779513082320876798;
constexpr double kRestFps = 30.0;  // Frame Time of the rest-pose file (no clip)

// `v` fixed-point with `decimals` digits; a rounded negative zero is written "0.000...".
std::string fixed(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  std::string s = text;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

// How the file is laid out: the joints in HIERARCHY order and their channels.
struct Layout {
  std::vector<std::vector<int>> children;  // per joint, in index order
  std::vector<int> order;                  // depth first from the root
  std::vector<bool> position;              // per joint: Xposition Yposition Zposition too
  int root = 0;
  double scale = 1.0;  // metres -> file units
  int decimals = 8;    // of positions and offsets
};

// Whether joint k's translation track leaves its rest offset at some frame.
bool movesAwayFromRest(const Asset& a, const AnimationClip* clip, int k) {
  if (!clip || clip->joint_translations.empty()) return false;
  const Eigen::Vector3d rest = a.skeleton.rest_local.row(k).transpose();
  for (const Eigen::Vector3d& p : clip->joint_translations[size_t(k)])
    if (p != rest) return true;
  return false;
}

void depthFirst(Layout& l, int k) {
  l.order.push_back(k);
  for (int c : l.children[size_t(k)]) depthFirst(l, c);
}

Layout layoutOf(const Asset& a, const AnimationClip* clip, bool cm) {
  const Skeleton& s = a.skeleton;
  const int k_count = static_cast<int>(s.names.size());
  Layout l;
  l.children.resize(size_t(k_count));
  l.position.assign(size_t(k_count), false);
  for (int k = 0; k < k_count; ++k) {
    if (s.parents[size_t(k)] < 0)
      l.root = k;
    else
      l.children[size_t(s.parents[size_t(k)])].push_back(k);
    l.position[size_t(k)] = s.parents[size_t(k)] < 0 || movesAwayFromRest(a, clip, k);
  }
  depthFirst(l, l.root);
  l.scale = cm ? 100.0 : 1.0;
  l.decimals = cm ? 6 : 8;
  return l;
}

// BVH names are one word: refuse blanks, braces and empty names.
Status checkNames(const Skeleton& s) {
  for (size_t k = 0; k < s.names.size(); ++k) {
    const std::string& n = s.names[k];
    if (n.empty() || n.find_first_of(" \t\r\n{}") != std::string::npos)
      return makeError("BVH writer: joint " + std::to_string(k) + " name '" + n +
                       "' is not one word (no blanks or braces)");
  }
  return Status();
}

std::string triple(const Eigen::Vector3d& v, const Layout& l) {
  return fixed(v.x() * l.scale, l.decimals) + " " + fixed(v.y() * l.scale, l.decimals) + " " +
         fixed(v.z() * l.scale, l.decimals);
}

void writeJoint(const Asset& a, const Layout& l, int k, int depth, std::string* out) {
  const std::string tab(size_t(depth), '\t');
  const Eigen::Vector3d offset = a.skeleton.rest_local.row(k).transpose();
  *out += tab + (k == l.root ? "ROOT " : "JOINT ") + a.skeleton.names[size_t(k)] + "\n";
  *out += tab + "{\n";
  *out += tab + "\tOFFSET " + triple(offset, l) + "\n";
  *out += tab + (l.position[size_t(k)]
                     ? "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
                     : "\tCHANNELS 3 Zrotation Xrotation Yrotation\n");
  for (int c : l.children[size_t(k)]) writeJoint(a, l, c, depth + 1, out);
  if (l.children[size_t(k)].empty()) {
    *out += tab + "\tEnd Site\n" + tab + "\t{\n";
    const Eigen::Vector3d site =
        k == l.root ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.5 * offset);
    *out += tab + "\t\tOFFSET " + triple(site, l) + "\n";
    *out += tab + "\t}\n";
  }
  *out += tab + "}\n";
}

// Joint k's position channels at frame f (its local translation).
Eigen::Vector3d positionAt(const Asset& a, const Layout& l, const AnimationClip* clip, int k,
                           size_t f) {
  if (!clip) return a.skeleton.rest_local.row(k).transpose();
  if (k == l.root)
    return clip->root_translation.empty() ? Eigen::Vector3d(a.skeleton.rest_local.row(k))
                                          : clip->root_translation[f];
  return clip->joint_translations[size_t(k)][f];
}

// One MOTION line; `previous` (per joint) keeps each joint's angles continuous.
std::string frameLine(const Asset& a, const Layout& l, const AnimationClip* clip, size_t f,
                      std::vector<EulerZxy>* previous) {
  std::string line;
  for (int k : l.order) {
    if (l.position[size_t(k)]) line += triple(positionAt(a, l, clip, k, f), l) + " ";
    const Eigen::Quaterniond q =
        clip ? clip->rotations[size_t(k)][f].cast<double>() : Eigen::Quaterniond::Identity();
    const EulerZxy e = eulerZxyNear(q, (*previous)[size_t(k)]);
    (*previous)[size_t(k)] = e;
    line += fixed(e.z * kRadiansToDegrees, 6) + " " + fixed(e.x * kRadiansToDegrees, 6) + " " +
            fixed(e.y * kRadiansToDegrees, 6) + " ";
  }
  line.back() = '\n';
  return line;
}

Status checkInput(const Asset& asset, const WriterOptions& options) {
  if (options.bvh_units != "m" && options.bvh_units != "cm")
    return makeError("BVH writer: units '" + options.bvh_units + "'; expected m or cm");
  if (asset.animations.size() > 1)
    return makeError("BVH writer: the asset has " + std::to_string(asset.animations.size()) +
                     " animations; a BVH file holds one");
  if (Status st = validateAsset(asset); !st) return st;  // the same rules for every writer
  if (asset.skeleton.names.empty()) return makeError("BVH writer: the skeleton has no joints");
  return checkNames(asset.skeleton);
}

struct BvhWriter : Writer {
  const char* name() const override { return "bvh"; }

  Result<std::string> serialize(const Asset& asset, const WriterOptions& options) const override {
    if (Status st = checkInput(asset, options); !st) return st.error();
    const AnimationClip* clip = asset.animations.empty() ? nullptr : &asset.animations.front();
    const Layout l = layoutOf(asset, clip, options.bvh_units == "cm");
    std::string out = "HIERARCHY\n";
    writeJoint(asset, l, l.root, 0, &out);
    const size_t frames = clip ? clip->times.size() : 1;
    out += "MOTION\nFrames: " + std::to_string(frames) + "\n";
    out += "Frame Time: " + fixed(1.0 / (clip ? clip->fps : kRestFps), 10) + "\n";
    std::vector<EulerZxy> previous(asset.skeleton.names.size());
    for (size_t f = 0; f < frames; ++f) out += frameLine(asset, l, clip, f, &previous);
    return out;
  }
};

}  // namespace

const Writer& bvhWriter() {
  static const BvhWriter writer;
  return writer;
}

}  // namespace smpl
