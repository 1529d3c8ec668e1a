// settingsOf, _options, _cli: see py_settings.h.
#include "python/bindings/py_settings.h"

#include <pybind11/stl.h>

#include "cli/command_line.h"
#include "cli/options.h"
#include "python/bindings/py_errors.h"

namespace pyb = pybind11;
using namespace pybind11::literals;

namespace smpl::py {
namespace {

// argv for the parser: the program name, then `args`.
std::vector<char*> argvOf(std::vector<std::string>* args) {
  std::vector<char*> argv;
  static char program[] = "smpl-export";
  argv.push_back(program);
  for (std::string& a : *args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return argv;
}

}  // namespace

Settings settingsOf(const std::vector<std::string>& args) {
  std::vector<std::string> copy = args;
  std::vector<char*> argv = argvOf(&copy);
  Result<Settings> s = parseSettings(static_cast<int>(argv.size()) - 1, argv.data());
  if (!s) throw Failure{"Error in arguments: " + s.message(), 1};
  if (isBatch(*s))
    throw usageFailure(
        "Error in arguments: batch mode (motion_dir, out_dir) is the command line's: call "
        "smpl_export.cli([...]) or export() per motion");
  return std::move(*s);
}

void registerSettings(pyb::module_& m) {
  m.def("_options", [] {
    std::vector<std::pair<std::string, bool>> out;
    for (const OptionSpec& o : optionTable()) out.emplace_back(o.name, o.value != nullptr);
    return out;
  });
  m.def(
      "_cli",
      [](std::vector<std::string> args) {
        std::vector<char*> argv = argvOf(&args);
        pyb::gil_scoped_release release;
        return runCommandLine(static_cast<int>(argv.size()) - 1, argv.data());
      },
      "args"_a);
}

}  // namespace smpl::py
