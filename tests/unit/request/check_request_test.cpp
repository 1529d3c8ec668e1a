// The request's checks (request/check_request.h): every range and
// every conflict refused with its message, naming the option as the user
// types it, of kind Usage; the model-dependent counts against the model; a
// request built in code (no command line) goes through the same checks.
#include "request/check_request.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "core/demo/demo_body.h"

namespace smpl {
namespace {

ExportRequest valid() {
  ExportRequest r;
  r.model = "builtin";
  r.out = "a.glb";
  return r;
}

struct Case {
  std::function<void(ExportRequest*)> change;
  std::string message;  // the whole message
};

TEST(CheckRequest, ValidRequestsPass) {
  EXPECT_TRUE(checkRequest(valid()).ok());
  ExportRequest batch = valid();  // a batch: the jobs get their outputs
  batch.out.clear();
  batch.motion_dir = "motions";
  EXPECT_TRUE(checkRequest(batch).ok());
  batch.format = "fbx";
  EXPECT_TRUE(checkRequest(batch).ok());
  ExportRequest bvh = valid();  // one motion, or none (the rest pose)
  bvh.out = "walk.bvh";
  EXPECT_TRUE(checkRequest(bvh).ok());
  bvh.motions = {"walk.npz"};
  EXPECT_TRUE(checkRequest(bvh).ok());
  batch.format = "bvh";
  EXPECT_TRUE(checkRequest(batch).ok());
  batch.format = "obj";
  EXPECT_EQ(checkRequest(batch).message(),
            "--format: expected 'glb', 'gltf', 'fbx', 'bvh', 'mjcf', 'usda' or 'usdz', got 'obj'");
  ExportRequest edges = valid();  // every range at its ends
  edges.animation.fps = 1000;
  edges.reading.source_fps = 1;
  edges.writer.morph_epsilon = 0.01;
  edges.writer.fbx_compress_level = 12;
  edges.writer.threads = 1024;
  edges.asset.betas = {1000, -1000};
  edges.animation.first_frame = 0;
  edges.animation.end_frame = 1;
  EXPECT_TRUE(checkRequest(edges).ok()) << checkRequest(edges).message();
  ExportRequest thinned = valid();  // epsilon thins the shape keys: no conflict
  thinned.asset.correctives = false;
  thinned.writer.morph_epsilon = 0.001;
  thinned.asset.shape_keys = 2;
  EXPECT_TRUE(checkRequest(thinned).ok());
}

TEST(CheckRequest, EachRangeAndConflictHasItsMessage) {
  const Case cases[] = {
      {[](ExportRequest* r) { r->model.clear(); },
       "missing --model PATH (use --model builtin for the demo body)"},
      {[](ExportRequest* r) { r->out.clear(); },
       "missing --out FILE (.glb, .gltf, .fbx, .bvh, .xml, .usda, .usd or .usdz)"},
      {[](ExportRequest* r) { r->out = "a.obj"; },
       "--out a.obj: unknown format (expected .glb, .gltf, .fbx, .bvh, .xml, .usda, .usd or "
       ".usdz)"},
      {[](ExportRequest* r) {
         r->out = "a.bvh", r->motions = {"a.npz", "b.npz"};
       },
       "--motion: bvh output holds one motion; got 2 (one output per motion: --motion-dir)"},
      {[](ExportRequest* r) { r->out = "a.bvh", r->asset.shape_keys = 2; },
       "--shape-keys needs an output format with a mesh; bvh output has none"},
      {[](ExportRequest* r) { r->asset.betas = {1}, r->betas_file = "b.npy"; },
       "--betas and --betas-file conflict: give one"},
      {[](ExportRequest* r) { r->betas_from_motion = true, r->betas_file = "b.npy"; },
       "--betas-from-motion conflicts with --betas/--betas-file"},
      {[](ExportRequest* r) { r->betas_from_motion = true, r->asset.betas = {0.5}; },
       "--betas-from-motion conflicts with --betas/--betas-file"},
      {[](ExportRequest* r) { r->asset.corrective_basis = 8, r->asset.correctives = false; },
       "--corrective-basis conflicts with --correctives none"},
      {[](ExportRequest* r) {
         r->asset.encoding = CorrectiveEncoding::Unit, r->asset.correctives = false;
       },
       "--corrective-weights conflicts with --correctives none (no corrective targets to "
       "encode)"},
      {[](ExportRequest* r) { r->asset.quantize_morphs = true, r->asset.correctives = false; },
       "--quantize-morphs quantizes corrective targets; with --correctives none there are none"},
      {[](ExportRequest* r) { r->writer.quantize_animation = true; },
       "--quantize-animation quantises animation keys; without --motion or --motion-dir there are "
       "none"},
      {[](ExportRequest* r) { r->writer.morph_epsilon = 0.001, r->asset.correctives = false; },
       "--corrective-epsilon thins morph targets; with --correctives none and no --shape-keys/"
       "--expression-keys there are none"},
      {[](ExportRequest* r) {
         r->asset.corrective_basis = 8, r->asset.encoding = CorrectiveEncoding::Split;
       },
       "--corrective-basis conflicts with --corrective-weights split (basis weights are signed "
       "or unit)"},
      {[](ExportRequest* r) { r->dmpl_count = 2; }, "--dmpl-count needs --dmpl"},
      {[](ExportRequest* r) { r->dmpl_regressed_joints = true; }, "--dmpl-joints needs --dmpl"},
      {[](ExportRequest* r) {
         r->asset.betas = {0, 1e300};
       },
       "--betas: value[1] is 1e+300; expected a finite value with magnitude at most 1000"},
      {[](ExportRequest* r) { r->asset.expression = {-1001}; },
       "--expression: value[0] is -1001; expected a finite value with magnitude at most 1000"},
      {[](ExportRequest* r) { r->reading.source_fps = 0; },
       "--source-fps: expected a rate in [1, 1000], got '0'"},
      {[](ExportRequest* r) { r->reading.source_fps = 5000; },
       "--source-fps: expected a rate in [1, 1000], got '5000'"},
      {[](ExportRequest* r) { r->animation.fps = 0; },
       "--fps: expected a rate in (0, 1000], got '0'"},
      {[](ExportRequest* r) { r->animation.fps = -30; },
       "--fps: expected a rate in (0, 1000], got '-30'"},
      {[](ExportRequest* r) { r->animation.fps = 1000.5; },
       "--fps: expected a rate in (0, 1000], got '1000.5'"},
      {[](ExportRequest* r) { r->animation.first_frame = -1; }, "--frames: bad start '-1'"},
      {[](ExportRequest* r) { r->animation.first_frame = 10, r->animation.end_frame = 5; },
       "--frames: end must be after start in '10:5'"},
      {[](ExportRequest* r) { r->writer.morph_epsilon = 0.02; },
       "--corrective-epsilon: expected metres in [0, 0.01], got '0.02'"},
      {[](ExportRequest* r) { r->writer.morph_epsilon = -1e-9; },
       "--corrective-epsilon: expected metres in [0, 0.01], got '-1e-09'"},
      {[](ExportRequest* r) { r->writer.fbx_compress_level = 13; },
       "--fbx-compress-level: expected 0..12, got '13'"},
      {[](ExportRequest* r) { r->writer.fbx_compress_level = -1; },
       "--fbx-compress-level: expected 0..12, got '-1'"},
      {[](ExportRequest* r) { r->writer.threads = 0; }, "--threads: expected 1..1024, got '0'"},
      {[](ExportRequest* r) { r->writer.threads = 1025; },
       "--threads: expected 1..1024, got '1025'"},
      {[](ExportRequest* r) { r->dmpl = "d.npz", r->dmpl_count = 0; },
       "--dmpl-count: expected N >= 1, got '0'"},
      {[](ExportRequest* r) { r->hands_wrist = true; }, "--hands-wrist needs --hands FILE"},
      {[](ExportRequest* r) { r->hands = {"h.pkl"}; },
       "--hands drives the fingers of one body clip: give one --motion or --motion-sequence"},
      {[](ExportRequest* r) {
         r->motions = {"a.pt", "b.pt"}, r->hands = {"h.pkl"};
       },
       "--hands drives the fingers of one body clip: give one --motion or --motion-sequence"},
      {[](ExportRequest* r) {
         r->motions = {"a.pt"}, r->hands = {"l.npz", "r.npz", "x.npz"};
       },
       "--hands: 3 files; give at most two (the left and the right hand)"},
      {[](ExportRequest* r) {
         r->motions = {"a.pt"}, r->hands = {"h"}, r->track.kind = TrackChoice::Kind::All;
       },
       "--hands drives one body: give --track ID (or longest), not --track all"},
  };
  for (const Case& c : cases) {
    ExportRequest r = valid();
    c.change(&r);
    Status st = checkRequest(r);
    ASSERT_FALSE(st.ok()) << c.message;
    EXPECT_EQ(st.message(), c.message);
    EXPECT_EQ(st.kind(), ErrorKind::Usage) << c.message;
  }
}

TEST(CheckRequest, CountsAreCheckedAgainstTheModel) {
  const BodyModel model = demoBody();
  const std::string k = std::to_string(model.numJoints()), b = std::to_string(model.numBetas());
  const std::string e = std::to_string(model.numExpressions());
  const std::string p = std::to_string(model.numPoseFeatures());
  const std::vector<double> too_many(model.numBetas() + 1, 0.1);
  EXPECT_TRUE(checkRequestForModel(valid(), {}, model).ok());
  ExportRequest all = valid();
  all.asset.max_influences = kAllInfluences;
  EXPECT_TRUE(checkRequestForModel(all, {}, model).ok());
  const Case cases[] = {
      {[&](ExportRequest* r) { r->asset.max_influences = model.numJoints() + 1; },
       "--max-influences must be between 1 and " + k + " (the model's joints) or 'all', got " +
           std::to_string(model.numJoints() + 1)},
      {[](ExportRequest* r) { r->asset.max_influences = -1; },
       "--max-influences must be between 1 and " + k + " (the model's joints) or 'all', got -1"},
      {[&](ExportRequest* r) { r->asset.shape_keys = model.numBetas() + 1; },
       "--shape-keys " + std::to_string(model.numBetas() + 1) + ": the model has " + b +
           " shape directions"},
      {[](ExportRequest* r) { r->asset.shape_keys = -1; },
       "--shape-keys -1: the model has " + b + " shape directions"},
      {[&](ExportRequest* r) { r->asset.expression_keys = model.numExpressions() + 1; },
       "--expression-keys " + std::to_string(model.numExpressions() + 1) + ": the model has " + e +
           " expression directions"},
      {[&](ExportRequest* r) { r->asset.expression.assign(model.numExpressions() + 1, 0.1); },
       "expression: " + std::to_string(model.numExpressions() + 1) + " values given; the model " +
           model.name + " has " + e},
      {[&](ExportRequest* r) { r->asset.corrective_basis = model.numPoseFeatures() + 1; },
       "--corrective-basis " + std::to_string(model.numPoseFeatures() + 1) + ": expected 1.." + p +
           " (the model has " + p + " pose correctives)"},
      {[](ExportRequest* r) { r->asset.corrective_basis = -1; },
       "--corrective-basis -1: expected 1.." + p + " (the model has " + p + " pose correctives)"},
  };
  for (const Case& c : cases) {
    ExportRequest r = valid();
    c.change(&r);
    Status st = checkRequestForModel(r, {}, model);
    ASSERT_FALSE(st.ok()) << c.message;
    EXPECT_EQ(st.message(), c.message);
    EXPECT_EQ(st.kind(), ErrorKind::Usage);
  }
  // The betas are the run's (--betas or the values of --betas-file).
  Status betas = checkRequestForModel(valid(), too_many, model);
  ASSERT_FALSE(betas.ok());
  EXPECT_EQ(betas.message(), "betas: " + std::to_string(too_many.size()) +
                                 " values given; the model " + model.name + " has " + b);
}

TEST(CheckRequest, DmplCountAgainstTheBasis) {
  ExportRequest r = valid();
  r.dmpl = "d.npz";
  EXPECT_TRUE(checkDmplCount(r, 8).ok());  // all
  r.dmpl_count = 8;
  EXPECT_TRUE(checkDmplCount(r, 8).ok());
  r.dmpl_count = 9;
  Status st = checkDmplCount(r, 8);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message(), "--dmpl-count 9: the basis has 8 directions");
  EXPECT_EQ(st.kind(), ErrorKind::Load);
}

}  // namespace
}  // namespace smpl
