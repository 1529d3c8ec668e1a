// Exit codes of smpl-export, from the kind of error (core/result.h).
#pragma once

#include "core/result.h"

namespace smpl {

enum ExitCode { kExitOk = 0, kExitUsage = 1, kExitLoad = 2, kExitExport = 3, kExitSave = 4 };

// Usage -> 1, Load -> 2, Export (and an error no stage classified) -> 3, Write -> 4.
inline ExitCode exitCodeFor(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Usage:
      return kExitUsage;
    case ErrorKind::Load:
      return kExitLoad;
    case ErrorKind::Write:
      return kExitSave;
    default:
      return kExitExport;
  }
}

}  // namespace smpl
