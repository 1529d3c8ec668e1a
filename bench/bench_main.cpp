// smpl-bench: prints the speed and size table of the product (issue "Speed and
// size"). Full-size synthetic models (bench/synthetic_model.h) stand in for the
// licensed ones. Usage: smpl-bench [--quick] [--anim-minutes M]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "bench/synthetic_model.h"
#include "core/forward.h"
#include "core/forward_batch.h"
#include "core/motion.h"
#include "core/pose_sampler.h"
#include "exporter/animation.h"
#include "exporter/pipeline.h"
#include "plugins/writer.h"

using namespace smpl;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

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
  for (const Eigen::VectorXd& pose : samplePoses(joints, count, 99)) frames.push_back(rotationsFromAxisAngle(pose));
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
    std::printf("| %-14s | write %-5s | %9.1f ms | %6.2f MB |\n", model.name.c_str(), ext + 1, ms, bytes / 1e6);
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
    std::printf("| %-14s | batch %4d, %d thr    | %7.3f ms/frame | %7.3f ms/frame/core |\n", model.name.c_str(),
                frames_count, threads, ms / frames_count, ms * threads / frames_count);
  }
}

void benchAnimation(const BodyModel& model, double minutes) {
  const int frames = static_cast<int>(minutes * 60 * 120);
  Motion motion;
  motion.name = "synthetic";
  motion.layout = ModelKind::SmplH;
  motion.fps = 120;
  motion.amass = true;
  std::vector<Eigen::VectorXd> poses = samplePoses(52, 64, 5, 0.5);
  for (int f = 0; f < frames; ++f) motion.frames.push_back(rotationsFromAxisAngle(poses[f % 64]));
  motion.translation.assign(frames, Eigen::Vector3d::Zero());
  Result<Asset> asset = buildAsset(model, ExportOptions());
  auto start = Clock::now();
  Result<AnimationClip> clip = bakeAnimation(model, *asset, motion, AnimationOptions(), "bench");
  const double bake = msSince(start);
  asset->animations.push_back(std::move(*clip));
  std::printf("| %-14s | bake %.0f min @120 fps (%d frames) | %8.0f ms | %9.0f frames/s |\n", model.name.c_str(),
              minutes, frames, bake, frames / (bake / 1e3));
  for (const char* ext : {".glb", ".fbx"}) {
    const Writer* w = writerForPath(std::string("x") + ext);
    if (!w) continue;
    start = Clock::now();
    Result<std::string> out = w->serialize(*asset, WriterOptions());
    const double ms = msSince(start);
    std::printf("| %-14s | + write %-4s | %8.0f ms | %9.0f frames/s | %7.1f MB |\n", model.name.c_str(), ext + 1, ms,
                frames / ((bake + ms) / 1e3), out.ok() ? out->size() / 1e6 : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  double minutes = 10;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--anim-minutes") && i + 1 < argc) minutes = std::atof(argv[++i]);
    else return std::fprintf(stderr, "usage: smpl-bench [--quick] [--anim-minutes M]\n"), 1;
  }
  std::printf("smpl-bench: %u hardware threads%s\n\n", std::thread::hardware_concurrency(), quick ? " (quick)" : "");
  const BodyModel smpl = syntheticModel(ModelKind::Smpl, 6890, 10, 0, 1);
  const BodyModel smplx = syntheticModel(ModelKind::SmplX, 10475, 300, 100, 2);
  std::printf("Export (median of %d)\n", quick ? 1 : 5);
  for (const BodyModel* m : {&smpl, &smplx}) benchExport(*m, quick ? 1 : 5);
  std::printf("\nForward pass\n");
  for (const BodyModel* m : {&smpl, &smplx}) benchForward(*m, quick ? 100 : 1000);
  std::printf("\nAnimation bake (SMPL-H motion on the SMPL-sized model)\n");
  benchAnimation(smpl, quick ? 0.5 : minutes);
  return 0;
}
