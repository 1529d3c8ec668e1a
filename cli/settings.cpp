// parseSettings: every option through the one table (cli/options.h), then the
// rules of where options apply. Nothing here touches a file, and no value is
// range-checked here: the request does that (request/check_request.h).
#include "cli/settings.h"

#include <algorithm>

#include "cli/options.h"
#include "cli/presets.h"
#include "core/io/printable.h"
#include "request/check_request.h"

namespace smpl {
namespace {

Error usageError(const std::string& message) { return makeError(message, ErrorKind::Usage); }

bool given(const Settings& s, const char* name) {
  return std::any_of(s.given_options.begin(), s.given_options.end(),
                     [&](const auto& o) { return o.first == name; });
}

// Whether the output format's writer row lists a format-only option; an
// unknown format lists everything (the request refuses the format itself).
bool formatTakes(const WriterFormat* format, const std::string& option) {
  return !format ||
         std::find(format->options.begin(), format->options.end(), option) != format->options.end();
}

// An option used where its table entry says it does not apply.
Status checkApplies(const Settings& s, bool batch) {
  const bool animated = !s.request.motions.empty() || batch;
  const WriterFormat* format = outputFormat(s);
  for (const auto& [name, value] : s.given_options) {
    const OptionSpec* o = findOption(name);
    const bool ok = o->applies == Applies::Any || (o->applies == Applies::Single && !batch) ||
                    (o->applies == Applies::Motion && animated) ||
                    (o->applies == Applies::Batch && batch) ||
                    (o->applies == Applies::Format && formatTakes(format, name)) ||
                    (o->applies == Applies::Mesh && (!format || format->needs_mesh));
    if (!ok && o->applies == Applies::Mesh)  // the request's wording (check_request.cpp)
      return usageError(name + " " + appliesRule(*o) + "; " + format->name + " output has none");
    if (!ok) return usageError(name + " " + appliesRule(*o));
  }
  return Status();
}

Status checkRules(const Settings& s) {
  const bool batch = isBatch(s);
  if (batch && (s.request.motion_dir.empty() || s.out_dir.empty()))
    return usageError("batch mode needs both --motion-dir and --out-dir");
  return checkApplies(s, batch);
}

// The option at argv[*i] and its value ("--name=value", "--name value", or a
// flag); advances *i past a separate value.
Status takeOption(int argc, const char* const* argv, int* i, Settings* s) {
  std::string arg = argv[*i], value;
  const size_t eq = arg.find('=');
  if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
    value = arg.substr(eq + 1);
    arg = arg.substr(0, eq);
  }
  const OptionSpec* o = findOption(arg);
  if (!o && arg.rfind("-", 0) != 0)
    return usageError("unexpected argument '" + printable(arg) +
                      "': options start with -- (see --help)");
  if (!o) return usageError("unknown option '" + printable(arg) + "' (see --help)");
  if (!o->value && eq != std::string::npos && arg.size() < std::string(argv[*i]).size())
    return usageError(std::string("option ") + o->name + " takes no value");
  if (o->value && eq == std::string::npos) {
    if (*i + 1 >= argc) return usageError(std::string("option ") + o->name + " needs a value");
    value = argv[++*i];
  }
  const std::string name = o->name;  // aliases count as their option
  if (name != "--motion" && name != "--hands" && given(*s, name.c_str()))  // repeatable
    return usageError("option " + name + " given twice");
  s->given_options.emplace_back(name, value);
  return o->apply(value, s);
}

}  // namespace

bool isBatch(const Settings& s) { return given(s, "--motion-dir") || given(s, "--out-dir"); }

const WriterFormat* outputFormat(const Settings& s) {
  if (!isBatch(s)) return writerFormatForPath(s.request.out);
  return batchFormat(s.request);
}

Result<Settings> parseSettings(int argc, const char* const* argv) {
  Settings s;
  for (int i = 1; i < argc; ++i)
    if (Status st = takeOption(argc, argv, &i, &s); !st) return st.error();
  for (const auto& option : s.given_options)  // the producer hash: options that change the bytes
    if (findOption(option.first)->hashed == Hashed::Value)
      s.request.hashed_options.push_back(option);
  if (s.help || s.version) return s;
  if (!s.preset.empty())
    if (Status st = applyPreset(s.preset, &s); !st) return st.error();
  if (Status st = checkRules(s); !st) return st.error();
  return s;
}

}  // namespace smpl
