// exportAsset: the asset it returns is finished (motions baked, the
// quantisation fold applied and marked, the encoding resolved, validated), so
// a writer's file and the sidecar written from the same asset agree.
#include "exporter/export_asset.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/models/model_loader.h"
#include "exporter/metadata_json.h"
#include "exporter/morph_scales.h"
#include "tools/morph_error.h"
#include "writers/gltf/gltf_writer.h"

namespace smpl {
namespace {

const std::string kFixtures = std::string(SMPL_FIXTURE_DIR);

struct Inputs {
  BodyModel model;
  Motion motion;
};

Inputs load() {
  Inputs in;
  Result<BodyModel> m = loadModel(kFixtures + "/models/smplh_small.npz");
  EXPECT_TRUE(m.ok()) << m.message();
  if (m) in.model = *m;
  Result<Motion> mo = loadMotion(kFixtures + "/motions/amass_smplh.npz");
  EXPECT_TRUE(mo.ok()) << mo.message();
  if (mo) in.motion = *mo;
  return in;
}

TEST(ExportAsset, BakesEachMotionAndResolvesTheEncoding) {
  const Inputs in = load();
  Result<Asset> still = exportAsset(in.model, ExportOptions(), {});
  ASSERT_TRUE(still.ok()) << still.message();
  EXPECT_TRUE(still->animations.empty());
  EXPECT_EQ(still->mesh.morph_targets[0].rest_weight, 0.f);  // Auto without motions: signed
  Result<Asset> moving =
      exportAsset(in.model, ExportOptions(),
                  {{&in.motion, "walk.npz", {}, nullptr}, {&in.motion, "again.npz", {}, nullptr}});
  ASSERT_TRUE(moving.ok()) << moving.message();
  ASSERT_EQ(moving->animations.size(), 2u);
  EXPECT_EQ(moving->animations[0].times.size(), in.motion.frames.size());
  // Auto with motions: split (rest weights 0, more targets than features, _pos/_neg pairs)
  EXPECT_EQ(moving->metadata.corrective_encoding, "split");
  EXPECT_GT(moving->mesh.morph_targets.size(), still->mesh.morph_targets.size());
  EXPECT_EQ(resolveEncoding(CorrectiveEncoding::Auto, 0), CorrectiveEncoding::Signed);
  EXPECT_EQ(resolveEncoding(CorrectiveEncoding::Auto, 1), CorrectiveEncoding::Split);
  EXPECT_EQ(resolveEncoding(CorrectiveEncoding::Auto, 1, /*basis=*/true), CorrectiveEncoding::Unit);
  EXPECT_EQ(resolveEncoding(CorrectiveEncoding::Signed, 3), CorrectiveEncoding::Signed);
}

// --quantize-morphs: the asset carries the fold (deltas / s_n, weights and
// metadata * s_n) and the mark; the writer adds nothing, so the metadata in
// the file equals metadataJson of the asset (the sidecar's source), and the
// decoded file reproduces the unquantized deltas within half an int16 step.
TEST(ExportAsset, QuantizeFoldsTheScalesIntoTheAsset) {
  const Inputs in = load();
  ExportOptions o;
  Result<Asset> plain = exportAsset(in.model, o, {{&in.motion, "walk.npz", {}, nullptr}});
  o.quantize_morphs = true;
  Result<Asset> q = exportAsset(in.model, o, {{&in.motion, "walk.npz", {}, nullptr}});
  ASSERT_TRUE(plain.ok() && q.ok());
  const std::vector<double> s = morphWeightScales(*plain);
  size_t marked = 0;
  for (size_t n = 0; n < q->mesh.morph_targets.size(); ++n) {
    const MorphTarget& t = q->mesh.morph_targets[n];
    marked += t.quantized;
    if (!t.quantized) continue;
    EXPECT_EQ(t.deltas.cwiseAbs().maxCoeff(), 1.f) << t.name;
    EXPECT_FLOAT_EQ(t.rest_weight, float(plain->mesh.morph_targets[n].rest_weight * s[n]))
        << t.name;
    EXPECT_FLOAT_EQ(q->animations[0].morph_weights(5, Eigen::Index(n)),
                    float(plain->animations[0].morph_weights(5, Eigen::Index(n)) * s[n]));
  }
  EXPECT_EQ(marked, q->metadata.correctives.size());
  EXPECT_DOUBLE_EQ(q->metadata.correctives[0].scale, plain->metadata.correctives[0].scale * s[0]);
  Result<std::string> bytes = gltfWriter().serialize(*q, WriterOptions());
  ASSERT_TRUE(bytes.ok()) << bytes.message();
  EXPECT_NE(bytes->find(metadataJson(*q)), std::string::npos)
      << "file metadata != sidecar metadata";
  Result<DecodedMorphs> d = decodeMorphs(*bytes);
  ASSERT_TRUE(d.ok()) << d.message();
  const Eigen::MatrixXf& exact = plain->mesh.morph_targets[0].deltas;
  EXPECT_LE((d->deltas[0].cast<double>() * s[0] - exact.cast<double>()).cwiseAbs().maxCoeff(),
            0.5 * s[0] / 32767 + 1e-9);
}

TEST(ExportAsset, ErrorsNameTheMotionAndLeaveNoAsset) {
  const Inputs in = load();
  AnimationOptions frames;
  frames.first_frame = 100000;
  Result<Asset> a =
      exportAsset(in.model, ExportOptions(), {{&in.motion, "walk.npz", frames, nullptr}});
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.message().find("walk.npz"), std::string::npos) << a.message();
  Result<Asset> none = exportAsset(in.model, ExportOptions(), {{nullptr, "gone.npz", {}, nullptr}});
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.message().find("gone.npz"), std::string::npos);
}

}  // namespace
}  // namespace smpl
