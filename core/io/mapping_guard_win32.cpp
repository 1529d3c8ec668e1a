// MappingGuard on Windows: nothing to watch. While a view of a file exists,
// Windows refuses to truncate it (SetEndOfFile fails with
// ERROR_USER_MAPPED_FILE), so a mapped input cannot shrink under its reader;
// every mapping is "watched" and never lost. (An I/O error on a network
// drive's page would raise EXCEPTION_IN_PAGE_ERROR; not handled.)
#include <utility>

#include "core/io/mapping_guard.h"

namespace smpl {

MappingGuard::MappingGuard(const void* data, size_t size) : slot_(data && size > 0 ? 0 : -1) {}

MappingGuard::MappingGuard(MappingGuard&& other) noexcept : slot_(std::exchange(other.slot_, -1)) {}

MappingGuard& MappingGuard::operator=(MappingGuard&& other) noexcept {
  if (this != &other) slot_ = std::exchange(other.slot_, -1);
  return *this;
}

MappingGuard::~MappingGuard() = default;

bool MappingGuard::lost() const { return false; }

void MappingGuard::release() { slot_ = -1; }

Error mappingLostError(const std::string& path) {
  return makeError(path + ": cannot read: the file shrank while it was being read");
}

}  // namespace smpl
