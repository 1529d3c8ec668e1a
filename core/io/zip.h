// Minimal read-only zip archive reader for .npz: stored and deflated entries
// (zlib), zip64 sizes and offsets. Every offset and size is checked against the
// file; uncompressed sizes are capped (default 4 GiB total) so a zip bomb gets
// an error, not an allocation.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/memory_budget.h"
#include "core/result.h"

namespace smpl {

struct ZipEntry {
  std::string name;
  std::vector<uint8_t> data;  // uncompressed bytes, CRC-checked
  MemoryCharge charge;        // `data` held against the memory budget
};

// One member's uncompressed bytes without a needless copy: `data` points into
// the archive for a stored member (valid while the archive's bytes live) or
// into `owned` for an inflated one (charged to the memory budget).
struct ZipBytes {
  const uint8_t* data = nullptr;
  size_t size = 0;
  std::unique_ptr<uint8_t[]> owned;
  MemoryCharge charge;  // `owned` held against the memory budget
};

struct ZipLimits {
  uint64_t max_total_uncompressed = 4ull << 30;
  uint64_t max_entries = 100000;
};

// One central-directory entry, listed but not extracted (lazy readers).
struct ZipMember {
  std::string name;
  uint16_t flags = 0, method = 0;
  uint32_t crc = 0;
  uint64_t csize = 0, usize = 0, local_offset = 0;
  uint64_t data_end = 0;  // where entry data must end (the central directory's offset)
};

// Lists the members without reading their data. Only the directory is
// validated here (entry count limit, names, offsets); a member's compression
// method and sizes are checked when it is extracted, so an odd or huge member
// nobody asks for never makes the listing fail.
Result<std::vector<ZipMember>> listZip(const uint8_t* data, size_t size, const std::string& context,
                                       const ZipLimits& limits = ZipLimits());

// Extracts one listed member (CRC-checked); its uncompressed size must stay
// within limits.max_total_uncompressed. `data`/`size` are the whole archive.
Result<ZipEntry> extractZipMember(const uint8_t* data, size_t size, const ZipMember& member,
                                  const std::string& context,
                                  const ZipLimits& limits = ZipLimits());

// As extractZipMember (same checks, CRC included), but a stored member is
// returned as a view of `data` instead of a copy, and an inflated one in a
// buffer that is not zero-filled first (the bulk model load path).
Result<ZipBytes> viewZipMember(const uint8_t* data, size_t size, const ZipMember& member,
                               const std::string& context, const ZipLimits& limits = ZipLimits());

// The first min(max_bytes, size) uncompressed bytes of a listed member,
// without CRC check (for peeking at a header before deciding to extract).
Result<std::vector<uint8_t>> readZipMemberPrefix(const uint8_t* data, size_t size,
                                                 const ZipMember& member, size_t max_bytes,
                                                 const std::string& context);

// `context` names the archive in errors.
Result<std::vector<ZipEntry>> readZip(const uint8_t* data, size_t size, const std::string& context,
                                      const ZipLimits& limits = ZipLimits());

}  // namespace smpl
