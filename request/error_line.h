// The one form of every error line a run prints (docs/cli.md "Exit codes and
// errors"): "Error <doing> <file>: <problem>".
#pragma once

#include <string>

namespace smpl {

// "Error <verb> <path>: <reason>", without repeating the path when the reason
// already starts with it (core errors name their file). Paths and messages
// may carry bytes from files or the command line: the line is printable()
// (core/io/printable.h), at most 4 KiB: a path over 1 KiB is shortened in its
// middle wherever it appears, then a line still too long loses its middle, so
// the reason at the end is always kept
// ("Error saving /data/aaaa...aaaa/x.glb: cannot create: File name too long").
std::string errorLine(const std::string& verb, const std::string& path, const std::string& message);

}  // namespace smpl
