// Minimal read-only zip archive reader for .npz: stored and deflated entries
// (zlib), zip64 sizes and offsets. Every offset and size is checked against the
// file; uncompressed sizes are capped (default 4 GiB total) so a zip bomb gets
// an error, not an allocation.
#pragma once

#include <cstdint>
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

struct ZipLimits {
  uint64_t max_total_uncompressed = 4ull << 30;
  uint64_t max_entries = 100000;
};

// `context` names the archive in errors.
Result<std::vector<ZipEntry>> readZip(const uint8_t* data, size_t size, const std::string& context,
                                      const ZipLimits& limits = ZipLimits());

}  // namespace smpl
