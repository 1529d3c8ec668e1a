// readPickleFile: kept apart from parsePickle so that in-memory users (the
// fuzz target) do not link file I/O.
#include "core/io/file_io.h"
#include "core/io/pickle/pickle.h"

namespace smpl {

Result<ArrayDict> readPickleFile(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  return parsePickle(bytes->data(), bytes->size(), baseName(path));
}

}  // namespace smpl
