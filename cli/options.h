// The one table of smpl-export's options. The parser (cli/settings.cpp), the
// conflict checks and the usage text (--help) all read it, and a test checks
// the README's option table against --help, so an option is described once.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

struct Settings;

// Where an option may be used; the parser refuses it anywhere else, naming
// the rule.
enum class Applies {
  Any,     // every run
  Single,  // one export (--out), not batch mode
  Motion,  // needs --motion or --motion-dir
  Batch,   // only batch mode (--motion-dir)
  Format,  // only the output formats whose writer row lists it (writers/writer.h
           // WriterFormat::options: --draco for .glb/.gltf, --fbx-units for .fbx, ...)
  Mesh,    // only the output formats with a mesh (WriterFormat::needs_mesh): the skin,
           // morph targets, UVs and mesh name options, refused for a skeleton-only .bvh
};

// How an option enters the producer hash (request/producer.h), which decides
// whether an existing output is up to date.
enum class Hashed {
  Value,    // as given: it changes the bytes written
  No,       // it does not change the bytes written (--threads, --out, ...)
  Content,  // it names an input, which producer.cpp hashes by content
};

struct OptionSpec {
  const char* name;   // "--max-influences"
  const char* alias;  // a short form ("-q"), or nullptr
  const char* value;  // the value's syntax in the usage text ("N"); nullptr: a flag
  Applies applies;
  const char* heading;  // starts a new section of the usage text, or nullptr
  const char* help;     // usage text; '\n' continues on the next line
  // Stores the value into the settings (a flag gets ""). Errors name the option.
  Status (*apply)(const std::string& value, Settings* s);
  Hashed hashed = Hashed::Value;
};

// Every option, in usage order.
const std::vector<OptionSpec>& optionTable();

// The entry for a name or alias, or nullptr.
const OptionSpec* findOption(const std::string& name);

// "needs --motion or --motion-dir", "applies only to batch mode (--motion-dir)",
// "applies only to .glb, .gltf output" (Applies::Format: the extensions of
// the writer rows that list the option), "needs an output format with a mesh"
// (Applies::Mesh), ...
std::string appliesRule(const OptionSpec& option);

// The --help text, generated from this table and the writer table (the
// formats' names and extensions: --format's choices, --out's extensions).
std::string usageText();

}  // namespace smpl
