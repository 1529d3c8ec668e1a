#include "exporter/pipeline.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <numeric>
#include <optional>

#include "core/heap_trim.h"
#include "core/math/corrective_refit.h"
#include "core/math/forward.h"
#include "core/math/skin_weights.h"
#include "core/models/uv_source.h"
#include "core/parallel.h"
#include "exporter/corrective_basis.h"
#include "exporter/export_skin.h"
#include "exporter/skin_cache.h"

namespace smpl {
namespace {

Eigen::VectorXd toVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

Skeleton buildSkeleton(const BodyModel& model, const Eigen::MatrixXd& joints) {
  Skeleton s;
  s.names = model.joint_names;
  s.parents = model.parents;
  s.rest_world = joints;
  s.rest_local = joints;
  for (int k = 1; k < model.numJoints(); ++k) s.rest_local.row(k) -= joints.row(model.parents[k]);
  return s;
}

// Area-weighted vertex normals of the rest mesh.
Eigen::MatrixXf vertexNormals(const Eigen::MatrixXd& v, const Eigen::MatrixXi& faces) {
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(v.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    Eigen::Vector3d a = v.row(faces(f, 0)), b = v.row(faces(f, 1)), c = v.row(faces(f, 2));
    Eigen::RowVector3d area_normal = (b - a).cross(c - a).transpose();
    for (int j = 0; j < 3; ++j) n.row(faces(f, j)) += area_normal;
  }
  for (Eigen::Index i = 0; i < n.rows(); ++i) {
    double len = n.row(i).norm();
    n.row(i) = len > 0 ? Eigen::RowVector3d(n.row(i) / len) : Eigen::RowVector3d(0, 1, 0);
  }
  return n.cast<float>();
}

// Column `col` of a 3N-row direction matrix, divided by `scale` (in double,
// before rounding to float), as asset-vertex deltas.
MorphTarget directionTarget(std::string name, const Eigen::MatrixXd& dirs, int col,
                            const std::vector<int>& source_vertex, double scale = 1.0) {
  MorphTarget t;
  t.name = std::move(name);
  t.deltas.resize(static_cast<Eigen::Index>(source_vertex.size()), 3);
  for (size_t i = 0; i < source_vertex.size(); ++i)
    for (int c = 0; c < 3; ++c)
      t.deltas(i, c) = static_cast<float>(dirs(3 * source_vertex[i] + c, col) / scale);
  return t;
}

// Pose feature n's deltas as exported (the refitted rows where there are,
// core/math/corrective_refit.h), divided by `scale`, as asset-vertex deltas.
MorphTarget correctiveTarget(std::string name, const BodyModel& model, const CorrectiveRefit& refit,
                             int n, const std::vector<int>& source_vertex, double scale) {
  if (refit.empty())
    return directionTarget(std::move(name), model.posedirs, n, source_vertex, scale);
  // The whole column first (the model's, with the refitted rows patched in):
  // one pass instead of a lookup per value.
  const Eigen::MatrixXd column = refit.column(model, n);
  return directionTarget(std::move(name), column, 0, source_vertex, scale);
}

// Unit encoding of feature n: weight = 0.5 f + offset keeps weights in [0, 1].
CorrectiveLayout encodedLayout(const BodyModel& model, int n, CorrectiveEncoding encoding) {
  CorrectiveLayout c{n, correctiveTargetName(model, n), 1.0, 0.0};
  if (encoding == CorrectiveEncoding::Unit) {
    const bool diagonal = (n % 9) / 3 == n % 3;
    c.scale = 0.5;
    c.offset = diagonal ? 1.0 : 0.5;
  }
  return c;
}

// Removes sum (offset/scale) d from the stored base mesh: the targets' rest
// weights (offsets) then add it back, so the rest pose is exactly v_shaped.
void shiftBaseMesh(const Eigen::VectorXd& shift, SkinnedMesh* mesh) {
  for (Eigen::Index i = 0; i < mesh->positions.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      mesh->positions(i, c) =
          static_cast<float>(mesh->positions(i, c) - shift(3 * mesh->source_vertex[i] + c));
}

// Split encoding of feature n (export_options.h): one rectified target per sign
// the feature can take; delta = P_n / scale, so weight * delta = f P_n.
void addSplitCorrective(const BodyModel& model, const CorrectiveRefit& refit, int n, Asset* asset) {
  const bool diagonal = (n % 9) / 3 == n % 3;
  const std::string name = correctiveTargetName(model, n);
  std::vector<CorrectiveLayout> parts;
  if (diagonal)
    parts.push_back(CorrectiveLayout{n, name, -0.5, 0.0, true});
  else
    parts = {CorrectiveLayout{n, name + "_pos", 1.0, 0.0, true},
             CorrectiveLayout{n, name + "_neg", -1.0, 0.0, true}};
  for (const CorrectiveLayout& c : parts) {
    std::vector<MorphTarget>& targets = asset->mesh.morph_targets;
    if (c.scale == -1.0 && !diagonal) {  // float(d / -1) == -float(d): _pos negated, bit for bit
      MorphTarget negated{c.target, -targets.back().deltas};
      targets.push_back(std::move(negated));
    } else {
      targets.push_back(
          correctiveTarget(c.target, model, refit, n, asset->mesh.source_vertex, c.scale));
    }
    asset->metadata.correctives.push_back(c);
  }
}

void addCorrectives(const BodyModel& model, const ExportOptions& o, const CorrectiveRefit& refit,
                    Asset* asset) {
  if (o.encoding == CorrectiveEncoding::Split) {
    for (int n = 0; n < model.numPoseFeatures(); ++n) addSplitCorrective(model, refit, n, asset);
    return;
  }
  SkinnedMesh& mesh = asset->mesh;
  const int count = model.numPoseFeatures();
  std::vector<MorphTarget> targets(static_cast<size_t>(count));  // built on every worker, in order
  runWorkers(o.threads > 0 ? o.threads : int(hardwareThreads()), [&](int w, int workers) {
    for (int n = w; n < count; n += workers) {
      const CorrectiveLayout c = encodedLayout(model, n, o.encoding);
      // weight * delta must equal f * P: delta = P / scale
      targets[size_t(n)] = correctiveTarget(c.target, model, refit, n, mesh.source_vertex, c.scale);
      targets[size_t(n)].rest_weight = static_cast<float>(c.offset);
    }
  });
  Eigen::VectorXd shift =
      Eigen::VectorXd::Zero(model.posedirs.rows());  // sum (offset/scale) P_n, in double
  for (int n = 0; n < count; ++n) {
    const CorrectiveLayout c = encodedLayout(model, n, o.encoding);
    // The offset's contribution at every pose is removed from the stored base mesh.
    if (c.offset != 0.0) shift += (c.offset / c.scale) * refit.column(model, n);
    mesh.morph_targets.push_back(std::move(targets[size_t(n)]));
    asset->metadata.correctives.push_back(c);
  }
  if (o.encoding == CorrectiveEncoding::Unit) shiftBaseMesh(shift, &mesh);
}

// K principal components instead of P targets (corrective_basis.h): the
// scale/offset of each keeps its weight in [-1, 1] (Signed) or [0, 1] (Unit)
// for every pose.
// Fitted to the model's posedirs: a basis export is not refitted (refitsCorrectives).
Status addCorrectiveBasis(const BodyModel& model, const ExportOptions& o, Asset* asset) {
  Result<CorrectiveBasisFit> fit = fitCorrectiveBasis(model.posedirs, o.corrective_basis);
  if (!fit) return fit.error();
  Eigen::VectorXd lo, hi;
  weightRange(fit->projection, &lo, &hi);
  CorrectiveBasis& basis = asset->metadata.corrective_basis;
  basis.projection = fit->projection;
  Eigen::VectorXd shift = Eigen::VectorXd::Zero(model.posedirs.rows());
  for (Eigen::Index k = 0; k < fit->basis.cols(); ++k) {
    const bool unit = o.encoding == CorrectiveEncoding::Unit;
    const double range = unit ? hi(k) - lo(k) : std::max(-lo(k), hi(k));
    const double scale = range > 1e-300 ? 1.0 / range : 1.0;
    const double offset = unit ? -lo(k) * scale : 0.0;
    basis.targets.push_back("pose_basis_" + std::to_string(k));
    basis.scale.push_back(scale);
    basis.offset.push_back(offset);
    MorphTarget t = directionTarget(basis.targets.back(), fit->basis, static_cast<int>(k),
                                    asset->mesh.source_vertex, scale);
    t.rest_weight = static_cast<float>(offset);
    shift += (offset / scale) * fit->basis.col(k);
    asset->mesh.morph_targets.push_back(std::move(t));
  }
  shiftBaseMesh(shift, &asset->mesh);
  return Status();
}

Status addMorphTargets(const BodyModel& model, const ExportOptions& o, const CorrectiveRefit& refit,
                       Asset* asset) {
  std::vector<MorphTarget>& targets = asset->mesh.morph_targets;
  const std::vector<int>& src = asset->mesh.source_vertex;
  if (o.correctives && o.corrective_basis > 0) {
    if (Status s = addCorrectiveBasis(model, o, asset); !s) return s;
  } else if (o.correctives) {
    addCorrectives(model, o, refit, asset);
  }
  // Counts beyond the model's directions are clamped (a precondition: the
  // request refuses them first, request/check_request.h).
  for (int i = 0; i < std::min(o.shape_keys, model.numBetas()); ++i)
    targets.push_back(directionTarget("shape_" + std::to_string(i), model.shapedirs, i, src));
  for (int i = 0; i < std::min(o.expression_keys, model.numExpressions()); ++i)
    targets.push_back(directionTarget("expr_" + std::to_string(i), model.exprdirs, i, src));
  return Status();
}

// Per-asset-vertex geometry and skin from the model's vertices.
void buildMesh(const BodyModel& model, const Eigen::MatrixXd& v_shaped, const SparseSkin& skin,
               const UvLayout* uv, SkinnedMesh* mesh) {
  if (uv) {
    mesh->source_vertex = uv->source_vertex;
    mesh->triangles = uv->triangles;
    mesh->uvs = uv->uvs;
  } else {
    mesh->source_vertex.resize(model.numVertices());
    std::iota(mesh->source_vertex.begin(), mesh->source_vertex.end(), 0);
    mesh->triangles = model.faces;
  }
  Eigen::MatrixXf normals = vertexNormals(v_shaped, model.faces);
  const Eigen::Index v = static_cast<Eigen::Index>(mesh->source_vertex.size());
  mesh->positions.resize(v, 3);
  mesh->normals.resize(v, 3);
  mesh->joints.resize(v, skin.joints.cols());
  mesh->weights.resize(v, skin.weights.cols());
  for (Eigen::Index i = 0; i < v; ++i) {
    const int s = mesh->source_vertex[i];
    mesh->positions.row(i) = v_shaped.row(s).cast<float>();
    mesh->normals.row(i) = normals.row(s);
    mesh->joints.row(i) = skin.joints.row(s);
    mesh->weights.row(i) = skin.weights.row(s).cast<float>();
  }
}

// The model-level metadata of every asset.
void fillMetadata(const BodyModel& model, const ExportOptions& o, AssetMetadata* meta) {
  meta->model_kind = modelKindName(model.kind);
  meta->model_name = model.name;
  meta->exporter_version = SMPL_EXPORT_VERSION;
  meta->betas = o.betas;
  meta->betas.resize(model.numBetas(), 0.0);
  meta->expression = o.expression;
  meta->expression.resize(model.numExpressions(), 0.0);
  meta->skin_weights = skinWeightMethodName(o.skin_weights);
  meta->corrective_encoding = correctiveEncodingName(o.encoding);
}

// Options::mesh false: the subject's skeleton and metadata only; nothing of
// the mesh is computed (no skin fit, no morph targets).
Asset skeletonAsset(const BodyModel& model, const ExportOptions& o, const Eigen::MatrixXd& joints) {
  Asset asset;
  asset.name = o.name;
  asset.skeleton = buildSkeleton(model, joints);
  asset.skeleton_only = true;
  fillMetadata(model, o, &asset.metadata);
  asset.metadata.max_influences = 0;
  return asset;
}

// The skin and, when the options refit, the refit of the subject `body`;
// without a corrective basis also the mesh with its morph targets (nothing
// there can fail, so it is kept with the fit and a batch builds it once).
FittedSkin fitSkin(const BodyModel& model, const ShapedBody& body, const ExportOptions& o,
                   const UvLayout* uv) {
  FittedSkin f;
  f.skin = exportSkin(model, body, o);
  if (refitsCorrectives(o)) {
    CorrectiveRefitOptions refit;
    refit.threads = o.threads > 0 ? o.threads : int(hardwareThreads());
    f.refit = std::make_shared<const CorrectiveRefit>(refitCorrectives(model, body, f.skin, refit));
  }
  if (o.corrective_basis == 0) {
    Asset part;
    buildMesh(model, body.v_shaped, f.skin, uv, &part.mesh);
    (void)addMorphTargets(model, o, *f.refit, &part);  // no basis: always succeeds
    f.mesh = std::move(part.mesh);
    f.correctives = std::move(part.metadata.correctives);
    f.has_mesh = true;
  }
  return f;
}

}  // namespace

std::string correctiveTargetName(const BodyModel& model, int feature) {
  const int joint = feature / 9 + 1, r = (feature % 9) / 3, c = feature % 3;
  return "pose_" + model.joint_names[joint] + "_" + std::to_string(r) + std::to_string(c);
}

Result<Asset> buildAsset(const BodyModel& model, const ExportOptions& o, SkinCache* skins) {
  Result<ShapedBody> body = shapeBody(model, toVector(o.betas), toVector(o.expression));
  if (!body) return body.error();
  if (!o.mesh) return skeletonAsset(model, o, body->joints);
  Result<std::optional<UvLayout>> uv =
      resolveUvLayout(o.uv_obj, model);  // model UVs, --uv FILE or none
  if (!uv)
    return makeError(uv.message(), ErrorKind::Load);  // a UV file that cannot be read: an input
  Asset asset;
  asset.name = o.name;
  asset.skeleton = buildSkeleton(model, body->joints);
  // From `skins` (the same subject's earlier export) or fitted for this export alone.
  const UvLayout* layout = *uv ? &**uv : nullptr;
  bool fitted = !skins;
  const std::shared_ptr<const FittedSkin> cached =
      skins ? skins->get(model, o,
                         [&] {
                           fitted = true;
                           return fitSkin(model, *body, o, layout);
                         })
            : nullptr;
  FittedSkin own = skins ? FittedSkin() : fitSkin(model, *body, o, layout);
  // The fit's and the refit's temporaries (a long clip's frames are loaded);
  // an export whose skin came from the cache freed nothing worth it.
  if (fitted) returnFreedHeap();
  const FittedSkin& fit = skins ? *cached : own;
  fillMetadata(model, o, &asset.metadata);
  asset.metadata.max_influences = int(fit.skin.joints.cols());  // influencesFor(), or fewer
  asset.corrective_refit = fit.refit;                           // shared, never copied
  if (fit.has_mesh) {  // the cache's copied, this export's own moved
    if (skins)
      asset.mesh = cached->mesh;
    else
      asset.mesh = std::move(own.mesh);
    asset.metadata.correctives = fit.correctives;
    return asset;
  }
  buildMesh(model, body->v_shaped, fit.skin, layout, &asset.mesh);
  if (Status s = addMorphTargets(model, o, *asset.corrective_refit, &asset); !s) return s.error();
  return asset;
}

}  // namespace smpl
