// smpl-reference: the C++ reference forward pass (core/forward.h) for a set of
// seeded random poses, written for the round-trip tests to compare an engine's
// output against. With the exported skin (exporter/export_skin.h: truncated or
// fitted to M influences, what the exported asset carries) and with the
// model's own weights.
//
//   smpl-reference --model PATH|builtin --out PREFIX [--betas v,v,..]
//                  [--max-influences M] [--skin-weights truncated|optimized]
//                  [--corrective-refit on|off]
//                  [--poses P] [--seed S] [--dump-model]
//   smpl-reference --model PATH|builtin --conformance-kit DIR [--perturb CASE:features|weights]
//
// --conformance-kit writes the runtime conformance kit (docs/conformance.md,
// tools/reference/conformance_kit.h) instead of PREFIX.json/.bin; --perturb
// makes one expected value of one case wrong (the loaders' failure tests).
//
// Output: PREFIX.json, a header
//   {"model_kind","joint_names","parents","max_influences","num_vertices",
//    "num_joints","arrays":{name:{"shape":[..],"offset":o}}}
// and PREFIX.bin, the arrays as little-endian float64, C order, `offset`
// counted in doubles. Arrays: poses (P,K,3) axis-angle, features (P,9(K-1)),
// joints (P,K,3) posed, vertices_pruned (P,N,3) (the exported skin and the
// exported correctives: refitted to that skin, core/math/corrective_refit.h,
// unless --corrective-refit off),
// vertices_full (P,N,3), v_shaped (N,3), rest_joints (K,3), skin_weights (N,K)
// (the exported skin, dense); the header also names "skin_weights"; with --dump-model also posedirs
// (N,3,9(K-1)) and weights (N,K), for models that have no file (builtin).
//
// --model, --betas, --max-influences, --skin-weights and --corrective-refit are the export's own
// options: they are parsed by smpl-export's option table (cli/options.h) into
// an ExportRequest, checked by the request's checks and the model loaded by
// its ModelSource (request/), so this tool takes exactly what
// smpl-export takes, with the same messages. --poses, --seed, --dump-model
// and --out (a prefix) are this tool's own.
#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/options.h"
#include "cli/settings.h"
#include "core/math/corrective_refit.h"
#include "core/math/forward.h"
#include "core/math/pose_sampler.h"
#include "core/math/skin_weights.h"
#include "exporter/export_skin.h"
#include "request/check_request.h"
#include "request/model_source.h"
#include "request/request_options.h"
#include "tools/reference/conformance_kit.h"

namespace {

struct Options {
  smpl::Settings export_settings;  // request: --model, --betas, --max-influences, --skin-weights
  std::string out;
  int poses = 20;
  uint64_t seed = 1;
  bool dump_model = false;
  smpl::KitRequest kit;  // --conformance-kit DIR, --perturb
  const smpl::ExportRequest& request() const { return export_settings.request; }
};

struct Output {
  std::ostringstream arrays;  // the "arrays" object's members
  std::vector<double> data;
  void add(const std::string& name, const std::vector<int64_t>& shape, const double* values) {
    int64_t count = 1;
    arrays << (data.empty() ? "" : ",") << "\"" << name << "\":{\"shape\":[";
    for (size_t i = 0; i < shape.size(); ++i) {
      arrays << (i ? "," : "") << shape[i];
      count *= shape[i];
    }
    arrays << "],\"offset\":" << data.size() << "}";
    data.insert(data.end(), values, values + count);
  }
  // Eigen matrix as C order (rows of the printed matrix).
  void addMatrix(const std::string& name, const std::vector<int64_t>& shape,
                 const Eigen::MatrixXd& m) {
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row = m;
    add(name, shape, row.data());
  }
};

// The export options through smpl-export's own table; this tool's flags here.
bool parseArgs(int argc, char** argv, Options* o, std::string* error) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : nullptr;
    bool needs = a != "--dump-model";
    if (needs && !v) return *error = a + ": missing value", false;
    if (a == "--model" || a == "--betas" || a == "--max-influences" || a == "--skin-weights" ||
        a == "--corrective-refit") {
      smpl::Status st = smpl::findOption(a)->apply(v, &o->export_settings);
      if (!st) return *error = st.message(), false;
    } else if (a == "--out") {
      o->out = v;
    } else if (a == "--poses") {
      o->poses = std::atoi(v);
    } else if (a == "--seed") {
      o->seed = std::strtoull(v, nullptr, 10);
    } else if (a == "--conformance-kit") {
      o->kit.dir = v;
    } else if (a == "--perturb") {
      o->kit.perturb = v;
    } else if (a == "--dump-model") {
      o->dump_model = true;
    } else {
      return *error = "unknown option " + a, false;
    }
    if (needs) ++i;
  }
  if (!o->kit.perturb.empty() && o->kit.dir.empty())
    return *error = "--perturb needs --conformance-kit", false;
  if (std::string e = smpl::checkPerturb(o->kit.perturb); !e.empty()) return *error = e, false;
  if (o->request().model.empty() || (o->out.empty() == o->kit.dir.empty()))
    return *error = "--model and one of --out and --conformance-kit are required", false;
  if (o->poses < 1) return *error = "--poses must be >= 1", false;
  if (smpl::Status st = smpl::checkRequestOptions(o->request()); !st)
    return *error = st.message(), false;
  return true;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

