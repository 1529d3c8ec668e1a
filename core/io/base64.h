// Base64 (RFC 4648, standard alphabet, '=' padding) as glTF data URIs carry
// buffers ("data:application/octet-stream;base64,..."): the Meshcapade scene
// files (.mcs) embed their .smpl bodies and camera tracks this way.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "core/result.h"

namespace smpl {

// The bytes `text` encodes. Strict: only the alphabet, a length that is a
// multiple of 4, padding only at the end; no whitespace. The output is charged
// to the memory budget before it is allocated (returned with its size only:
// the caller holds it briefly). Errors name `context`: "x.mcs: buffer 1:
// base64 data is truncated (2047 characters, not a multiple of 4)",
// "...: not base64 (character 0x20 at 17)".
Result<std::vector<uint8_t>> decodeBase64(std::string_view text, const std::string& context);

// The number of bytes `text` decodes to, from its length and padding alone
// (no decoding): lets a caller check a declared length first.
uint64_t base64DecodedSize(std::string_view text);

}  // namespace smpl
