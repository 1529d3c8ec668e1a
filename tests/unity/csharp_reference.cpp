// Reference data for the C# runtime test (unity/Tests): for a few random poses
// of each model, the local rotations R_k, the features poseFeatures(R) of
// core/math/forward.h, and the world rotations of the bones as Unity would report
// them for two imported skeletons:
//   identity_rest: bones with identity rest orientation, Unity axes
//                  (C = mirror X: model (x,y,z) -> Unity (-x,y,z)), so the
//                  world rotation is M G_k M with M = diag(-1,1,1);
//   bind_rest:     bones with a random fixed bind orientation B_k, as FBX
//                  importers produce: world rotation M G_k M B_k, rest B_k.
// G_k = G_p(k) R_k are the model's world rotations (rest: identity).
// Quaternions are written in Unity's order (x, y, z, w).
// Also, per model, the metadata of a --corrective-basis 16 (unit weights)
// export ("basis_sidecar", the exporter's own serialiser) and per pose the
// weights it defines, scale_k (C f)_k + offset_k ("basis_weights").
//
// usage: smpl-csharp-reference OUT.json MODEL...
#include <Eigen/Geometry>
#include <cstdio>
#include <string>
#include <vector>

#include "core/load/model_loader.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "exporter/metadata_json.h"
#include "exporter/pipeline.h"

