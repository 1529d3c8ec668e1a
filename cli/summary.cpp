#include "cli/summary.h"

#include <cstdio>

#include "cli/batch_report.h"
#include "core/io/printable.h"
#include "core/stopwatch.h"
#include "exporter/export_skin.h"

namespace smpl {

void printNotes(const ExportReport& r, bool quiet) {
  // The model used is not the one asked for (a folder's fallback): a warning.
  if (!r.model_note.empty())
    std::fprintf(stderr, "warning: %s\n", printable(r.model_note, 4096).c_str());
  if (quiet) return;
  if (!r.betas_note.empty()) std::fprintf(stderr, "note: %s\n", r.betas_note.c_str());
  for (const std::string& note : r.notes)
    std::fprintf(stderr, "note: %s\n", printable(note, 4096).c_str());
}

void printSummary(const std::string& out, const ExportReport& r) {
  if (!r.skin_fitted && r.vertices == 0)  // a format without a mesh (BVH)
    std::printf("%s: %d joints, skeleton only, %.2f MB, %.0f ms\n", printable(out).c_str(),
                r.joints, r.bytes / 1e6, r.seconds * 1e3);
  else
    std::printf("%s: %d vertices, %d joints, %d morph targets, %.2f MB, %.0f ms\n",
                printable(out).c_str(), r.vertices, r.joints, r.morph_targets, r.bytes / 1e6,
                r.seconds * 1e3);
  if (r.frames > 0) std::printf("animation: %d frames\n", r.frames);
  if (r.placement.origin != "model")
    std::printf("origin: %s (every position moved %+.6f m in y%s)\n", r.placement.origin.c_str(),
                r.placement.floor_offset,
                r.placement.root_bone ? "; root bone 'root' below the pelvis" : "");
  if (r.skin_error_measured) {
    const PruningError& err = r.skin_error;
    std::printf(
        "skinning error of %d influences vs all (%d held-out random poses): %s mean %.3f mm, max "
        "%.3f mm",
        r.max_influences, err.poses, skinWeightMethodName(r.options.skin_weights), err.mean_m * 1e3,
        err.max_m * 1e3);
    if (err.refit) std::printf(" with corrective refit");
    if (err.refit)
      std::printf("; without refit mean %.3f mm, max %.3f mm", err.without_refit.mean_m * 1e3,
                  err.without_refit.max_m * 1e3);
    if (r.options.skin_weights != SkinWeightMethod::Truncated || err.refit)
      std::printf("; truncated mean %.3f mm, max %.3f mm", err.truncated.mean_m * 1e3,
                  err.truncated.max_m * 1e3);
    std::printf("\n");
  }
  std::printf("model: %s\n", printable(r.model_path).c_str());
}

void drawProgress(const std::string& name, double fraction) {
  static std::string current;  // the motion being baked, and when its bar started
  static SteadyTime start;
  if (name != current || fraction <= 0) current = name, start = steadyNow();
  const double elapsed = secondsSince(start);
  const int width = 24, filled = static_cast<int>(fraction * width);
  const std::string eta = fraction >= 1.0 ? formatDuration(elapsed) + "     "
                          : fraction > 0.02
                              ? "ETA " + formatDuration(elapsed / fraction * (1 - fraction))
                              : "ETA ?   ";
  std::fprintf(stderr, "\rbaking %-20.20s [%s%s] %3d%% %s", printable(name).c_str(),
               std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
               static_cast<int>(fraction * 100), eta.c_str());
  if (fraction >= 1.0) std::fprintf(stderr, "\n");
}

}  // namespace smpl
