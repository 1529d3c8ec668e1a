// Names that come from data (a track id read from a motion file: a pickle's
// dict key, a JSON person id, a folder name) become part of output file
// names only through safeNameComponent(). Pasted in as they are, such ids
// were paths: "X/../../../tmp/victim" climbed out of the output folder
// through a planted folder or link, an id with a newline made a file name
// with a newline, a 300-digit id failed at write time after other tracks
// were committed. The mapping keeps readable ids readable ("0", "person_2"),
// escapes every other byte the way URLs do (reversible), and bounds the
// length, so the result is always one plain file-name component on every
// file system the tool writes to (Linux, Windows, macOS).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace smpl {

// Longest component safeNameComponent() returns, in bytes.
inline constexpr size_t kMaxNameComponent = 64;

// `id` as one file-name component:
//   - ASCII letters, digits, '-' and '_' are kept; '.' is kept except as the
//     first or the last byte (never ".", "..", a hidden name or a name that
//     Windows strips);
//   - every other byte (path separators, '%', spaces, control bytes, bytes of
//     non-ASCII UTF-8) becomes "%XX", two upper-case hex digits;
//   - the empty id becomes "%" (a component is never empty);
//   - a result longer than kMaxNameComponent keeps its first bytes (never
//     half an escape) and ends "~" + the first 16 hex digits of the SHA-256
//     of `id`: distinct ids still give distinct names ('~' is escaped in
//     short names, so a bounded name never equals an unbounded one).
// Distinct ids give distinct components (up to the 64-bit hash suffix of
// ids longer than the bound). Examples: "12" -> "12", "a/b" -> "a%2Fb",
// ".." -> "%2E.", "x\n" -> "x%0A", "50%" -> "50%25".
std::string safeNameComponent(std::string_view id);

// The id a component of safeNameComponent() was made from; nothing for a
// bounded (hashed) component or text that no id maps to.
std::optional<std::string> idOfNameComponent(std::string_view component);

}  // namespace smpl
