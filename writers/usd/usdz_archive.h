// A .usdz package (the Usdz File Format Specification,
// openusd.org/release/spec_usdz.html): a zip archive whose files are stored
// uncompressed, each file's data starting at a multiple of 64 bytes from
// the start of the archive, the first file the root layer. The padding is
// an extra field of the local header (header id 0x1986, zeros), as
// OpenUSD's own writer pads (pxr/usd/usd/zipFile.cpp). Deterministic: fixed
// timestamps (1980-01-01 00:00, the earliest DOS date), no attributes.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

struct UsdzFile {
  std::string name;   // path inside the archive ("body.usda"), ASCII
  std::string bytes;  // stored as they are
};

// The archive of `files` in order. Errors: an empty or non-ASCII name, or
// an archive beyond the 4 GiB of a zip without zip64.
Result<std::string> usdzArchive(const std::vector<UsdzFile>& files);

}  // namespace smpl
