#include "exporter/animation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

#include "core/heap_trim.h"
#include "core/joint_names.h"
#include "core/math/rotation.h"
#include "exporter/dmpl_targets.h"
#include "exporter/expression_targets.h"

namespace smpl {
namespace {

// One resampled source position: frame index and blend fraction.
struct Sample {
  int frame;
  double t;
};

std::vector<Sample> resampleTimes(int first, int end, double fps_in, double fps_out) {
  std::vector<Sample> samples;
  const double duration = (end - 1 - first) / fps_in;
  const int count = static_cast<int>(std::floor(duration * fps_out + 1e-9)) + 1;
  for (int i = 0; i < count; ++i) {
    const double pos = first + i * fps_in / fps_out;
    int frame = std::min(static_cast<int>(std::floor(pos + 1e-9)), end - 1);
    samples.push_back({frame, std::max(0.0, pos - frame)});
  }
  return samples;
}

// Output frames of resampleTimes(), computed in double so that a tiny source
// rate or a large --fps cannot overflow the count, and charged to the memory
// budget (rotations, translation, time and morph weights per frame) before any
// of it is allocated.
Status chargeSamples(int first, int end, double fps_in, double fps_out, int joints,
                     Eigen::Index targets, const std::string& context, MemoryCharge* charge) {
  const double count = std::floor((end - 1 - first) / fps_in * fps_out + 1e-9) + 1;
  const double per_frame = joints * sizeof(Eigen::Quaterniond) + sizeof(Eigen::Vector3d) +
                           sizeof(double) + sizeof(Sample) +
                           static_cast<double>(targets) * sizeof(float);
  const double bytes = count * per_frame;
  const std::string what = "resampling " + std::to_string(end - first) + " frames to " +
                           std::to_string(static_cast<long long>(std::min(count, 9e18))) +
                           " frames";
  if (count > 2147483647.0 || bytes > 1.8e19) return checkMemory(UINT64_MAX, context, what);
  return charge->add(static_cast<uint64_t>(bytes), context, what);
}

Eigen::Quaterniond rotationAt(const Motion& m, int source_joint, const Sample& s) {
  Eigen::Quaterniond a(m.frames[s.frame][source_joint]);
  if (s.t < 1e-12 || s.frame + 1 >= static_cast<int>(m.frames.size())) return a.normalized();
  Eigen::Quaterniond b(m.frames[s.frame + 1][source_joint]);
  return slerp(a.normalized(), s.t, b.normalized());
}

Eigen::Vector3d translationAt(const Motion& m, const Sample& s) {
  if (s.frame + 1 >= static_cast<int>(m.translation.size())) return m.translation[s.frame];
  return (1 - s.t) * m.translation[s.frame] + s.t * m.translation[s.frame + 1];
}

// The frame change of the sample (Motion::world_rotation/world_translation):
// slerp / lerp between source frames; identity when the motion has none.
void frameChangeAt(const Motion& m, const Sample& s, Eigen::Matrix3d* a, Eigen::Vector3d* b) {
  *a = Eigen::Matrix3d::Identity();
  *b = Eigen::Vector3d::Zero();
  if (m.world_rotation.empty()) return;
  const int next = std::min(s.frame + 1, static_cast<int>(m.world_rotation.size()) - 1);
  const Eigen::Quaterniond q0(m.world_rotation[s.frame]), q1(m.world_rotation[next]);
  *a = slerp(q0.normalized(), s.t, q1.normalized()).toRotationMatrix();
  *b = (1 - s.t) * m.world_translation[s.frame] + s.t * m.world_translation[next];
}

// The key stored for `q`: its sign flipped when that keeps it on the short
// path from the previous key (LINEAR interpolation in engines), `previous`
// updated, then normalised in double and rounded to float once.
Eigen::Quaternionf trackKey(Eigen::Quaterniond q, Eigen::Quaterniond* previous, bool first) {
  if (!first && q.dot(*previous) < 0) q.coeffs() *= -1.0;
  *previous = q;
  const double n = q.norm();
  return Eigen::Quaternionf(float(q.w() / n), float(q.x() / n), float(q.y() / n), float(q.z() / n));
}

Status checkFrames(const Motion& motion, const AnimationOptions& o, const std::string& context,
                   int* end) {
  const int total = static_cast<int>(motion.frames.size());
  *end = o.end_frame < 0 ? total : o.end_frame;
  if (o.first_frame < 0 || o.first_frame >= *end || *end > total)
    return makeError(context + ": --frames " + std::to_string(o.first_frame) + ":" +
                     std::to_string(*end) + " is outside the motion's " + std::to_string(total) +
                     " frames");
  return Status();
}

// Morph target index of each corrective layout entry, then of each basis
// target (by name: the layout is the contract).
std::vector<int> correctiveTargets(const Asset& asset) {
  std::map<std::string, int> index;
  for (size_t i = 0; i < asset.mesh.morph_targets.size(); ++i)
    index[asset.mesh.morph_targets[i].name] = static_cast<int>(i);
  std::vector<int> targets;
  for (const CorrectiveLayout& c : asset.metadata.correctives)
    targets.push_back(index.at(c.target));
  for (const std::string& name : asset.metadata.corrective_basis.targets)
    targets.push_back(index.at(name));
  return targets;
}

// Weight of each morph target per frame: correctives get scale * f + offset,
// basis targets scale_k (C f)_k + offset_k; others stay 0.
void fillMorphWeights(const Asset& asset, const std::vector<int>& targets,
                      const Rotations& rotations, MorphWeightTrack* weights, int frame) {
  const Eigen::VectorXd f = poseFeatures(rotations);
  const auto& correctives = asset.metadata.correctives;
  for (size_t i = 0; i < correctives.size(); ++i) {
    const CorrectiveLayout& c = correctives[i];
    const double w = c.scale * f[c.feature] + c.offset;
    (*weights)(frame, targets[i]) = static_cast<float>(c.rectified ? std::max(0.0, w) : w);
  }
  const CorrectiveBasis& basis = asset.metadata.corrective_basis;
  if (basis.targets.empty()) return;
  const Eigen::VectorXd w = basis.projection * f;
  for (size_t k = 0; k < basis.targets.size(); ++k)
    (*weights)(frame, targets[correctives.size() + k]) =
        static_cast<float>(basis.scale[k] * w[k] + basis.offset[k]);
}

// "y", "z", "-y": how the clip's world was turned (the metadata's clip source).
const char* worldName(UpAxis up, MotionWorld world) {
  if (up == UpAxis::Auto)
    up = world == MotionWorld::Z             ? UpAxis::Z
         : world == MotionWorld::CameraYDown ? UpAxis::NegY
                                             : UpAxis::Y;
  return up == UpAxis::Z ? "z" : up == UpAxis::NegY ? "-y" : "y";
}

// The notes that concern the clip as baked: the expression (what was dropped,
// what fixed joints cost).
void clipNotes(const BodyModel& model, const Asset& asset, const Motion& motion,
               AnimationClip* clip) {
  const int baked = static_cast<int>(asset.metadata.expression_targets.targets.size());
  int exported = 0;
  for (const MorphTarget& t : asset.mesh.morph_targets) exported += t.name.rfind("expr_", 0) == 0;
  for (std::string& note : expressionNotes(motion, exported, model.numExpressions()))
    clip->notes.push_back(std::move(note));
  if (baked == 0 || motion.expression.rows() == 0) return;
  char text[300];
  std::snprintf(text, sizeof text,
                "%s: the expression is baked with the betas-only skeleton (fixed joints); against "
                "the authors' math, where the joints follow the expression, this costs up to "
                "%.3f mm",
                clip->name.c_str(), clip->expression_joint_error * 1000);
  clip->notes.push_back(text);
}

// The rest mid-point p of Motion::translation_anchor's joints (BEV's hips),
// J from the export's betas; J_0 when the motion has no anchor.
Result<Eigen::Vector3d> anchorPoint(const BodyModel& model, const Asset& asset,
                                    const Motion& motion, const std::string& context) {
  const Eigen::MatrixXd& joints = asset.skeleton.rest_world;
  if (motion.translation_anchor.empty()) return Eigen::Vector3d(joints.row(0).transpose());
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (const std::string& name : motion.translation_anchor) {
    const auto it = std::find(model.joint_names.begin(), model.joint_names.end(), name);
    if (it == model.joint_names.end())
      return makeError(context + ": the translation is anchored at the joint '" + name +
                       "', which the model " + model.name + " does not have");
    p += joints.row(it - model.joint_names.begin()).transpose();
  }
  return Eigen::Vector3d(p / static_cast<double>(motion.translation_anchor.size()));
}

// Frees the decoded frames [*freed, keep) of `m` (no later sample reads
// them) and, every 1024 output frames, hands the freed pages back
// (heap_trim.h), so that a long clip's frames and tracks are not whole in
// memory together.
void releasePassedFrames(int keep, int sample, int* freed, Motion* m) {
  for (; *freed < keep; ++*freed) Rotations().swap(m->frames[size_t(*freed)]);
  if (sample % 1024 == 1023) returnFreedHeap();
}

}  // namespace

Eigen::Matrix3d worldTurn(UpAxis up, MotionWorld world) {
  const std::string name = worldName(up, world);
  if (name == "z") return axisAngleMatrix(-M_PI / 2, Eigen::Vector3d::UnitX());
  if (name == "-y") return Eigen::Vector3d(1, -1, -1).asDiagonal();
  return Eigen::Matrix3d::Identity();
}

Result<MotionMapping> mapMotion(const BodyModel& model, const Motion& motion,
                                const std::string& context) {
  const std::vector<std::string>& source = canonicalJointNames(motion.layout);
  std::map<std::string, int> index;
  for (size_t i = 0; i < source.size(); ++i)
    index[canonicalJointName(source[i])] = static_cast<int>(i);
  MotionMapping m;
  std::vector<bool> used(source.size(), false);
  for (const std::string& name : model.joint_names) {
    auto it = index.find(canonicalJointName(name));  // either eye spelling matches
    m.source_of_joint.push_back(it == index.end() ? -1 : it->second);
    if (it == index.end())
      m.missing.push_back(name);
    else
      used[it->second] = true;
  }
  for (size_t i = 0; i < source.size(); ++i)
    if (!used[i]) m.dropped.push_back(source[i]);
  if (m.source_of_joint[0] < 0)
    return makeError(context + ": a " + modelKindName(motion.layout) + " motion cannot drive a " +
                     modelKindName(model.kind) + " model (no common root joint)");
  return m;
}

Result<AnimationClip> bakeAnimation(const BodyModel& model, const Asset& asset,
                                    const Motion& motion, const AnimationOptions& o,
                                    const std::string& context, const Progress& progress,
                                    Motion* release) {
  if (release && release != &motion)
    return makeError(context + ": release is not the motion baked");
  int end = 0;
  if (Status s = checkFrames(motion, o, context, &end); !s) return s.error();
  Result<MotionMapping> mapping = mapMotion(model, motion, context);
  if (!mapping) return mapping.error();
  const double fps = o.fps ? *o.fps : motion.fps;
  AnimationClip clip;
  if (Status st = chargeSamples(o.first_frame, end, motion.fps, fps, model.numJoints(),
                                static_cast<Eigen::Index>(asset.mesh.morph_targets.size()), context,
                                &clip.charge);
      !st)
    return st.error();
  const std::vector<Sample> samples = resampleTimes(o.first_frame, end, motion.fps, fps);
  // A Z-up capture world or a camera frame -> Y-up output: the whole body turns.
  const Eigen::Matrix3d up = worldTurn(o.up, motion.world);
  const int k = model.numJoints(), t = static_cast<int>(samples.size());
  const int expressions = static_cast<int>(asset.metadata.expression_targets.targets.size());
  const Eigen::Vector3d j0 = asset.skeleton.rest_world.row(0).transpose();
  Result<Eigen::Vector3d> anchor = anchorPoint(model, asset, motion, context);
  if (!anchor) return anchor.error();
  clip.name = motion.name;
  clip.fps = fps;
  clip.source = ClipSource{motion.source_layout, motion.track, motion.first_frame + o.first_frame,
                           motion.first_frame + end, worldName(o.up, motion.world)};
  clip.dropped_joints = mapping->dropped;
  // The tracks are allocated untouched and filled frame by frame, so that
  // with `release` their pages fill as the decoded frames' pages are freed.
  clip.rotations.resize(k);
  for (auto& track : clip.rotations) track.resize(t);  // Quaternionf(): no initialisation
  std::vector<Eigen::Quaterniond> previous(k);         // each joint's last key, in double
  clip.morph_weights.resize(t, static_cast<Eigen::Index>(asset.mesh.morph_targets.size()));
  clip.times.reserve(t);
  clip.root_translation.reserve(t);
  int freed = o.first_frame;  // with `release`: frames below this one are freed
  const std::vector<int> targets = correctiveTargets(asset);
  Rotations local(k);
  Eigen::Matrix3d source_root = Eigen::Matrix3d::Identity();  // R_0 before the world turn
  for (int i = 0; i < t; ++i) {
    clip.times.push_back(i / fps);
    Eigen::Matrix3d change;  // the layout's per-frame frame change, then the world turn
    Eigen::Vector3d shift;
    frameChangeAt(motion, samples[i], &change, &shift);
    const Eigen::Matrix3d turn = up * change;
    for (int j = 0; j < k; ++j) {
      const int src = mapping->source_of_joint[j];
      Eigen::Quaterniond q =
          src < 0 ? Eigen::Quaterniond::Identity() : rotationAt(motion, src, samples[i]);
      if (j == 0) source_root = q.toRotationMatrix();
      if (j == 0) q = Eigen::Quaterniond(turn) * q;
      clip.rotations[j][i] = trackKey(q, &previous[j], i == 0);
      local[j] = q.toRotationMatrix();
    }
    // The root node sits at J_0 + trans in the capture world (an anchored
    // translation places the anchor instead: trans - R_0 (p - J_0)); rotate it with the world.
    const Eigen::Vector3d node =
        motion.translation_anchor.empty()
            ? Eigen::Vector3d(j0 + translationAt(motion, samples[i]))
            : Eigen::Vector3d(translationAt(motion, samples[i]) - source_root * (*anchor - j0));
    Eigen::Vector3d root = up * (change * node + shift);
    if (o.in_place) root = Eigen::Vector3d(j0.x(), root.y(), j0.z());
    clip.root_translation.push_back(root);
    clip.morph_weights.row(i).setZero();
    fillMorphWeights(asset, targets, local, &clip.morph_weights, i);
    if (const int d = static_cast<int>(asset.metadata.dmpl.targets.size());
        d > 0)  // DMPL soft tissue (dmpl_targets.h)
      if (Status st = applyDmplFrame(asset, dmplAt(motion, samples[i].frame, samples[i].t, d),
                                     local, turn, i, &clip);
          !st)
        return st.error();
    if (expressions > 0)  // animated SMPL-X expression (expression_targets.h)
      applyExpressionFrame(asset,
                           expressionAt(motion, samples[i].frame, samples[i].t,
                                        model.numExpressions(), asset.metadata.expression),
                           local, turn, i, &clip);
    if (progress && (i % 256 == 0 || i + 1 == t)) progress(double(i + 1) / t);
    if (release) releasePassedFrames(i + 1 < t ? samples[i + 1].frame : end, i, &freed, release);
  }
  clipNotes(model, asset, motion, &clip);
  return clip;
}

}  // namespace smpl