bool writeFiles(const Options& o, const smpl::BodyModel& model, const Output& out) {
  std::ofstream bin(o.out + ".bin", std::ios::binary);
  // x86/ARM are little-endian, which the header promises; raw doubles are exact.
  bin.write(reinterpret_cast<const char*>(out.data.data()),
            static_cast<std::streamsize>(out.data.size() * 8));
  std::ofstream json(o.out + ".json");
  json << "{\"model_kind\":" << quoted(smpl::modelKindName(model.kind)) << ",\"joint_names\":[";
  for (int k = 0; k < model.numJoints(); ++k)
    json << (k ? "," : "") << quoted(model.joint_names[k]);
  json << "],\"parents\":[";
  for (int k = 0; k < model.numJoints(); ++k) json << (k ? "," : "") << model.parents[k];
  const smpl::ExportRequest& r = o.request();
  json << "],\"max_influences\":"
       << (r.asset.max_influences == smpl::kAllInfluences ? model.numJoints()
                                                          : r.asset.max_influences)
       << ",\"skin_weights\":" << quoted(smpl::skinWeightMethodName(r.asset.skin_weights))
       << ",\"num_vertices\":" << model.numVertices() << ",\"num_joints\":" << model.numJoints()
       << ",\"arrays\":{" << out.arrays.str() << "}}\n";
  return bin.good() && json.good();
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  std::string error;
  if (!parseArgs(argc, argv, &o, &error)) {
    std::fprintf(stderr, "smpl-reference: %s\n", error.c_str());
    return 2;
  }
  const smpl::ExportRequest& request = o.request();
  smpl::ModelSource models(request.model);  // a file, builtin, or a folder's neutral pick
  smpl::Result<smpl::ModelPick> pick = models.forMotion(nullptr);
  if (!pick) {
    std::fprintf(stderr, "smpl-reference: %s\n", pick.message().c_str());
    return 3;
  }
  const smpl::BodyModel* model = pick->model;
  if (smpl::Status st = smpl::checkRequestForModel(request, request.asset.betas, *model); !st) {
    std::fprintf(stderr, "smpl-reference: %s\n", st.message().c_str());
    return 2;
  }
  if (!o.kit.dir.empty()) {
    if (std::string e = smpl::writeConformanceKit(*model, o.kit); !e.empty()) {
      std::fprintf(stderr, "smpl-reference: %s\n", e.c_str());
      return 4;
    }
    return 0;
  }
  const int n = model->numVertices(), k = model->numJoints(), p = o.poses;
  const smpl::ExportOptions export_options = smpl::exportOptionsOf(request, request.asset.betas);
  const std::vector<double>& beta_values = request.asset.betas;
  const Eigen::VectorXd betas =
      Eigen::Map<const Eigen::VectorXd>(beta_values.data(), Eigen::Index(beta_values.size()));
  smpl::Result<smpl::ShapedBody> body = smpl::shapeBody(*model, betas);
  if (!body) {
    std::fprintf(stderr, "smpl-reference: %s\n", body.message().c_str());
    return 3;
  }
  const smpl::SparseSkin skin = smpl::exportSkin(*model, *body, export_options);
  const Eigen::MatrixXd pruned = smpl::denseWeights(skin, k);
  // The exported correctives: refitted to the skin unless --corrective-refit off.
  smpl::BodyModel exported = *model;
  if (smpl::refitsCorrectives(export_options))
    exported.posedirs = smpl::refitCorrectives(*model, *body, skin, smpl::CorrectiveRefitOptions())
                            .posedirs(*model);
  const std::vector<Eigen::VectorXd> poses = smpl::samplePoses(k, p, o.seed, 0.6);
  Eigen::MatrixXd pose_rows(p, 3 * k), features(p, 9 * (k - 1)), joints(p, 3 * k);
  Eigen::MatrixXd v_pruned(p, 3 * n), v_full(p, 3 * n), v_shaped, rest_joints;
  for (int i = 0; i < p; ++i) {
    smpl::ForwardInput in;
    in.betas = betas;
    in.rotations = smpl::rotationsFromAxisAngle(poses[i]);
    in.weights = &pruned;
    smpl::Result<smpl::ForwardResult> a = smpl::forward(exported, in);
    in.weights = nullptr;
    smpl::Result<smpl::ForwardResult> b = smpl::forward(*model, in);
    if (!a || !b) {
      std::fprintf(stderr, "smpl-reference: %s\n", (a ? b : a).message().c_str());
      return 3;
    }
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    pose_rows.row(i) = poses[i].transpose();
    features.row(i) = a->pose_features.transpose();
    joints.row(i) = Eigen::Map<const Eigen::RowVectorXd>(RowMajor(a->joints).data(), 3 * k);
    v_pruned.row(i) = Eigen::Map<const Eigen::RowVectorXd>(RowMajor(a->vertices).data(), 3 * n);
    v_full.row(i) = Eigen::Map<const Eigen::RowVectorXd>(RowMajor(b->vertices).data(), 3 * n);
    v_shaped = a->v_shaped;
    rest_joints = a->rest_joints;
  }
  Output out;
  out.addMatrix("poses", {p, k, 3}, pose_rows);
  out.addMatrix("features", {p, 9 * (k - 1)}, features);
  out.addMatrix("joints", {p, k, 3}, joints);
  out.addMatrix("vertices_pruned", {p, n, 3}, v_pruned);
  out.addMatrix("vertices_full", {p, n, 3}, v_full);
  out.addMatrix("v_shaped", {n, 3}, v_shaped);
  out.addMatrix("rest_joints", {k, 3}, rest_joints);
  out.addMatrix("skin_weights", {n, k}, pruned);
  if (o.dump_model) {
    // posedirs is 3N x F with row 3i+c; C order (N,3,F) is exactly those rows.
    out.addMatrix("posedirs", {n, 3, 9 * (k - 1)}, model->posedirs);
    out.addMatrix("weights", {n, k}, model->weights);
  }
  if (!writeFiles(o, *model, out)) {
    std::fprintf(stderr, "smpl-reference: %s: cannot write output\n", o.out.c_str());
    return 4;
  }
  return 0;
}
