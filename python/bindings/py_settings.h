// Keyword options into the export request through the command line's own
// parser (cli/settings.h parseSettings over cli/options.h's table): the shim
// turns each keyword into the option it names ('-' for '_'), so every option,
// rule and message is the CLI's.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "cli/settings.h"

namespace smpl::py {

// `args` without the program name ("--model", "m.npz", "--out", "x.glb", ...).
// Errors (Failure, usage, exit 1): "Error in arguments: <the CLI's message>",
// batch mode.
Settings settingsOf(const std::vector<std::string>& args);

// _options(): (name, takes_value) of every CLI option, for the shim's keyword
// check; _cli(args): the command line in process.
void registerSettings(pybind11::module_& m);

}  // namespace smpl::py
