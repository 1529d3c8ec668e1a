// SkinCache (exporter/skin_cache.h): one fit per subject, shared by the
// exports that need it, keyed on everything the fit depends on.
#include "exporter/skin_cache.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "core/demo/demo_body.h"
#include "exporter/pipeline.h"

namespace smpl {
namespace {

// A stand-in fit that counts its calls (the cache's bookkeeping, not the math).
FittedSkin countedFit(std::atomic<int>* calls, int tag) {
  ++*calls;
  FittedSkin f;
  f.skin.joints = Eigen::MatrixXi::Constant(1, 1, tag);
  f.skin.weights = Eigen::MatrixXd::Ones(1, 1);
  return f;
}

ExportOptions subject(double beta0) {
  ExportOptions o;
  o.betas = {beta0, -0.5};
  return o;
}

TEST(SkinCache, OneFitPerSubjectAndEveryKeyPartSeparatesSubjects) {
  const BodyModel& model = demoBody();
  SkinCache cache(16);
  std::atomic<int> calls{0};
  auto fit = [&] { return countedFit(&calls, 0); };
  (void)cache.get(model, subject(1.0), fit);
  (void)cache.get(model, subject(1.0), fit);
  EXPECT_EQ(calls, 1);
  ExportOptions padded = subject(1.0);
  padded.betas.push_back(0.0);  // the same subject: shapeBody pads betas with zeros
  (void)cache.get(model, padded, fit);
  EXPECT_EQ(calls, 1);
  std::vector<ExportOptions> others(11, subject(1.0));
  others[0].betas[0] = 1.0 + 1e-12;
  others[1].max_influences = 3;
  others[2].skin_weights = SkinWeightMethod::Truncated;
  others[3].corrective_refit = false;
  others[4].expression = {0.25};  // ignored by a model without expressions: padded away
  // What the mesh and its morph targets (kept with the fit) depend on.
  others[5].uv_obj = "none";
  others[6].encoding = CorrectiveEncoding::Unit;
  others[7].correctives = false;
  others[8].corrective_basis = 4;
  others[9].shape_keys = 2;
  others[10].expression_keys = 1;
  for (const ExportOptions& o : others) (void)cache.get(model, o, fit);
  EXPECT_EQ(calls, 11) << "betas, influences, method, refit, UVs, encoding, correctives, basis, "
                          "shape and expression keys each make a new subject; an expression the "
                          "model does not have does not";
  EXPECT_EQ(cache.computed(), 11);
  EXPECT_EQ(cache.reused(), 3);
}

TEST(SkinCache, KeepsTheMostRecentSubjectsOnly) {
  const BodyModel& model = demoBody();
  SkinCache cache(1);
  std::atomic<int> calls{0};
  auto fit = [&] { return countedFit(&calls, 0); };
  (void)cache.get(model, subject(1.0), fit);
  (void)cache.get(model, subject(2.0), fit);  // evicts subject 1
  (void)cache.get(model, subject(1.0), fit);
  EXPECT_EQ(calls, 3);
}

TEST(SkinCache, ConcurrentCallersOfOneSubjectWaitForOneFit) {
  const BodyModel& model = demoBody();
  SkinCache cache(4);
  std::atomic<int> calls{0};
  auto slow = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return countedFit(&calls, 7);
  };
  std::vector<std::thread> pool;
  std::atomic<int> sevens{0};
  for (int t = 0; t < 4; ++t)
    pool.emplace_back(
        [&] { sevens += cache.get(model, subject(1.0), slow)->skin.joints(0, 0) == 7; });
  for (std::thread& t : pool) t.join();
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(sevens, 4);
}

TEST(SkinCache, AFailedFitReachesItsCallerAndIsNotKept) {
  const BodyModel& model = demoBody();
  SkinCache cache(4);
  EXPECT_THROW((void)cache.get(model, subject(1.0), []() -> FittedSkin { throw std::bad_alloc(); }),
               std::bad_alloc);
  std::atomic<int> calls{0};
  (void)cache.get(model, subject(1.0), [&] { return countedFit(&calls, 0); });
  EXPECT_EQ(calls, 1);
}

// The real fit through buildAsset: the second export of a subject is served
// from the cache and gives the same asset as an export without one.
// Everything buildAsset makes of the mesh: geometry, skin, targets and their layouts.
void expectSameMesh(const Asset& a, const Asset& b) {
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.mesh.normals, b.mesh.normals);
  EXPECT_EQ(a.mesh.joints, b.mesh.joints);
  EXPECT_EQ(a.mesh.weights, b.mesh.weights);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.source_vertex, b.mesh.source_vertex);
  ASSERT_EQ(a.mesh.morph_targets.size(), b.mesh.morph_targets.size());
  for (size_t t = 0; t < a.mesh.morph_targets.size(); ++t) {
    EXPECT_EQ(a.mesh.morph_targets[t].name, b.mesh.morph_targets[t].name) << t;
    EXPECT_EQ(a.mesh.morph_targets[t].rest_weight, b.mesh.morph_targets[t].rest_weight) << t;
    ASSERT_EQ(a.mesh.morph_targets[t].deltas, b.mesh.morph_targets[t].deltas) << t;
  }
  ASSERT_EQ(a.metadata.correctives.size(), b.metadata.correctives.size());
  for (size_t c = 0; c < a.metadata.correctives.size(); ++c) {
    EXPECT_EQ(a.metadata.correctives[c].target, b.metadata.correctives[c].target) << c;
    EXPECT_EQ(a.metadata.correctives[c].scale, b.metadata.correctives[c].scale) << c;
    EXPECT_EQ(a.metadata.correctives[c].offset, b.metadata.correctives[c].offset) << c;
  }
}

