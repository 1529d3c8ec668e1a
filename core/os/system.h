// The operating system's process and machine facts, as the project uses them:
// one implementation per OS (system_posix.cpp, system_win32.cpp), chosen by
// core/CMakeLists.txt.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace smpl::os {

// This process's id.
uint64_t processId();
// `size` bytes from the OS's random source (getrandom(2) / BCryptGenRandom);
// false when it has none ready (the caller falls back to a hash of time and pid).
bool randomBytes(void* out, size_t size);
// The machine's physical memory in bytes, or 0 when unknown.
uint64_t physicalMemoryBytes();
// This program's executable as an absolute UTF-8 path (/proc/self/exe,
// GetModuleFileNameW), or "" where the OS cannot tell (WebAssembly).
std::string executablePath();
// Whether standard stream `fd` (1: stdout, 2: stderr) is a terminal.
bool isTerminal(int fd);

// The command line as UTF-8: POSIX passes argv through; Windows reads it again
// as UTF-16 (GetCommandLineW, CommandLineToArgvW) and converts it, so
// non-ASCII file names survive whatever the console's code page.
class Utf8Arguments {
 public:
  Utf8Arguments(int argc, char** argv);
  int argc() const { return static_cast<int>(args_.size()); }
  char** argv() { return pointers_.data(); }

 private:
  std::vector<std::string> args_;
  std::vector<char*> pointers_;  // into args_, then a null
};

// Standard streams as the POSIX build writes them: on Windows stdout and
// stderr in binary mode ("\n" stays one byte) and the console's output code
// page UTF-8. Nothing on POSIX.
void prepareStandardStreams();

// For the command-line program only, at startup (never in a library that a
// host process loads: its signals are the host's): SIGXFSZ and SIGPIPE
// ignored, so a write past `ulimit -f` or into a closed pipe fails with
// EFBIG / EPIPE and is reported as a write error, its temporary removed,
// instead of killing the process mid-write. Nothing on Windows (no such signals).
void ignoreWriteSignals();

}  // namespace smpl::os
