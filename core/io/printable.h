// Untrusted text in error messages: npy header keys, dtype strings, npz and
// zip member names, pickle global names, JSON keys and user-given file names
// reach the terminal through errors. printable() makes such text one line of
// printable characters, so a file cannot move the cursor, recolour the
// terminal, overwrite the line with '\r' or split the error over two lines.
//
//   printable("ke\x1b[2Jy\r")  ==  "ke\\x1b[2Jy\\x0d"
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace smpl {

// Valid, printable UTF-8 passes unchanged. Every other byte becomes "\xNN":
// C0 controls (tab, newline, '\r', ESC...), DEL, the bytes of C1 controls
// (U+0080..U+009F) and bytes that are not well-formed UTF-8 (overlong forms,
// surrogates, truncated sequences). Backslashes are kept as they are, so the
// function is idempotent: escaping an escaped message changes nothing, and a
// message can be escaped where it is built and again where it is printed.
// Text longer than `max_bytes` is cut at a character boundary and ends "...".
std::string printable(std::string_view text, size_t max_bytes = 256);

// As printable(), but text longer than `max_bytes` (after escaping) keeps its
// beginning and its end and loses its middle, replaced by "...", cut at
// character and escape boundaries. For error lines, whose reason comes last:
//   printableMiddle("Error saving /a/<4000 bytes>/b.glb: File name too long", 60)
//     == "Error saving /a/aaaaaaaaaa...aaaaaaa/b.glb: File name too long"
// (the result is at most `max_bytes` bytes; idempotent like printable()).
std::string printableMiddle(std::string_view text, size_t max_bytes);

}  // namespace smpl
