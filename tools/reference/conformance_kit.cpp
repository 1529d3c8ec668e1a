// smpl-reference --conformance-kit: the cases of docs/conformance.md.
#include "tools/reference/conformance_kit.h"

#include <sys/stat.h>

#include <Eigen/Geometry>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

#include "core/io/file_io.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "exporter/export_asset.h"
#include "exporter/metadata_json.h"
#include "exporter/pipeline.h"
#include "tools/reference/kit_bad_sidecars.h"
#include "tools/reference/kit_json.h"

namespace smpl {
namespace {

/// How an importer delivers the bones: world rotation W_k = C G_k C^T B_k,
/// C model -> engine axes, B_k the bone's bind orientation (rest W_k = B_k).
struct KitFrame {
  std::string name;
  Eigen::Matrix3d axes;
  bool bind_rotated;  ///< false: B_k = I (bones at identity rest)
  std::string what;
  bool root_at_axes = false;  ///< B_0 = C: the root's rest orientation is the model frame
};

Eigen::Matrix3d rows(double a, double b, double c, double d, double e, double f, double g, double h,
                     double i) {
  Eigen::Matrix3d m;
  m << a, b, c, d, e, f, g, h, i;
  return m;
}

std::vector<KitFrame> kitFrames() {
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  return {
      {"identity_rest", id, false, "model axes, bones at identity rest (glTF importers)"},
      {"fbx_rotated", id, true,
       "model axes, bones with a fixed bind orientation (FBX pre-rotations)"},
      {"z_up", rows(1, 0, 0, 0, 0, -1, 0, 1, 0), true,
       "Z-up world, (x,y,z) -> (x,-z,y), bones rolled (Blender, Maya Z-up)"},
      {"unity_identity", rows(-1, 0, 0, 0, 1, 0, 0, 0, 1), false,
       "Unity's left-handed flip (x,y,z) -> (-x,y,z), bones at identity rest"},
      {"unity_bind", rows(-1, 0, 0, 0, 1, 0, 0, 0, 1), true,
       "Unity's left-handed flip, bones with a fixed bind orientation"},
      {"unreal", rows(1, 0, 0, 0, 0, 1, 0, 1, 0), true,
       "Unreal's FBX axes (x,y,z) -> (x,z,y), bones with a fixed bind orientation"},
      {"three_turned",
       Eigen::Matrix3d(Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, 1, -0.2).normalized())), true,
       "a character turned in the scene, its root at rest in the model frame, the other bones "
       "re-oriented "
       "(three.js loaders: the driver takes C from the root's rest)",
       true},
  };
}

/// Whether the root's rest world rotation (B_0) is C, as the three.js driver assumes.
bool rootRestIsAxes(const KitFrame& f) {
  return f.root_at_axes || (!f.bind_rotated && f.axes.isApprox(Eigen::Matrix3d::Identity(), 1e-15));
}

struct KitEncoding {
  std::string name;
  CorrectiveEncoding encoding;
  int basis;
  bool quantize;
};

std::vector<KitEncoding> kitEncodings() {
  return {{"signed", CorrectiveEncoding::Signed, 0, false},
          {"unit", CorrectiveEncoding::Unit, 0, false},
          {"split", CorrectiveEncoding::Split, 0, false},
          {"signed_quantized", CorrectiveEncoding::Signed, 0, true},
          {"basis", CorrectiveEncoding::Unit, 8, false}};
}

/// Expected weights: correctives in metadata order, then the basis rows.
std::vector<double> expectedWeights(const AssetMetadata& m, const Eigen::VectorXd& f) {
  std::vector<double> w;
  for (const CorrectiveLayout& c : m.correctives) {
    double v = c.scale * f[c.feature] + c.offset;
    w.push_back(c.rectified ? std::max(0.0, v) : v);
  }
  const CorrectiveBasis& b = m.corrective_basis;
  if (b.projection.rows() > 0) {
    Eigen::VectorXd p = b.projection * f;
    for (Eigen::Index k = 0; k < p.size(); ++k) w.push_back(b.scale[k] * p[k] + b.offset[k]);
  }
  return w;
}

Rotations worldOf(const std::vector<int>& parents, const Rotations& local) {
  Rotations world(local.size());
  for (size_t k = 0; k < local.size(); ++k)
    world[k] = parents[k] < 0 ? local[k] : Eigen::Matrix3d(world[parents[k]] * local[k]);
  return world;
}

