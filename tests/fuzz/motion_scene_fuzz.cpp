// libFuzzer entry point for the multi-person and hand readers motion_fuzz
// does not reach (it writes only .npz / .json and reads one track):
// PromptHMR results.pkl (motion_prompthmr.cpp), the Meshcapade `.mcs` glTF
// scene (motion_mcs.cpp, motion_mcs_gltf.cpp), Multi-HMR per-image .npz
// (motion_multihmr.cpp) and HaMeR hand tracks (motion_hamer.cpp) combined
// into a body clip (combine_hands.cpp).
//
// The first byte picks: bits 0-1 the file's extension (.pkl, .mcs, .npz,
// .json; readers sniff the content, the extension only names the file),
// bit 2 a frame of a --motion-sequence (MotionOptions::frame_file: HaMeR
// rows become tracks, an empty Multi-HMR image is allowed), bit 3 the
// --source-params (the default / incam), bit 4 the tracks are also put as hand
// tracks into a synthetic SMPL-X body clip (combineHands, with bit 5 the
// wrists). The rest is the file, written to a private temporary because
// loadMotionSet reads a path. The memory budget is 1 GiB, below libFuzzer's
// -rss_limit_mb, so a hostile size must end in the budget's error.
// Seeds: tests/fuzz/seeds/motion_scene/ (tests/fuzz/seeds/README.md).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/memory_budget.h"
#include "core/motions/combine_hands.h"
#include "core/motions/motion.h"

namespace {

// Touch every value so a bad size pairing would show up under ASan.
void touch(const smpl::Motion& m) {
  double sum = m.fps;
  for (const auto& frame : m.frames)
    for (const auto& r : frame) sum += r.sum();
  for (const auto& t : m.translation) sum += t.sum();
  for (double b : m.betas) sum += b;
  sum += m.expression.sum();
  volatile double sink = sum;
  (void)sink;
}

// A short SMPL-X body clip in the camera frame, as --hands combines into.
smpl::Motion body(size_t frames) {
  smpl::Motion m;
  m.layout = smpl::ModelKind::SmplX;
  m.world = smpl::MotionWorld::CameraYDown;
  m.frames.assign(frames, smpl::Rotations(55, Eigen::Matrix3d::Identity()));
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  smpl::setMemoryLimit(1ull << 30);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".pkl", ".mcs", ".npz", ".json"};
  const uint8_t mode = data[0];
  const std::string path =
      "/tmp/smpl_motion_scene_fuzz_" + std::to_string(::getpid()) + kExtensions[mode & 3];
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  smpl::MotionOptions options;
  options.frame_file = (mode & 4) != 0;
  options.source_params = (mode & 8) ? smpl::SourceParams::Incam : smpl::SourceParams::Default;
  smpl::Result<smpl::MotionSet> set = smpl::loadMotionSet(path, options);
  std::remove(path.c_str());
  if (!set.ok()) return 0;
  for (const smpl::Motion& m : set->tracks) touch(m);
  if ((mode & 16) && !set->tracks.empty()) {
    std::vector<smpl::HandTrack> hands;
    for (const smpl::Motion& m : set->tracks) hands.push_back(smpl::HandTrack{&m, path});
    smpl::Motion b = body(set->tracks.front().frames.size());
    if (combineHands(hands, (mode & 32) != 0, "body.npz", &b).ok()) touch(b);
  }
  return 0;
}
