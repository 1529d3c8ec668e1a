// --preset web|engine|archive: named bundles of the size options (README
// "Size"), so nobody has to find the combination by hand. A preset is
// applied after argv is parsed: each of its options that was not given
// explicitly is applied as if typed (explicit options override), and only
// where it applies: format-only options for the output formats that take
// them, --quantize-animation only with a motion, the morph-target options
// only with correctives. Their sizes and errors are measured by
// tools/bench/preset_table.py; docs/performance.md shows the recorded table
// (numbers are not repeated in --help, where they could only be typed by hand).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/result.h"

namespace smpl {

struct Settings;

struct Preset {
  std::string name;                                          // --preset value
  std::string purpose;                                       // who reads the file
  std::vector<std::pair<std::string, std::string>> options;  // (option, value) as typed
};

// web, engine, archive (usage order).
const std::vector<Preset>& presets();

// The --help text of the presets: one paragraph each, "name: purpose; options".
std::string presetsHelp();

// Applies settings->preset's options that were not given (see above). An
// unknown name is a usage error naming the choices; so is a preset whose
// output must be glTF (web) with another format.
Status applyPreset(const std::string& name, Settings* settings);

}  // namespace smpl
