// std::filesystem paths from and to the UTF-8 strings the project passes
// around. On Windows, libstdc++ reads a narrow std::string as Latin-1 (each
// byte one UTF-16 unit) whatever the code page, so "Jürgen.npz" would name
// "JÃ¼rgen.npz"; fs::u8path / u8string convert UTF-8 properly there. On POSIX
// both are the bytes as they are. Every std::filesystem call on a user's path
// goes through fsPath(), and every path turned back into a string through
// utf8() (scripts/check-portable.py flags fs::path(...) and .string()).
#pragma once

#include <filesystem>
#include <string>

namespace smpl::os {

inline std::filesystem::path fsPath(const std::string& utf8_path) {
#ifdef _WIN32
  return std::filesystem::u8path(utf8_path);
#else
  return std::filesystem::path(utf8_path);
#endif
}

inline std::string utf8(const std::filesystem::path& p) {
#ifdef _WIN32
  return p.u8string();
#else
  return p.string();
#endif
}

// utf8() with '/' separators on every platform (relative names that must
// compare equal across platforms: batch shards, model folder entries).
inline std::string genericUtf8(const std::filesystem::path& p) {
#ifdef _WIN32
  return p.generic_u8string();
#else
  return p.generic_string();
#endif
}

}  // namespace smpl::os
