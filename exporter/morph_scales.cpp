#include "exporter/morph_scales.h"

#include <set>
#include <string>

namespace smpl {

namespace {
float peak(const MorphTarget& t) { return t.deltas.size() ? t.deltas.cwiseAbs().maxCoeff() : 0.f; }
}  // namespace

std::vector<bool> quantizedTargets(const Asset& asset) {
  std::set<std::string> correctives;  // per-feature targets and --corrective-basis targets
  for (const CorrectiveLayout& c : asset.metadata.correctives) correctives.insert(c.target);
  for (const std::string& name : asset.metadata.corrective_basis.targets) correctives.insert(name);
  std::vector<bool> q;
  q.reserve(asset.mesh.morph_targets.size());
  for (const MorphTarget& t : asset.mesh.morph_targets)
    q.push_back(correctives.count(t.name) && peak(t) > 0);
  return q;
}

std::vector<double> morphWeightScales(const Asset& asset) {
  const std::vector<bool> q = quantizedTargets(asset);
  std::vector<double> s(q.size(), 1.0);
  for (size_t n = 0; n < q.size(); ++n)
    if (q[n]) s[n] = double(peak(asset.mesh.morph_targets[n]));
  return s;
}

void foldScalesIntoMetadata(const std::vector<double>& s, const SkinnedMesh& mesh,
                            AssetMetadata* metadata) {
  for (CorrectiveLayout& c : metadata->correctives)
    for (size_t n = 0; n < mesh.morph_targets.size() && n < s.size(); ++n)
      if (mesh.morph_targets[n].name == c.target) {
        c.scale *= s[n];
        c.offset *= s[n];
        break;
      }
  CorrectiveBasis& basis = metadata->corrective_basis;
  for (size_t k = 0; k < basis.targets.size() && k < basis.scale.size() && k < basis.offset.size();
       ++k)
    for (size_t n = 0; n < mesh.morph_targets.size() && n < s.size(); ++n)
      if (mesh.morph_targets[n].name == basis.targets[k]) {
        basis.scale[k] *= s[n];
        basis.offset[k] *= s[n];
        break;
      }
}

void foldMorphScales(Asset* asset) {
  const std::vector<double> s = morphWeightScales(*asset);
  const std::vector<bool> q = quantizedTargets(*asset);
  foldScalesIntoMetadata(s, asset->mesh, &asset->metadata);
  for (size_t n = 0; n < s.size(); ++n) {
    MorphTarget& t = asset->mesh.morph_targets[n];
    t.quantized = t.quantized || q[n];
    if (s[n] == 1.0) continue;
    t.deltas /= float(s[n]);
    t.peak *= s[n];
    t.rest_weight = float(t.rest_weight * s[n]);
    for (AnimationClip& clip : asset->animations)
      if (clip.morph_weights.cols() == Eigen::Index(s.size()))
        clip.morph_weights.col(Eigen::Index(n)) *= float(s[n]);
  }
}

}  // namespace smpl
