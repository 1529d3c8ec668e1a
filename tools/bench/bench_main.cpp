// smpl-bench: prints the speed and size table of the product.
// --compact: only the compact glTF table. Full-size synthetic models
// (bench/synthetic_model.h) stand in for the licensed ones. Usage: smpl-bench [--quick] [--compact]
// [--anim-minutes M] (--help: usage) smpl-bench --compare [--smplx CHECKOUT]: side by side with the
// peers (compare.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "core/demo/demo_body.h"
#include "core/math/forward.h"
#include "core/math/forward_batch.h"
#include "core/math/pose_sampler.h"
#include "core/motions/motion.h"
#include "exporter/animation.h"
#include "exporter/morph_scales.h"
#include "exporter/pipeline.h"
#include "tools/bench/compare.h"
#include "tools/bench/synthetic_model.h"
#include "tools/morph_error.h"
#include "writers/writer.h"

using namespace smpl;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// Median of `repeats` timings of fn(), in ms.
template <class Fn>
double timeMs(int repeats, Fn fn) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    auto start = Clock::now();
    fn();
    t.push_back(msSince(start));
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::vector<Rotations> randomFrames(int joints, int count) {
  std::vector<Rotations> frames;
  for (const Eigen::VectorXd& pose : samplePoses(joints, count, 99))
    frames.push_back(rotationsFromAxisAngle(pose));
  return frames;
}

void benchExport(const BodyModel& model, int repeats) {
  Result<Asset> asset = buildAsset(model, ExportOptions());
  std::printf("| %-14s | build asset | %9.1f ms |           |\n", model.name.c_str(),
              timeMs(repeats, [&] { (void)buildAsset(model, ExportOptions()); }));
  for (const char* ext : {".glb", ".fbx"}) {
    const Writer* w = writerForPath(std::string("x") + ext);
    if (!w) continue;
    size_t bytes = 0;
    double ms = timeMs(repeats, [&] {
      Result<std::string> out = w->serialize(*asset, WriterOptions());
      bytes = out.ok() ? out->size() : 0;
    });
    std::printf("| %-14s | write %-5s | %9.1f ms | %6.2f MB |\n", model.name.c_str(), ext + 1, ms,
                bytes / 1e6);
  }
}

// Compact glTF encodings (README "Size"): size, write time and the max vertex
// error each adds over 32 seeded poses (tools/morph_error.h).
void benchCompact(const BodyModel& model, int repeats) {
  Result<Asset> asset = buildAsset(model, ExportOptions());
  if (!asset)
    return (void)std::printf("| %-14s | %s |\n", model.name.c_str(), asset.message().c_str());
  struct Encoding {
    const char* name;
    double epsilon;
    bool quantize, draco;
  };
  const Encoding encodings[] = {{"float", 0, false, false},
                                {"sparse 1e-5", 1e-5, false, false},
                                {"sparse 1e-4", 1e-4, false, false},
                                {"quantized", 0, true, false},
                                {"sparse 1e-5+quant", 1e-5, true, false},
                                {"draco", 0, false, true},
                                {"sparse 1e-5+quant+draco", 1e-5, true, true}};
  const Writer* w = writerForPath("x.glb");
  Asset folded =
      *asset;  // --quantize-morphs: exportAsset folds each corrective's peak into its weights
  foldMorphScales(&folded);
  for (const Encoding& e : encodings) {
    WriterOptions o;
    o.morph_epsilon = e.epsilon;
    o.draco = e.draco;
    std::string bytes;
    const double ms = timeMs(repeats, [&] {
      Result<std::string> out = w->serialize(e.quantize ? folded : *asset, o);
      bytes = out.ok() ? *out : std::string();
    });
    Result<DecodedMorphs> decoded = decodeMorphs(bytes);
    Result<double> err = decoded ? morphError(*decoded, *asset) : Result<double>(decoded.error());
    std::printf("| %-14s | %-24s | %7.2f MB | %7.1f ms | %9.3g m |%s\n", model.name.c_str(), e.name,
                bytes.size() / 1e6, ms, err ? *err : -1.0, err ? "" : err.message().c_str());
  }
}

void benchForward(const BodyModel& model, int frames_count) {
  const std::vector<Rotations> frames = randomFrames(model.numJoints(), frames_count);
  ForwardInput in;
  in.rotations = frames[0];
  const double single = timeMs(21, [&] { (void)forward(model, in); });
  std::printf("| %-14s | forward 1 frame      | %7.3f ms/frame |\n", model.name.c_str(), single);
  Result<ShapedBody> body = shapeBody(model, Eigen::VectorXd());
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  for (int threads : {1, cores}) {
    BatchInput bi{&*body, &frames, nullptr, threads, 64};
    const double ms = timeMs(3, [&] { (void)forwardBatch(model, bi); });
    std::printf("| %-14s | batch %4d, %d thr    | %7.3f ms/frame | %7.3f ms/frame/core |\n",
                model.name.c_str(), frames_count, threads, ms / frames_count,
                ms * threads / frames_count);
  }
}