/// Engine world rotations C G_k C^T B_k and the importer's local ones W_p^-1 W_k.
void engineRotations(const KitFrame& frame, const std::vector<int>& parents,
                     const Rotations& model_world, const Rotations& bind, Rotations* world,
                     Rotations* local) {
  const size_t n = model_world.size();
  world->resize(n);
  local->resize(n);
  for (size_t k = 0; k < n; ++k)
    (*world)[k] = frame.axes * model_world[k] * frame.axes.transpose() * bind[k];
  for (size_t k = 0; k < n; ++k)
    (*local)[k] = parents[k] < 0 ? (*world)[k]
                                 : Eigen::Matrix3d((*world)[parents[k]].transpose() * (*world)[k]);
}

struct KitPose {
  Eigen::VectorXd axis_angle;  ///< K x 3, model axes (what the features come from)
  Rotations world, local;
  Eigen::VectorXd features;
  std::vector<double> weights;
};

/// Unit quaternions (x, y, z, w), Hamilton convention, w >= 0.
void writeRotations(KitJson* j, const char* quats, const Rotations& r) {
  j->key(quats).beginArray();
  for (const Eigen::Matrix3d& m : r) {
    Eigen::Quaterniond q(m);
    if (q.w() < 0) q.coeffs() *= -1;  // one of the two signs, fixed: w >= 0
    j->numbers({q.x(), q.y(), q.z(), q.w()});
  }
  j->end();
}

std::string caseJson(const std::string& name, const KitFrame& frame, const KitEncoding& enc,
                     const Rotations& rest_world, const Rotations& rest_local,
                     const std::vector<KitPose>& poses) {
  KitJson j;
  j.beginObject();
  j.key("case").string(name).key("frame").string(frame.name).key("encoding").string(enc.name);
  j.key("sidecar").string(name + ".smpl.json");
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> axes = frame.axes;
  j.key("axes").numbers(std::vector<double>(axes.data(), axes.data() + 9));
  writeRotations(&j, "rest_world", rest_world);
  writeRotations(&j, "rest_local", rest_local);
  j.key("poses").beginArray();
  for (const KitPose& p : poses) {
    j.beginObject();
    j.key("axis_angle")
        .numbers(
            std::vector<double>(p.axis_angle.data(), p.axis_angle.data() + p.axis_angle.size()));
    writeRotations(&j, "world", p.world);
    writeRotations(&j, "local", p.local);
    j.key("features")
        .numbers(std::vector<double>(p.features.data(), p.features.data() + p.features.size()));
    j.key("weights").numbers(p.weights);
    j.end();
  }
  j.end();
  j.end();
  return j.text();
}

/// The one tolerance table (absolute, per quantity and precision).
void writeTolerances(KitJson* j) {
  j->key("tolerances").beginObject();
  for (const char* q : {"features", "weights"}) {
    j->key(q).beginObject().key("float64").number(1e-9).key("float32").number(1e-5).end();
  }
  j->end();
}

std::string manifestJson(const BodyModel& model, const std::vector<std::string>& cases,
                         const std::vector<std::string>& frames,
                         const std::vector<std::string>& encodings, int poses) {
  KitJson j;
  j.beginObject().key("kit_version").number(1).key("model_kind").string(modelKindName(model.kind));
  j.key("num_joints")
      .number(model.numJoints())
      .key("num_features")
      .number(9 * (model.numJoints() - 1));
  j.key("poses_per_case").number(poses);
  writeTolerances(&j);
  j.key("frames").beginArray();
  for (const KitFrame& f : kitFrames()) {
    Eigen::Matrix<double, 3, 3, Eigen::RowMajor> axes = f.axes;
    j.beginObject().key("name").string(f.name).key("what").string(f.what);
    j.key("axes").numbers(std::vector<double>(axes.data(), axes.data() + 9));
    j.key("bind_rotated")
        .boolean(f.bind_rotated)
        .key("root_rest_is_axes")
        .boolean(rootRestIsAxes(f));
    j.end();
  }
  j.end();
  j.key("cases").beginArray();
  for (size_t i = 0; i < cases.size(); ++i) {
    j.beginObject().key("name").string(cases[i]).key("frame").string(frames[i]);
    j.key("encoding").string(encodings[i]).key("sidecar").string(cases[i] + ".smpl.json");
    j.key("data").string(cases[i] + ".json").end();
  }
  j.end();
  j.key("bad").beginArray();
  for (const BadSidecar& b : badSidecars()) {
    j.beginObject().key("name").string(b.name).key("sidecar").string("bad/" + b.name +
                                                                     ".smpl.json");
    j.key("error").string(b.error).key("what").string(b.what);
    j.key("schema_rejects").boolean(b.schema).end();
  }
  j.end().end();
  return j.text();
}

