// parseSettings: every option through the one table (cli/options.h), then the
// rules that involve several options. Nothing here touches a file.
#include "cli/settings.h"

#include <algorithm>

#include "cli/options.h"
#include "core/io/printable.h"

namespace smpl {
namespace {

Error usageError(const std::string& message) { return makeError(message, ErrorKind::Usage); }

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool given(const Settings& s, const char* name) {
  return std::any_of(s.given_options.begin(), s.given_options.end(),
                     [&](const auto& o) { return o.first == name; });
}

// An option used where its table entry says it does not apply.
Status checkApplies(const Settings& s, bool batch, bool fbx) {
  const bool animated = !s.motions.empty() || batch;
  for (const auto& [name, value] : s.given_options) {
    const OptionSpec* o = findOption(name);
    const bool ok = o->applies == Applies::Any || (o->applies == Applies::Single && !batch) ||
                    (o->applies == Applies::Motion && animated) ||
                    (o->applies == Applies::Batch && batch) ||
                    (o->applies == Applies::Gltf && !fbx) || (o->applies == Applies::Fbx && fbx);
    if (!ok) return usageError(name + " " + appliesRule(o->applies));
  }
  return Status();
}

// Size options that would otherwise be silently ignored together (issue 13 item 6).
Status checkSizeOptionPairs(const Settings& s) {
  const ExportOptions& e = s.export_options;
  if (given(s, "--corrective-weights") && !e.correctives)
    return usageError(
        "--corrective-weights conflicts with --correctives none (no corrective targets to encode)");
  if (given(s, "--quantize-morphs") && !e.correctives)
    return usageError(
        "--quantize-morphs quantizes corrective targets; with --correctives none there are none");
  if (given(s, "--corrective-epsilon") && !e.correctives && e.shape_keys == 0 &&
      e.expression_keys == 0)
    return usageError(
        "--corrective-epsilon thins morph targets; with --correctives none and no --shape-keys/"
        "--expression-keys there are none");
  if (given(s, "--corrective-basis") && e.encoding == CorrectiveEncoding::Split)
    return usageError(
        "--corrective-basis conflicts with --corrective-weights split (basis weights are signed or "
        "unit)");
  return Status();
}

Status checkConflicts(const Settings& s) {
  if (s.model.empty())
    return usageError("missing --model PATH (use --model builtin for the demo body)");
  if (given(s, "--betas") && given(s, "--betas-file"))
    return usageError("--betas and --betas-file conflict: give one");
  if (s.betas_from_motion && s.betas_given)
    return usageError("--betas-from-motion conflicts with --betas/--betas-file");
  if (given(s, "--corrective-basis") && !s.export_options.correctives)
    return usageError("--corrective-basis conflicts with --correctives none");
  for (const char* o : {"--dmpl-count", "--dmpl-joints"})
    if (given(s, o) && s.dmpl.empty()) return usageError(std::string(o) + " needs --dmpl");
  if (Status st = checkSizeOptionPairs(s); !st) return st;
  const bool batch = given(s, "--motion-dir") || given(s, "--out-dir");
  if (batch && (s.motion_dir.empty() || s.out_dir.empty()))
    return usageError("batch mode needs both --motion-dir and --out-dir");
  if (!batch && s.out.empty()) return usageError("missing --out FILE (.glb, .gltf or .fbx)");
  const bool fbx = batch ? s.format == "fbx" : endsWith(s.out, ".fbx");
  if (!batch && !fbx && !endsWith(s.out, ".glb") && !endsWith(s.out, ".gltf"))
    return usageError("--out " + s.out + ": unknown format (expected .glb, .gltf or .fbx)");
  if (Status st = checkApplies(s, batch, fbx); !st) return st;
  if (given(s, "--gltf-embed") && (batch ? s.format != "gltf" : !endsWith(s.out, ".gltf")))
    return usageError("--gltf-embed applies only to .gltf output");
  return Status();
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
  if (name != "--motion" && given(*s, name.c_str()))
    return usageError("option " + name + " given twice");
  s->given_options.emplace_back(name, value);
  return o->apply(value, s);
}

}  // namespace

Result<Settings> parseSettings(int argc, const char* const* argv) {
  Settings s;
  for (int i = 1; i < argc; ++i)
    if (Status st = takeOption(argc, argv, &i, &s); !st) return st.error();
  s.betas_given = given(s, "--betas") || given(s, "--betas-file");
  s.writer_options.binary = !endsWith(s.out, ".gltf") && s.format != "gltf";
  if (s.help || s.version) return s;
  if (Status st = checkConflicts(s); !st) return st.error();
  return s;
}

}  // namespace smpl
