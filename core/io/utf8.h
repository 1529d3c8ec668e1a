// UTF-8 encoding of one code point, shared by the pickle reader (Python str)
// and numpy string arrays (UTF-32 'U' elements), so there is one encoder.
#pragma once

#include <cstdint>
#include <string>

namespace smpl {

// Append `cp` (at most 0x10FFFF) to `out` as UTF-8. Surrogates are encoded as
// they are, like Python's "surrogatepass"; callers that must produce strict
// Unicode check the code point first.
void appendUtf8(std::string* out, uint32_t cp);

}  // namespace smpl