void benchAnimation(const BodyModel& model, double minutes) {
  const int frames = static_cast<int>(minutes * 60 * 120);
  Motion motion;
  motion.name = "synthetic";
  motion.layout = ModelKind::SmplH;
  motion.fps = 120;
  motion.world = MotionWorld::Z;
  std::vector<Eigen::VectorXd> poses = samplePoses(52, 64, 5, 0.5);
  for (int f = 0; f < frames; ++f) motion.frames.push_back(rotationsFromAxisAngle(poses[f % 64]));
  motion.translation.assign(frames, Eigen::Vector3d::Zero());
  Result<Asset> asset = buildAsset(model, ExportOptions());
  auto start = Clock::now();
  Result<AnimationClip> clip = bakeAnimation(model, *asset, motion, AnimationOptions(), "bench");
  const double bake = msSince(start);
  asset->animations.push_back(std::move(*clip));
  std::printf("| %-14s | bake %g min @120 fps (%d frames) | %8.0f ms | %9.0f frames/s |\n",
              model.name.c_str(), minutes, frames, bake, frames / (bake / 1e3));
  for (const char* ext : {".glb", ".fbx"}) {
    const Writer* w = writerForPath(std::string("x") + ext);
    if (!w) continue;
    start = Clock::now();
    Result<std::string> out = w->serialize(*asset, WriterOptions());
    const double ms = msSince(start);
    std::printf("| %-14s | + write %-4s | %8.0f ms | %9.0f frames/s | %7.1f MB |\n",
                model.name.c_str(), ext + 1, ms, frames / ((bake + ms) / 1e3),
                out.ok() ? out->size() / 1e6 : 0.0);
  }
}

}  // namespace

const char kUsage[] =
    "usage: smpl-bench [--quick] [--compact] [--anim-minutes M]\n"
    "       smpl-bench --compare [--smplx CHECKOUT] [--standin DIR] [--blender PATH] [--frames "
    "N]\n";

int main(int argc, char** argv) {
  bool quick = false;
  double minutes = 10;
  bool compact_only = false;
  CompareOptions compare;
  bool compare_only = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h"))
      return std::printf("%s", kUsage), 0;
    if (!std::strcmp(argv[i], "--compare"))
      compare_only = true;
    else if (!std::strcmp(argv[i], "--smplx") && i + 1 < argc)
      compare.smplx = argv[++i];
    else if (!std::strcmp(argv[i], "--standin") && i + 1 < argc)
      compare.standin = argv[++i];
    else if (!std::strcmp(argv[i], "--blender") && i + 1 < argc)
      compare.blender = argv[++i];
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
      compare.frames = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--compact"))
      compact_only = true;
    else if (!std::strcmp(argv[i], "--anim-minutes") && i + 1 < argc)
      minutes = std::atof(argv[++i]);
    else
      return std::fprintf(stderr, "%s", kUsage), 1;
  }
  if (compare_only) return runCompare(compare);
  std::printf("smpl-bench: %u hardware threads%s\n\n", std::thread::hardware_concurrency(),
              quick ? " (quick)" : "");
  const BodyModel smpl = syntheticModel(ModelKind::Smpl, 6890, 10, 0, 1);
  if (compact_only) {  // only the compact glTF table
    std::printf("Compact glTF (write time median of 5; error: max added vertex error, 32 poses)\n");
    for (const BodyModel* m : {&demoBody(), &smpl}) benchCompact(*m, 5);
    return 0;
  }
  const BodyModel smplx = syntheticModel(ModelKind::SmplX, 10475, 300, 100, 2);
  std::printf("Export (median of %d)\n", quick ? 1 : 5);
  for (const BodyModel* m : {&smpl, &smplx}) benchExport(*m, quick ? 1 : 5);
  std::printf("\nCompact glTF (write time median of %d; error: max added vertex error, 32 poses)\n",
              quick ? 3 : 5);
  for (const BodyModel* m : {&demoBody(), &smpl}) benchCompact(*m, quick ? 3 : 5);
  std::printf("\nForward pass\n");
  for (const BodyModel* m : {&smpl, &smplx}) benchForward(*m, quick ? 100 : 1000);
  std::printf("\nAnimation bake (SMPL-H motion on the SMPL-sized model)\n");
  benchAnimation(smpl, quick ? 0.5 : minutes);
  return 0;
}