namespace {

using smpl::Rotations;

const Eigen::Matrix3d kMirrorX = Eigen::Vector3d(-1, 1, 1).asDiagonal();

void writeNumbers(std::FILE* out, const double* v, size_t n) {
  std::fputc('[', out);
  for (size_t i = 0; i < n; ++i) std::fprintf(out, "%s%.17g", i ? "," : "", v[i]);
  std::fputc(']', out);
}

void writeString(std::FILE* out, const std::string& s) {
  std::fputc('"', out);
  for (char c : s) {
    if (c == '"' || c == '\\') std::fputc('\\', out);
    if (static_cast<unsigned char>(c) >= 0x20) std::fputc(c, out);
  }
  std::fputc('"', out);
}

void writeQuaternions(std::FILE* out, const Rotations& rotations) {
  std::fputc('[', out);
  for (size_t k = 0; k < rotations.size(); ++k) {
    Eigen::Quaterniond q(rotations[k]);
    const double v[4] = {q.x(), q.y(), q.z(), q.w()};
    if (k) std::fputc(',', out);
    writeNumbers(out, v, 4);
  }
  std::fputc(']', out);
}

Rotations worldRotations(const std::vector<int>& parents, const Rotations& local) {
  Rotations world(local.size());
  for (size_t k = 0; k < local.size(); ++k)
    world[k] = parents[k] < 0 ? local[k] : Eigen::Matrix3d(world[parents[k]] * local[k]);
  return world;
}

// world rotations as Unity reports them: M G_k M B_k (B_k = I for identity rest).
Rotations engineRotations(const Rotations& world, const Rotations& bind) {
  Rotations out(world.size());
  for (size_t k = 0; k < world.size(); ++k) out[k] = kMirrorX * world[k] * kMirrorX * bind[k];
  return out;
}

void writePose(std::FILE* out, const smpl::BodyModel& model, const Eigen::VectorXd& axis_angle,
               const Rotations& bind, const smpl::CorrectiveBasis& basis) {
  const Rotations local = smpl::rotationsFromAxisAngle(axis_angle);
  const Eigen::VectorXd features = smpl::poseFeatures(local);
  const Rotations world = worldRotations(model.parents, local);
  const Rotations identity(local.size(), Eigen::Matrix3d::Identity());
  std::fprintf(out, "{\"axis_angle\":");
  writeNumbers(out, axis_angle.data(), axis_angle.size());
  std::fprintf(out, ",\"local_rotations\":[");
  for (size_t k = 0; k < local.size(); ++k) {
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = local[k];
    if (k) std::fputc(',', out);
    writeNumbers(out, r.data(), 9);
  }
  std::fprintf(out, "],\"features\":");
  writeNumbers(out, features.data(), features.size());
  std::fprintf(out, ",\"identity_rest_world\":");
  writeQuaternions(out, engineRotations(world, identity));
  std::fprintf(out, ",\"bind_rest_world\":");
  writeQuaternions(out, engineRotations(world, bind));
  Eigen::VectorXd weights = basis.projection * features;
  for (Eigen::Index k = 0; k < weights.size(); ++k)
    weights(k) = basis.scale[k] * weights(k) + basis.offset[k];
  std::fprintf(out, ",\"basis_weights\":");
  writeNumbers(out, weights.data(), weights.size());
  std::fprintf(out, "}");
}

bool writeModel(std::FILE* out, const std::string& path, uint64_t seed) {
  smpl::Result<smpl::BodyModel> model = smpl::loadModel(path);
  if (!model) {
    std::fprintf(stderr, "Error loading %s: %s\n", path.c_str(), model.message().c_str());
    return false;
  }
  smpl::Result<smpl::ShapedBody> shaped = smpl::shapeBody(*model, Eigen::VectorXd());
  if (!shaped) {
    std::fprintf(stderr, "Error shaping %s: %s\n", path.c_str(), shaped.message().c_str());
    return false;
  }
  const int k = model->numJoints();
  // Moderate poses, then large ones (angles near pi exercise the quaternion sign).
  std::vector<Eigen::VectorXd> poses = smpl::samplePoses(k, 6, seed, 0.6);
  for (const Eigen::VectorXd& p : smpl::samplePoses(k, 2, seed + 1, 2.5)) poses.push_back(p);
  const Rotations bind = smpl::rotationsFromAxisAngle(smpl::samplePoses(k, 1, seed + 2, 3.0)[0]);
  smpl::ExportOptions options;
  options.corrective_basis = 16;
  options.encoding = smpl::CorrectiveEncoding::Unit;
  smpl::Result<smpl::Asset> asset = smpl::buildAsset(*model, options);
  if (!asset) {
    std::fprintf(stderr, "Error exporting %s: %s\n", path.c_str(), asset.message().c_str());
    return false;
  }

  std::fprintf(out, "{\"name\":");
  writeString(out, path.substr(path.find_last_of('/') + 1));
  std::fprintf(out, ",\"joint_names\":[");
  for (int j = 0; j < k; ++j) {
    if (j) std::fputc(',', out);
    writeString(out, model->joint_names[j]);
  }
  std::fprintf(out, "],\"parents\":[");
  for (int j = 0; j < k; ++j) std::fprintf(out, "%s%d", j ? "," : "", model->parents[j]);
  std::fprintf(out, "],\"rest_joints\":[");
  for (int j = 0; j < k; ++j) {
    const double v[3] = {shaped->joints(j, 0), shaped->joints(j, 1), shaped->joints(j, 2)};
    if (j) std::fputc(',', out);
    writeNumbers(out, v, 3);
  }
  std::fprintf(out, "],\"axis_map\":");
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> axis = kMirrorX;
  writeNumbers(out, axis.data(), 9);
  std::fprintf(out, ",\"bind_rest\":");
  writeQuaternions(out, bind);
  std::fprintf(out, ",\"basis_sidecar\":");
  writeString(out, smpl::metadataJson(*asset));
  std::fprintf(out, ",\"poses\":[");
  for (size_t i = 0; i < poses.size(); ++i) {
    if (i) std::fputc(',', out);
    writePose(out, *model, poses[i], bind, asset->metadata.corrective_basis);
  }
  std::fprintf(out, "]}");
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s OUT.json MODEL...\n", argv[0]);
    return 2;
  }
  const std::string out_path = argv[1];
  const std::string tmp_path = out_path + ".tmp";
  std::FILE* out = std::fopen(tmp_path.c_str(), "wb");
  if (!out) {
    std::fprintf(stderr, "Error writing %s: cannot open\n", tmp_path.c_str());
    return 4;
  }
  std::fprintf(out, "{\"models\":[");
  bool ok = true;
  for (int i = 2; i < argc && ok; ++i) {
    if (i > 2) std::fputc(',', out);
    ok = writeModel(out, argv[i], 1000 + 17 * i);
  }
  std::fprintf(out, "]}\n");
  ok = std::fclose(out) == 0 && ok;
  if (!ok || std::rename(tmp_path.c_str(), out_path.c_str()) != 0) {
    std::remove(tmp_path.c_str());
    return ok ? 4 : 3;
  }
  return 0;
}
