// POSIX implementation of core/os/system.h (Linux; also the WebAssembly
// build, whose emscripten libc has getentropy, not getrandom).
#include <signal.h>
#include <unistd.h>

#include <cstddef>
// <cstddef> first: emscripten's sys/random.h uses size_t.
#include <sys/random.h>

#include "core/os/system.h"

namespace smpl::os {

uint64_t processId() { return static_cast<uint64_t>(::getpid()); }

bool randomBytes(void* out, size_t size) {
#ifdef __EMSCRIPTEN__
  return size <= 256 && ::getentropy(out, size) == 0;
#else
  return ::getrandom(out, size, GRND_NONBLOCK) == static_cast<ssize_t>(size);
#endif
}

uint64_t physicalMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(page);
}

std::string executablePath() {
#ifdef __EMSCRIPTEN__
  return "";
#else
  std::string path(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", path.data(), path.size());
  if (n <= 0 || static_cast<size_t>(n) >= path.size()) return "";
  path.resize(static_cast<size_t>(n));
  return path;
#endif
}

bool isTerminal(int fd) { return ::isatty(fd) != 0; }

Utf8Arguments::Utf8Arguments(int argc, char** argv) : args_(argv, argv + argc) {
  for (std::string& a : args_) pointers_.push_back(a.data());
  pointers_.push_back(nullptr);
}

void prepareStandardStreams() {}

void ignoreWriteSignals() {
  ::signal(SIGPIPE, SIG_IGN);
#ifdef SIGXFSZ
  ::signal(SIGXFSZ, SIG_IGN);
#endif
}

}  // namespace smpl::os
