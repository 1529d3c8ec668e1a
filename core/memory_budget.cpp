// Process-wide memory budget: an atomic counter of charged bytes and a limit.
#include "core/memory_budget.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/number_text.h"
#include "core/os/system.h"

namespace smpl {
namespace {

constexpr uint64_t kGiB = 1ull << 30;

std::atomic<uint64_t> g_charged{0};
std::atomic<uint64_t> g_limit{0};  // 0: not set yet, use the default

Error budgetError(uint64_t bytes, const std::string& context, const std::string& what,
                  uint64_t charged, uint64_t limit) {
  const uint64_t total = bytes > UINT64_MAX - charged ? UINT64_MAX : charged + bytes;
  return makeError(context + ": " + what + " would need " + formatBytes(total) +
                   (charged > 0 ? " in total" : "") + "; the limit is " + formatBytes(limit) +
                   ", set --memory-limit");
}

}  // namespace

MemoryCharge::MemoryCharge(const MemoryCharge& other) : bytes_(other.bytes_) {
  g_charged.fetch_add(bytes_);
}

MemoryCharge& MemoryCharge::operator=(const MemoryCharge& other) {
  if (this == &other) return *this;
  release();
  bytes_ = other.bytes_;
  g_charged.fetch_add(bytes_);
  return *this;
}

MemoryCharge& MemoryCharge::operator=(MemoryCharge&& other) noexcept {
  if (this == &other) return *this;
  release();
  bytes_ = other.bytes_;
  other.bytes_ = 0;
  return *this;
}

Status MemoryCharge::add(uint64_t bytes, const std::string& context, const std::string& what) {
  const uint64_t limit = memoryLimit();
  uint64_t charged = g_charged.load();
  do {
    if (bytes > limit || charged > limit - bytes)
      return budgetError(bytes, context, what, charged, limit);
  } while (!g_charged.compare_exchange_weak(charged, charged + bytes));
  bytes_ += bytes;
  return Status();
}

void MemoryCharge::release() {
  if (bytes_ == 0) return;
  g_charged.fetch_sub(bytes_);
  bytes_ = 0;
}

Status checkMemory(uint64_t bytes, const std::string& context, const std::string& what) {
  const uint64_t limit = memoryLimit(), charged = g_charged.load();
  if (bytes > limit || charged > limit - bytes)
    return budgetError(bytes, context, what, charged, limit);
  return Status();
}

uint64_t memoryLimit() {
  const uint64_t limit = g_limit.load();
  if (limit != 0) return limit;
  g_limit.store(defaultMemoryLimit());
  return g_limit.load();
}

void setMemoryLimit(uint64_t bytes) { g_limit.store(bytes == 0 ? defaultMemoryLimit() : bytes); }

uint64_t memoryCharged() { return g_charged.load(); }

uint64_t defaultMemoryLimit() {
  const uint64_t physical = os::physicalMemoryBytes();
  if (physical == 0) return 8 * kGiB;
  return std::min<uint64_t>(8 * kGiB, physical / 4 * 3);
}

Result<uint64_t> parseMemorySize(const std::string& text) {
  const std::string usage =
      "--memory-limit: expected a size such as 512M or 4G (16M to 1P), got '" + text + "'";
  // The number in the command line's one grammar (number_text.h), then the unit.
  const size_t length = decimalPrefixLength(text);
  Result<double> v = parseDecimal(std::string_view(text).substr(0, length), 0, 1e300);
  if (length == 0 || !v || *v <= 0) return makeError(usage);
  std::string suffix = text.substr(length);
  if (!suffix.empty() && (suffix.back() == 'B' || suffix.back() == 'b')) suffix.pop_back();
  if (suffix.size() == 2 && (suffix[1] == 'i' || suffix[1] == 'I')) suffix.pop_back();  // "GiB"
  double scale = 1;
  if (suffix.size() > 1) return makeError(usage);
  if (suffix.size() == 1) {
    const std::string units = "KMGTP";
    const size_t power =
        units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(suffix[0]))));
    if (power == std::string::npos) return makeError(usage);
    scale = std::ldexp(1.0, 10 * static_cast<int>(power + 1));
  }
  const double bytes = *v * scale;
  if (bytes < 16.0 * (1 << 20) || bytes > std::ldexp(1.0, 50)) return makeError(usage);
  return static_cast<uint64_t>(bytes);
}

std::string formatBytes(uint64_t bytes) {
  char text[64];
  if (bytes >= kGiB)
    std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / kGiB);
  else if (bytes >= (1u << 20))
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1u << 20));
  else if (bytes >= 1024)
    std::snprintf(text, sizeof text, "%.1f KiB", static_cast<double>(bytes) / 1024);
  else
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  return text;
}

}  // namespace smpl
