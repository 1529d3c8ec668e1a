// UTF-8 in one place: the encoder shared by the pickle reader (Python str) and
// numpy string arrays (UTF-32 'U' elements), the decoder of one well-formed
// sequence that printable() (core/io/printable.h), the name escaping below and
// the MJCF .npz writer (joint names as 'U' elements) use, and that escaping
// itself. Text, not I/O: in core so that readers and writers share it. Names that come from files
// (a motion file's stem becomes a clip name, a model file's stem the metadata's model_name) go into
// glTF JSON, FBX strings and the sidecar, which must be valid UTF-8: escapeInvalidUtf8 makes them
// so, deterministically and without touching valid (non-ASCII) names.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace smpl {

// Append `cp` (at most 0x10FFFF) to `out` as UTF-8. Surrogates are encoded as
// they are, like Python's "surrogatepass"; callers that must produce strict
// Unicode check the code point first.
void appendUtf8(std::string* out, uint32_t cp);

// Length (1..4) of the well-formed UTF-8 sequence that starts at text[i], with
// its code point in *cp; 0 when the bytes there are not one (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF, no truncated tail).
size_t utf8SequenceLength(std::string_view text, size_t i, uint32_t* cp);

// True when every byte of `text` belongs to a well-formed UTF-8 sequence.
bool isValidUtf8(std::string_view text);

// `text` with each byte that is not part of a well-formed UTF-8 sequence
// replaced by the four characters "\xNN" (lowercase hex); valid UTF-8,
// control characters included, is kept as it is (JSON writers escape
// controls themselves). The result is always valid UTF-8, the function is
// idempotent, and the same bytes always give the same text:
//   escapeInvalidUtf8("walk\xff.npz") == "walk\\xff.npz"
//   escapeInvalidUtf8("caf\xc3\xa9")  == "caf\xc3\xa9"
std::string escapeInvalidUtf8(std::string_view text);

}  // namespace smpl
