#include "cli/summary.h"

#include <cstdio>

#include "core/io/printable.h"
#include "exporter/export_skin.h"

namespace smpl {

void printSummary(const std::string& out, const ExportReport& r) {
  if (!r.betas_note.empty()) std::printf("note: %s\n", r.betas_note.c_str());
  if (!r.model_note.empty()) std::printf("note: %s\n", printable(r.model_note, 4096).c_str());
  std::printf("%s: %d vertices, %d joints, %d morph targets, %.2f MB, %.0f ms\n",
              printable(out).c_str(), r.vertices, r.joints, r.morph_targets, r.bytes / 1e6,
              r.seconds * 1e3);
  if (r.frames > 0) std::printf("animation: %d frames\n", r.frames);
  if (r.placement.origin != "model")
    std::printf("origin: %s (every position moved %+.6f m in y%s)\n", r.placement.origin.c_str(),
                r.placement.floor_offset,
                r.placement.root_bone ? "; root bone 'root' below the pelvis" : "");
  for (const std::string& note : r.notes) std::printf("note: %s\n", printable(note, 4096).c_str());
  if (r.skin_error_measured) {
    const PruningError& err = r.skin_error;
    std::printf(
        "skinning error of %d influences vs all (%d held-out random poses): %s mean %.3f mm, max "
        "%.3f mm",
        r.max_influences, err.poses, skinWeightMethodName(r.options.skin_weights), err.mean_m * 1e3,
        err.max_m * 1e3);
    if (r.options.skin_weights != SkinWeightMethod::Truncated)
      std::printf("; truncated mean %.3f mm, max %.3f mm", err.truncated.mean_m * 1e3,
                  err.truncated.max_m * 1e3);
    std::printf("\n");
  }
  std::printf("model: %s\n", printable(r.model_path).c_str());
}

void drawProgress(const std::string& name, double fraction) {
  const int width = 30, filled = static_cast<int>(fraction * width);
  std::fprintf(stderr, "\r%-24.24s [%s%s] %3d%%", name.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100));
  if (fraction >= 1.0) std::fprintf(stderr, "\n");
}

}  // namespace smpl
