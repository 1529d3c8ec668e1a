// SHA-256 (FIPS 180-4, computed by OpenSSL) of bytes or of a file, as lowercase hex: the digest
// the batch manifest records for each output (`sha256sum` prints the same).
#pragma once

#include <string>

#include "core/result.h"

namespace smpl {

std::string sha256Hex(const std::string& bytes);

// Errors name the file.
Result<std::string> sha256File(const std::string& path);

}  // namespace smpl
