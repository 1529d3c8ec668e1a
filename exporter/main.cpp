// smpl-export: a thin main. Parse and check every option, then run the
// pipeline: load -> build asset -> serialise -> write atomically -> summary.
#include <chrono>
#include <cstdio>
#include <string>

#include "core/demo_body.h"
#include "core/file_io.h"
#include "core/model_loader.h"
#include "exporter/metadata_json.h"
#include "exporter/pipeline.h"
#include "exporter/pruning_error.h"
#include "exporter/settings.h"
#include "plugins/writer.h"

using namespace smpl;

namespace {

enum Exit { kOk = 0, kUsage = 1, kLoad = 2, kExport = 3, kSave = 4 };

int fail(Exit code, const std::string& what, const std::string& message) {
  std::fprintf(stderr, "Error %s: %s\n", what.c_str(), message.c_str());
  return code;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void printSummary(const Settings& s, const Asset& asset, size_t bytes, double seconds, const PruningError& err) {
  std::printf("%s: %zu vertices, %zu joints, %zu morph targets, %.2f MB, %.0f ms\n", s.out.c_str(),
              static_cast<size_t>(asset.mesh.positions.rows()), asset.skeleton.names.size(),
              asset.mesh.morph_targets.size(), bytes / 1e6, seconds * 1e3);
  std::printf("skinning error of %d influences vs all (%d random poses): mean %.3f mm, max %.3f mm\n",
              asset.metadata.max_influences, err.poses, err.mean_m * 1e3, err.max_m * 1e3);
}

}  // namespace

int main(int argc, char** argv) {
  Result<Settings> parsed = parseSettings(argc, argv);
  if (!parsed) return fail(kUsage, "in arguments", parsed.message());
  Settings& s = *parsed;
  if (s.help) return std::printf("%s", usageText().c_str()), kOk;
  if (s.version) return std::printf("smpl-export %s\n", SMPL_EXPORT_VERSION), kOk;
  const Writer* writer = writerForPath(s.out);
  if (!writer) return fail(kUsage, "in arguments", "no writer for " + s.out);
  const auto start = std::chrono::steady_clock::now();

  if (!s.betas_file.empty()) {
    Result<std::vector<double>> betas = readBetasFile(s.betas_file);
    if (!betas) return fail(kLoad, "loading " + s.betas_file, betas.message());
    s.export_options.betas = *betas;
  }
  Result<BodyModel> loaded = s.model == "builtin" ? Result<BodyModel>(demoBody()) : loadModel(s.model);
  if (!loaded) return fail(kLoad, "loading " + s.model, loaded.message());
  const BodyModel& model = *loaded;

  Result<Asset> asset = buildAsset(model, s.export_options);
  if (!asset) return fail(kExport, "exporting " + s.out, asset.message());
  Result<std::string> bytes = writer->serialize(*asset, s.writer_options);
  if (!bytes) return fail(kExport, "exporting " + s.out, bytes.message());
  const double seconds = secondsSince(start);

  if (Status st = writeFileAtomic(s.out, *bytes); !st) return fail(kSave, "saving " + s.out, st.message());
  const std::string sidecar = s.out + ".smpl.json";
  if (Status st = writeFileAtomic(sidecar, metadataJson(*asset)); !st) {
    std::remove(s.out.c_str());  // no half-finished export: the file and its metadata go together
    return fail(kSave, "saving " + sidecar, st.message());
  }
  if (!s.quiet) {
    Result<PruningError> err = measurePruningError(model, s.export_options, s.error_poses);
    if (!err) return fail(kExport, "measuring " + s.out, err.message());
    printSummary(s, *asset, bytes->size(), seconds, *err);
  }
  return kOk;
}
