// The asset as a .usda layer (usd_layer.h).
#include "writers/usd/usd_layer.h"

#include <cmath>
#include <set>
#include <vector>

#include "exporter/metadata_json.h"
#include "exporter/validate_asset.h"
#include "writers/usd/usd_text.h"

namespace smpl {
namespace {

using usd::appendFloat;
using usd::appendFloat3;

Status nameError(const char* what, const std::string& name, const char* problem) {
  return makeError(std::string("USD writer: ") + what + " name " + usd::quoted(name) + " " +
                   problem);
}

Status checkNames(const Asset& asset) {
  std::set<std::string> joints, targets;
  const Skeleton& s = asset.skeleton;
  for (size_t k = 0; k < s.names.size(); ++k) {
    if (!usd::isIdentifier(s.names[k]))
      return nameError("joint", s.names[k], "is not a USD identifier ([A-Za-z_][A-Za-z0-9_]*)");
    if (!joints.insert(s.names[k]).second) return nameError("joint", s.names[k], "is not unique");
    if (s.parents[k] >= int(k))  // UsdSkel: a joint's parent comes before it
      return nameError("joint", s.names[k], "comes before its parent");
  }
  for (const MorphTarget& t : asset.mesh.morph_targets) {
    if (!usd::isIdentifier(t.name))
      return nameError("morph target", t.name, "is not a USD identifier ([A-Za-z_][A-Za-z0-9_]*)");
    if (!targets.insert(t.name).second) return nameError("morph target", t.name, "is not unique");
    if (t.quantized)
      return nameError("morph target", t.name, "is quantized (glTF only): USD stores metres");
  }
  return Status();
}

Status checkInput(const Asset& asset) {
  if (asset.animations.size() > 1)
    return makeError("USD writer: the asset has " + std::to_string(asset.animations.size()) +
                     " animations; a UsdSkel body binds one");
  if (Status st = validateAsset(asset); !st) return st;
  if (asset.skeleton.names.empty()) return makeError("USD writer: the skeleton has no joints");
  if (asset.mesh.positions.rows() == 0) return makeError("USD writer: the asset has no mesh");
  if (Status st = checkNames(asset); !st) return st;
  if (!asset.animations.empty()) {
    const AnimationClip& c = asset.animations.front();
    for (size_t f = 0; f < c.times.size(); ++f)
      if (std::abs(c.times[f] * c.fps - double(f)) > 1e-6)
        return makeError("USD writer: animation " + c.name + " frame " + std::to_string(f) +
                         " is not at time code " + std::to_string(f) + " of " +
                         std::to_string(c.fps) + " fps");
  }
  return Status();
}

// "pelvis/left_hip/left_knee": joint k's path token (UsdSkel joint order).
std::vector<std::string> jointPaths(const Skeleton& s) {
  std::vector<std::string> paths(s.names.size());
  for (size_t k = 0; k < s.names.size(); ++k)
    paths[k] = s.parents[k] < 0 ? s.names[k] : paths[size_t(s.parents[k])] + "/" + s.names[k];
  return paths;
}

void appendTokens(std::string& out, const std::vector<std::string>& tokens) {
  out += '[';
  for (size_t i = 0; i < tokens.size(); ++i) out += (i ? ", " : "") + usd::quoted(tokens[i]);
  out += ']';
}

std::vector<std::string> targetNames(const SkinnedMesh& m) {
  std::vector<std::string> names;
  for (const MorphTarget& t : m.morph_targets) names.push_back(t.name);
  return names;
}

void appendHeader(std::string& out, const Asset& asset) {
  out += "#usda 1.0\n(\n    customLayerData = {\n        string smpl_export = ";
  out += usd::quoted(metadataJson(asset)) + "\n    }\n";
  out += "    defaultPrim = \"Body\"\n";
  if (!asset.animations.empty()) {
    const AnimationClip& c = asset.animations.front();
    out += "    endTimeCode = " + std::to_string(c.times.empty() ? 0 : c.times.size() - 1) + "\n";
  }
  out += "    metersPerUnit = 1\n";
  if (!asset.animations.empty()) {
    out += "    startTimeCode = 0\n    timeCodesPerSecond = ";
    usd::appendDouble(out, asset.animations.front().fps);
    out += "\n";
  }
  out += "    upAxis = \"Y\"\n)\n\n";
}

// One frame's local joint translations: the clip's root and joint tracks,
// else the rest offsets.
Eigen::Vector3d localTranslation(const Asset& a, const AnimationClip* clip, size_t k, size_t f) {
  if (clip && k == 0 && !clip->root_translation.empty()) return clip->root_translation[f];
  if (clip && k < clip->joint_translations.size() && !clip->joint_translations[k].empty())
    return clip->joint_translations[k][f];
  return a.skeleton.rest_local.row(Eigen::Index(k)).transpose();
}

void appendRotations(std::string& out, const Asset& a, const AnimationClip* clip, size_t f) {
  out += '[';
  for (size_t k = 0; k < a.skeleton.names.size(); ++k) {
    if (k) out += ", ";
    usd::appendQuat(out, clip ? clip->rotations[k][f] : Eigen::Quaternionf::Identity());
  }
  out += ']';
}

void appendTranslations(std::string& out, const Asset& a, const AnimationClip* clip, size_t f) {
  out += '[';
  for (size_t k = 0; k < a.skeleton.names.size(); ++k) {
    const Eigen::Vector3d t = localTranslation(a, clip, k, f);
    if (k) out += ", ";
    appendFloat3(out, float(t.x()), float(t.y()), float(t.z()));
  }
  out += ']';
}

void appendWeights(std::string& out, const Asset& a, const AnimationClip* clip, size_t f) {
  const std::vector<MorphTarget>& targets = a.mesh.morph_targets;
  out += '[';
  for (size_t i = 0; i < targets.size(); ++i) {
    if (i) out += ", ";
    appendFloat(
        out, clip ? clip->morph_weights(Eigen::Index(f), Eigen::Index(i)) : targets[i].rest_weight);
  }
  out += ']';
}

using FrameWriter = void (*)(std::string&, const Asset&, const AnimationClip*, size_t);

// `type name.timeSamples = { 0: [...], ... }`, or without a clip `type name = [...]`.
void appendAnimated(std::string& out, const char* declaration, FrameWriter frame, const Asset& a,
                    const AnimationClip* clip) {
  out += "            ";
  out += declaration;
  if (!clip) {
    out += " = ";
    frame(out, a, nullptr, 0);
    out += "\n";
    return;
  }
  out += ".timeSamples = {\n";
  for (size_t f = 0; f < clip->times.size(); ++f) {
    out += "                " + std::to_string(f) + ": ";
    frame(out, a, clip, f);
    out += ",\n";
  }
  out += "            }\n";
}

void appendAnimation(std::string& out, const Asset& a, const std::vector<std::string>& paths) {
  const AnimationClip* clip = a.animations.empty() ? nullptr : &a.animations.front();
  out += "        def SkelAnimation \"Motion\"\n        {\n            uniform token[] joints = ";
  appendTokens(out, paths);
  out += "\n            uniform token[] blendShapes = ";
  appendTokens(out, targetNames(a.mesh));
  out += "\n";
  appendAnimated(out, "quatf[] rotations", appendRotations, a, clip);
  appendAnimated(out, "float3[] translations", appendTranslations, a, clip);
  out += "            half3[] scales = [";
  for (size_t k = 0; k < paths.size(); ++k) out += k ? ", (1, 1, 1)" : "(1, 1, 1)";
  out += "]\n";
  appendAnimated(out, "float[] blendShapeWeights", appendWeights, a, clip);
  out += "        }\n";
}

void appendMatrices(std::string& out, const Eigen::MatrixXd& translations) {
  out += '[';
  for (Eigen::Index k = 0; k < translations.rows(); ++k) {
    if (k) out += ", ";
    usd::appendTranslationMatrix(out, translations.row(k).transpose());
  }
  out += ']';
}

void appendSkeleton(std::string& out, const Asset& a) {
  const std::vector<std::string> paths = jointPaths(a.skeleton);
  out +=
      "    def Skeleton \"Skeleton\" (\n        prepend apiSchemas = [\"SkelBindingAPI\"]\n"
      "    )\n    {\n        uniform token[] joints = ";
  appendTokens(out, paths);
  out += "\n        uniform token[] jointNames = ";
  appendTokens(out, a.skeleton.names);
  out += "\n        uniform matrix4d[] bindTransforms = ";
  appendMatrices(out, a.skeleton.rest_world);
  out += "\n        uniform matrix4d[] restTransforms = ";
  appendMatrices(out, a.skeleton.rest_local);
  out += "\n        rel skel:animationSource = </Body/Skeleton/Motion>\n\n";
  appendAnimation(out, a, paths);
  out += "    }\n\n";
}

void appendRows3(std::string& out, const Eigen::MatrixXf& rows) {
  out += '[';
  for (Eigen::Index v = 0; v < rows.rows(); ++v) {
    if (v) out += ", ";
    appendFloat3(out, rows(v, 0), rows(v, 1), rows(v, 2));
  }
  out += ']';
}

void appendUvs(std::string& out, const Eigen::MatrixXf& uvs) {
  out += "        texCoord2f[] primvars:st = [";
  for (Eigen::Index v = 0; v < uvs.rows(); ++v) {
    out += v ? ", (" : "(";
    appendFloat(out, uvs(v, 0));
    out += ", ";
    appendFloat(out, uvs(v, 1));
    out += ')';
  }
  out += "] (\n            interpolation = \"vertex\"\n        )\n";
}

void appendTopology(std::string& out, const SkinnedMesh& m) {
  out += "        int[] faceVertexCounts = [";
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f) out += f ? ", 3" : "3";
  out += "]\n        int[] faceVertexIndices = [";
  for (Eigen::Index f = 0; f < m.triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c) out += (f || c ? ", " : "") + std::to_string(m.triangles(f, c));
  out += "]\n";
}

void appendSkin(std::string& out, const SkinnedMesh& m) {
  const std::string element = std::to_string(m.joints.cols());
  out += "        int[] primvars:skel:jointIndices = [";
  for (Eigen::Index v = 0; v < m.joints.rows(); ++v)
    for (Eigen::Index i = 0; i < m.joints.cols(); ++i)
      out += (v || i ? ", " : "") + std::to_string(m.joints(v, i));
  out += "] (\n            elementSize = " + element +
         "\n            interpolation = \"vertex\"\n        )\n";
  out += "        float[] primvars:skel:jointWeights = [";
  for (Eigen::Index v = 0; v < m.weights.rows(); ++v)
    for (Eigen::Index i = 0; i < m.weights.cols(); ++i) {
      if (v || i) out += ", ";
      appendFloat(out, m.weights(v, i));
    }
  out += "] (\n            elementSize = " + element +
         "\n            interpolation = \"vertex\"\n        )\n";
  out +=
      "        matrix4d primvars:skel:geomBindTransform = "
      "((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))\n";
}

// A target's non-zero deltas as offsets at pointIndices (one zero offset at
// point 0 for an all-zero target: UsdSkel reads empty offsets as no shape).
void appendBlendShape(std::string& out, const MorphTarget& t) {
  std::string offsets, indices;
  for (Eigen::Index v = 0; v < t.deltas.rows(); ++v) {
    if (t.deltas(v, 0) == 0 && t.deltas(v, 1) == 0 && t.deltas(v, 2) == 0) continue;
    if (!indices.empty()) offsets += ", ", indices += ", ";
    appendFloat3(offsets, t.deltas(v, 0), t.deltas(v, 1), t.deltas(v, 2));
    indices += std::to_string(v);
  }
  if (indices.empty()) offsets = "(0, 0, 0)", indices = "0";
  out += "\n        def BlendShape " + usd::quoted(t.name) +
         "\n        {\n            uniform vector3f[] offsets = [" + offsets +
         "]\n            uniform int[] pointIndices = [" + indices + "]\n        }\n";
}

void appendBlendShapeBinding(std::string& out, const SkinnedMesh& m) {
  out += "        uniform token[] skel:blendShapes = ";
  appendTokens(out, targetNames(m));
  out += "\n        rel skel:blendShapeTargets = [";
  for (size_t i = 0; i < m.morph_targets.size(); ++i)
    out += (i ? ", </Body/Mesh/" : "</Body/Mesh/") + m.morph_targets[i].name + ">";
  out += "]\n";
}

void appendMesh(std::string& out, const Asset& a) {
  const SkinnedMesh& m = a.mesh;
  out +=
      "    def Mesh \"Mesh\" (\n        prepend apiSchemas = [\"SkelBindingAPI\"]\n"
      "    )\n    {\n        uniform bool doubleSided = 0\n        float3[] extent = [";
  const Eigen::RowVector3f lo = m.positions.colwise().minCoeff();
  const Eigen::RowVector3f hi = m.positions.colwise().maxCoeff();
  appendFloat3(out, lo.x(), lo.y(), lo.z());
  out += ", ";
  appendFloat3(out, hi.x(), hi.y(), hi.z());
  out += "]\n";
  appendTopology(out, m);
  out += "        normal3f[] normals = ";
  appendRows3(out, m.normals);
  out += " (\n            interpolation = \"vertex\"\n        )\n";
  out += "        uniform token orientation = \"rightHanded\"\n        point3f[] points = ";
  appendRows3(out, m.positions);
  out += "\n";
  if (m.uvs.rows() > 0) appendUvs(out, m.uvs);
  appendSkin(out, m);
  appendBlendShapeBinding(out, m);
  out += "        rel skel:skeleton = </Body/Skeleton>\n";
  out += "        uniform token subdivisionScheme = \"none\"\n";
  for (const MorphTarget& t : m.morph_targets) appendBlendShape(out, t);
  out += "    }\n";
}

}  // namespace

Result<std::string> usdaLayer(const Asset& asset) {
  if (Status st = checkInput(asset); !st) return st.error();
  std::string out;
  appendHeader(out, asset);
  out += "def SkelRoot \"Body\"\n{\n";
  appendSkeleton(out, asset);
  appendMesh(out, asset);
  out += "}\n";
  return out;
}

}  // namespace smpl