// Two exports of `o` through one cache (the second served from it) and one without.
struct ThreeBuilds {
  Result<Asset> first, second, fresh;
};
ThreeBuilds buildThrice(const BodyModel& model, const ExportOptions& o, SkinCache* cache) {
  ThreeBuilds b{buildAsset(model, o, cache), buildAsset(model, o, cache), buildAsset(model, o)};
  return b;
}

// The mesh kept with the fit, for each corrective encoding and with shape
// keys: a cached export's mesh equals a fresh one's (Unit also shifts the base mesh).
TEST(SkinCache, TheKeptMeshEqualsAFreshOneForEveryEncoding) {
  const BodyModel& model = demoBody();
  for (CorrectiveEncoding e :
       {CorrectiveEncoding::Signed, CorrectiveEncoding::Unit, CorrectiveEncoding::Split}) {
    ExportOptions o = subject(0.4);
    o.encoding = e;
    o.shape_keys = 2;
    SkinCache cache(4);
    const ThreeBuilds b = buildThrice(model, o, &cache);
    ASSERT_TRUE(b.first && b.second && b.fresh);
    EXPECT_EQ(cache.reused(), 1);
    SCOPED_TRACE(correctiveEncodingName(e));
    EXPECT_GE(b.second->metadata.correctives.size(), size_t(model.numPoseFeatures()));
    expectSameMesh(*b.second, *b.fresh);
  }
}

TEST(SkinCache, AReusedFitGivesTheSameAssetAsAFreshOne) {
  const BodyModel& model = demoBody();
  ExportOptions o = subject(0.8);
  o.max_influences = 2;
  SkinCache cache(4);
  const ThreeBuilds b = buildThrice(model, o, &cache);
  ASSERT_TRUE(b.first && b.second && b.fresh);
  EXPECT_EQ(cache.computed(), 1);
  EXPECT_EQ(cache.reused(), 1);
  ASSERT_GT(b.fresh->corrective_refit->cut, 0);
  expectSameMesh(*b.second, *b.fresh);
  ExportOptions other = o;
  other.betas[0] = -0.8;  // another subject: its own fit, its own weights
  Result<Asset> third = buildAsset(model, other, &cache);
  ASSERT_TRUE(third);
  EXPECT_EQ(cache.computed(), 2);
  EXPECT_NE(third->mesh.weights, b.fresh->mesh.weights);
}

}  // namespace
}  // namespace smpl
