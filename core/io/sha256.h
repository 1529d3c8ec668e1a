// SHA-256 (FIPS 180-4, computed by OpenSSL or Windows CNG) of bytes or of a file, as lowercase hex:
// the digest the batch manifest records for each output and the sidecar records for every file of
// its output (exporter/metadata_json.h), which batch mode verifies (`sha256sum` prints the same).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/byte_span.h"
#include "core/result.h"

namespace smpl {

std::string sha256Hex(const std::string& bytes);
std::string sha256Hex(const void* data, size_t size);
// Of `data` followed by the parts of `tail` (a file written in parts), without joining them.
std::string sha256Hex(const void* data, size_t size, const std::vector<ByteSpan>& tail);

// Errors name the file.
Result<std::string> sha256File(const std::string& path);

}  // namespace smpl
