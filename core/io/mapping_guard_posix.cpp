// The SIGBUS handler behind MappingGuard (see the header). Everything the
// handler touches is lock-free atomics and system calls (mmap, sigaction,
// raise), so it is async-signal-safe in practice on Linux.
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <mutex>

#include "core/io/mapping_guard.h"

namespace smpl {
namespace {

enum : int { kFree = 0, kClaimed = 1, kActive = 2 };

struct Slot {
  std::atomic<int> state{kFree};  // the handler reads begin/end only when kActive
  std::atomic<uintptr_t> begin{0};
  std::atomic<uintptr_t> end{0};
  std::atomic<bool> lost{false};
};

Slot g_slots[MappingGuard::kMaxWatched];
struct sigaction g_previous {};
uintptr_t g_page = 4096;
std::once_flag g_installed;

// A fault that is not ours: what would have happened without us.
void passOn(int sig, siginfo_t* info, void* context) {
  if ((g_previous.sa_flags & SA_SIGINFO) && g_previous.sa_sigaction) {
    g_previous.sa_sigaction(sig, info, context);
    return;
  }
  if (g_previous.sa_handler != SIG_DFL && g_previous.sa_handler != SIG_IGN) {
    g_previous.sa_handler(sig);
    return;
  }
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  // A fault repeats when the handler returns and now kills; a sent signal
  // (kill, raise: si_code <= 0) must be raised again to do the same.
  if (info == nullptr || info->si_code <= 0) ::raise(sig);
}

void onSigbus(int sig, siginfo_t* info, void* context) {
  if (info != nullptr && info->si_code > 0) {
    const uintptr_t at = reinterpret_cast<uintptr_t>(info->si_addr);
    for (Slot& s : g_slots) {
      if (s.state.load(std::memory_order_acquire) != kActive) continue;
      const uintptr_t begin = s.begin.load(std::memory_order_relaxed);
      const uintptr_t end = s.end.load(std::memory_order_relaxed);
      if (at < begin || at >= end) continue;
      const uintptr_t page = at & ~(g_page - 1);
      void* zeros = ::mmap(reinterpret_cast<void*>(page), end - page, PROT_READ,
                           MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0);
      if (zeros == MAP_FAILED) break;
      s.lost.store(true, std::memory_order_release);
      return;  // the faulting read is retried and now reads zeros
    }
  }
  passOn(sig, info, context);
}

void install() {
  const long page = ::sysconf(_SC_PAGESIZE);
  if (page > 0) g_page = static_cast<uintptr_t>(page);
  struct sigaction sa {};
  sa.sa_sigaction = onSigbus;
  sa.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_RESTART;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGBUS, &sa, &g_previous);
}

}  // namespace

MappingGuard::MappingGuard(const void* data, size_t size) {
  if (data == nullptr || size == 0) return;
  std::call_once(g_installed, install);
  const uintptr_t begin = reinterpret_cast<uintptr_t>(data);
  for (int i = 0; i < kMaxWatched; ++i) {
    Slot& s = g_slots[i];
    int expected = kFree;
    if (!s.state.compare_exchange_strong(expected, kClaimed, std::memory_order_acq_rel)) continue;
    s.begin.store(begin, std::memory_order_relaxed);
    s.end.store(begin + size, std::memory_order_relaxed);
    s.lost.store(false, std::memory_order_relaxed);
    s.state.store(kActive, std::memory_order_release);  // publishes the range
    slot_ = i;
    return;
  }
}

MappingGuard::MappingGuard(MappingGuard&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }

MappingGuard& MappingGuard::operator=(MappingGuard&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = -1;
  }
  return *this;
}

MappingGuard::~MappingGuard() { release(); }

void MappingGuard::release() {
  if (slot_ < 0) return;
  g_slots[slot_].state.store(kFree, std::memory_order_release);
  slot_ = -1;
}

bool MappingGuard::lost() const {
  return slot_ >= 0 && g_slots[slot_].lost.load(std::memory_order_acquire);
}

Error mappingLostError(const std::string& path) {
  return makeError(path +
                   ": cannot read: the file shrank while it was being read (truncated or rewritten "
                   "by another process) or its pages could not be read");
}

}  // namespace smpl
