// The one form of every error line a run prints (docs/cli.md "Exit codes and
// errors"): "Error <doing> <file>: <problem>".
#pragma once

#include <string>

namespace smpl {

// "Error <verb> <path>: <reason>", without repeating the path when the reason
// already starts with it (core errors name their file). Paths and messages
// may carry bytes from files or the command line: the line is printable()
// (core/io/printable.h), at most 4096 characters.
std::string errorLine(const std::string& verb, const std::string& path, const std::string& message);

}  // namespace smpl