std::string makeDir(const std::string& dir) {
  if (::mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
    return dir + ": cannot create the folder (" + std::strerror(errno) + ")";
  struct stat st;
  if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return dir + ": not a folder (a symbolic link or a file is refused)";
  return "";
}

std::string write(const std::string& path, const std::string& text) {
  Status st = writeFileAtomic(path, text);
  return st ? "" : path + ": " + st.message();
}

/// Applies --perturb CASE:features|weights to the poses of that case.
void perturb(const std::string& spec, const std::string& name, std::vector<KitPose>* poses) {
  if (spec == name + ":features") (*poses)[0].features[0] += 1e-3;
  if (spec == name + ":weights") (*poses)[0].weights[0] += 1e-3;
}

}  // namespace

std::string checkPerturb(const std::string& perturb) {
  bool known = perturb.empty();
  for (const KitEncoding& enc : kitEncodings())
    for (const KitFrame& frame : kitFrames())
      for (const char* what : {":features", ":weights"})
        known = known || perturb == frame.name + "." + enc.name + what;
  return known ? "" : "--perturb " + perturb + ": not CASE:features or CASE:weights of a kit case";
}

std::string writeConformanceKit(const BodyModel& model, const KitRequest& request) {
  if (std::string e = checkPerturb(request.perturb); !e.empty()) return e;
  if (std::string e = makeDir(request.dir); !e.empty()) return e;
  if (std::string e = makeDir(request.dir + "/bad"); !e.empty()) return e;
  const int k = model.numJoints();
  // Moderate poses, then large ones (angles near pi exercise the quaternion sign).
  std::vector<Eigen::VectorXd> axis_angles = samplePoses(k, 4, request.seed, 0.6);
  for (const Eigen::VectorXd& p : samplePoses(k, 2, request.seed + 1, 2.5))
    axis_angles.push_back(p);
  const Rotations bind = rotationsFromAxisAngle(samplePoses(k, 1, request.seed + 2, 3.0)[0]);
  const Rotations identity(size_t(k), Eigen::Matrix3d::Identity());
  std::vector<std::string> cases, frames, encodings;
  for (const KitEncoding& enc : kitEncodings()) {
    ExportOptions options;
    options.encoding = enc.encoding;
    options.corrective_basis = enc.basis;
    options.quantize_morphs = enc.quantize;
    Result<Asset> asset = exportAsset(model, options, {});
    if (!asset) return "export (" + enc.name + "): " + asset.message();
    for (const KitFrame& frame : kitFrames()) {
      const std::string name = frame.name + "." + enc.name;
      Rotations b = frame.bind_rotated ? bind : identity;
      if (frame.root_at_axes) b[0] = frame.axes;  // W_0(rest) = C C^T B_0 = C
      Rotations rest_world, rest_local;
      engineRotations(frame, model.parents, identity, b, &rest_world, &rest_local);
      std::vector<KitPose> poses;
      for (const Eigen::VectorXd& aa : axis_angles) {
        KitPose p;
        p.axis_angle = aa;
        const Rotations local = rotationsFromAxisAngle(aa);
        engineRotations(frame, model.parents, worldOf(model.parents, local), b, &p.world, &p.local);
        p.features = poseFeatures(local);
        p.weights = expectedWeights(asset->metadata, p.features);
        poses.push_back(std::move(p));
      }
      perturb(request.perturb, name, &poses);
      const std::string base = request.dir + "/" + name;
      if (std::string e = write(base + ".smpl.json", metadataJson(*asset) + "\n"); !e.empty())
        return e;
      if (std::string e =
              write(base + ".json", caseJson(name, frame, enc, rest_world, rest_local, poses));
          !e.empty())
        return e;
      cases.push_back(name);
      frames.push_back(frame.name);
      encodings.push_back(enc.name);
    }
  }
  for (const BadSidecar& bad : badSidecars())
    if (std::string e = write(request.dir + "/bad/" + bad.name + ".smpl.json", bad.text);
        !e.empty())
      return e;
  return write(request.dir + "/manifest.json",
               manifestJson(model, cases, frames, encodings, int(axis_angles.size())));
}

}  // namespace smpl
