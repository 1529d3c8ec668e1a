#include "cli/presets.h"

#include <algorithm>

#include "cli/options.h"
#include "cli/settings.h"
#include "writers/writer.h"

namespace smpl {
namespace {

Error usageError(const std::string& message) { return makeError(message, ErrorKind::Usage); }

bool given(const Settings& s, const std::string& name) {
  return std::any_of(s.given_options.begin(), s.given_options.end(),
                     [&](const auto& o) { return o.first == name; });
}

// Whether `option` of a preset applies to this run (cli/presets.h).
bool applies(const Settings& s, const std::string& option) {
  const OptionSpec* spec = findOption(option);
  const WriterFormat* format = outputFormat(s);
  if (spec->applies == Applies::Format &&
      (!format ||
       std::find(format->options.begin(), format->options.end(), option) == format->options.end()))
    return false;
  const bool animated = !s.request.motions.empty() || isBatch(s);
  if (option == "--quantize-animation") return animated;
  if (option == "--quantize-morphs" || option == "--corrective-epsilon")
    return s.request.asset.correctives;
  return true;
}

}  // namespace

const std::vector<Preset>& presets() {
  static const std::vector<Preset> table = {
      {"web",
       "the smallest file three.js, Babylon.js and glTFast load",
       {{"--max-influences", "4"},
        {"--quantize-morphs", ""},
        {"--corrective-epsilon", "1e-5"},
        {"--quantize-animation", ""},
        {"--meshopt", ""}}},
      {"engine",
       "what Unity, Unreal and Godot import without an extension or an encoding they may lack "
       "(no Draco, meshopt or quantisation; sparse accessors are core glTF; add "
       "--quantize-animation for importers that read normalised keys)",
       {{"--max-influences", "4"}, {"--corrective-epsilon", "1e-5"}}},
      {"archive",
       "exact: every influence of the model, float data",
       {{"--max-influences", "all"}, {"--skin-weights", "truncated"}}},
  };
  return table;
}

std::string presetsHelp() {
  std::string text;
  for (const Preset& p : presets()) {
    std::string options;
    for (const auto& [name, value] : p.options)
      options += (options.empty() ? "" : " ") + name + (value.empty() ? "" : " " + value);
    text += "\n" + p.name + ": " + p.purpose + "; " + options;
  }
  return text;
}

Status applyPreset(const std::string& name, Settings* s) {
  auto p = std::find_if(presets().begin(), presets().end(),
                        [&](const Preset& preset) { return preset.name == name; });
  if (p == presets().end())
    return usageError("--preset: expected 'web', 'engine' or 'archive', got '" + name + "'");
  const WriterFormat* format = outputFormat(*s);
  if (p->name == "web" && format && format->name == "fbx")
    return usageError(
        "--preset web makes glTF files (meshopt, quantised); FBX output has neither: use .glb, or "
        "--preset engine");
  for (const auto& [option, value] : p->options) {
    if (given(*s, option) || !applies(*s, option)) continue;
    if (option == "--meshopt" && !meshoptAvailable()) continue;  // the static build (writer.h)
    if (Status st = findOption(option)->apply(value, s); !st) return st;
  }
  return Status();
}

}  // namespace smpl
