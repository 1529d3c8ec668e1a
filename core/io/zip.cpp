// Read-only zip reader (APPNOTE.TXT 6.3): End of Central Directory, zip64 EOCD
// record and locator, central directory entries with zip64 extra fields, local
// headers, stored and deflated data. The central directory is the source of
// truth (local headers may defer sizes to a data descriptor); local headers
// are only checked to agree with it. All declared sizes are validated against
// the file and the limits before any entry is allocated or inflated.
#include "core/io/zip.h"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>

#include "core/huge_pages.h"
#include "core/io/printable.h"

namespace smpl {
namespace {

constexpr uint32_t kEocdSig = 0x06054b50, kZip64EocdSig = 0x06064b50, kZip64LocatorSig = 0x07064b50;
constexpr uint32_t kCentralSig = 0x02014b50, kLocalSig = 0x04034b50;
constexpr size_t kEocdBytes = 22, kZip64LocatorBytes = 20, kZip64EocdBytes = 56;
constexpr size_t kCentralBytes = 46, kLocalBytes = 30;
constexpr size_t kMaxCommentBytes = 65535;
// Deflate cannot expand more than 1032:1 (a 258-byte match in 2 bits); a
// larger declared size is a lie, refused before allocating it.
constexpr uint64_t kMaxDeflateRatio = 1032;
constexpr uint64_t kZlibChunk = 1u << 30;  // z_stream counts are 32-bit

uint16_t le16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | p[1] << 8); }
uint32_t le32(const uint8_t* p) { return le16(p) | static_cast<uint32_t>(le16(p + 2)) << 16; }
uint64_t le64(const uint8_t* p) { return le32(p) | static_cast<uint64_t>(le32(p + 4)) << 32; }

std::string hex32(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

struct Directory {
  uint64_t entries = 0, cd_offset = 0, cd_size = 0;
  uint64_t cd_limit = 0;  // where the central directory must end (EOCD or zip64 record)
};

using CentralEntry = ZipMember;

Result<size_t> findEocd(const uint8_t* data, size_t size, const std::string& ctx) {
  if (size < kEocdBytes) return makeError(ctx + ": not a zip archive (too short)");
  const size_t lowest =
      size - kEocdBytes > kMaxCommentBytes ? size - kEocdBytes - kMaxCommentBytes : 0;
  for (size_t pos = size - kEocdBytes + 1; pos-- > lowest;) {
    if (le32(data + pos) == kEocdSig && pos + kEocdBytes + le16(data + pos + 20) <= size)
      return pos;
  }
  return makeError(ctx + ": not a zip archive (no end of central directory record)");
}

// Replaces the 16/32-bit EOCD fields with the zip64 record's, when present.
Status readZip64Eocd(const uint8_t* data, size_t eocd, Directory& dir, bool needed,
                     const std::string& ctx) {
  if (eocd < kZip64LocatorBytes || le32(data + eocd - kZip64LocatorBytes) != kZip64LocatorSig) {
    if (needed) return makeError(ctx + ": zip64 end of central directory locator missing");
    return Status();
  }
  const size_t loc = eocd - kZip64LocatorBytes;
  const uint64_t rec = le64(data + loc + 8);
  if (rec > loc || loc - rec < kZip64EocdBytes || le32(data + rec) != kZip64EocdSig)
    return makeError(ctx + ": bad zip64 end of central directory record offset " +
                     std::to_string(rec));
  if (le32(data + rec + 16) != 0 || le32(data + rec + 20) != 0)
    return makeError(ctx + ": multi-disk zip archives are not supported");
  dir.entries = le64(data + rec + 32);
  dir.cd_size = le64(data + rec + 40);
  dir.cd_offset = le64(data + rec + 48);
  dir.cd_limit = rec;
  return Status();
}

Result<Directory> readDirectory(const uint8_t* data, size_t size, const std::string& ctx) {
  Result<size_t> eocd = findEocd(data, size, ctx);
  if (!eocd) return eocd.error();
  const uint8_t* e = data + *eocd;
  const uint16_t disk = le16(e + 4), cd_disk = le16(e + 6), on_disk = le16(e + 8),
                 total = le16(e + 10);
  Directory dir{total, le32(e + 16), le32(e + 12), *eocd};
  const bool needed = total == 0xFFFF || dir.cd_size == 0xFFFFFFFFu || dir.cd_offset == 0xFFFFFFFFu;
  if ((disk != 0 && disk != 0xFFFF) || (cd_disk != 0 && cd_disk != 0xFFFF) || on_disk != total)
    return makeError(ctx + ": multi-disk zip archives are not supported");
  if (Status st = readZip64Eocd(data, *eocd, dir, needed, ctx); !st) return st.error();
  if (dir.cd_offset > dir.cd_limit || dir.cd_size > dir.cd_limit - dir.cd_offset)
    return makeError(ctx + ": central directory (offset " + std::to_string(dir.cd_offset) + ", " +
                     std::to_string(dir.cd_size) + " bytes) lies outside the archive");
  if (dir.entries > dir.cd_size / kCentralBytes)
    return makeError(ctx + ": central directory of " + std::to_string(dir.cd_size) +
                     " bytes cannot hold " + std::to_string(dir.entries) + " entries");
  return dir;
}

// Zip64 extended information (header id 1): the 64-bit values follow in a
// fixed order, present only for the fields whose 32-bit value is saturated.
Status applyZip64Extra(const uint8_t* p, size_t len, CentralEntry& c, const std::string& ctx) {
  for (size_t pos = 0; pos + 4 <= len;) {
    const uint16_t id = le16(p + pos), n = le16(p + pos + 2);
    if (n > len - pos - 4) return makeError(ctx + ": bad extra field in the central directory");
    if (id == 1) {
      size_t at = pos + 4, end = at + n;
      for (uint64_t* v : {&c.usize, &c.csize, &c.local_offset}) {
        if (*v != 0xFFFFFFFFu) continue;
        if (end - at < 8) return makeError(ctx + ": zip64 extra field too short");
        *v = le64(p + at);
        at += 8;
      }
    }
    pos += 4 + n;
  }
  return Status();
}

Status checkSupported(const CentralEntry& c, const std::string& ectx) {
  if (c.flags & 0x41) return makeError(ectx + ": encrypted zip entries are not supported");
  if (c.method != 0 && c.method != 8)
    return makeError(ectx + ": unsupported compression method " + std::to_string(c.method) +
                     " (only stored and deflate)");
  if (c.method == 0 && c.csize != c.usize)
    return makeError(ectx + ": stored entry sizes disagree (" + std::to_string(c.csize) + " vs " +
                     std::to_string(c.usize) + ")");
  if (c.method == 8 && c.usize > c.csize * kMaxDeflateRatio + 258)
    return makeError(ectx + ": declared uncompressed size " + std::to_string(c.usize) +
                     " is impossible for " + std::to_string(c.csize) + " bytes of deflate data");
  return Status();
}

// Parses the entry at `pos` (within [pos, end)) and advances `pos`.
Result<CentralEntry> readCentralEntry(const uint8_t* data, size_t& pos, size_t end,
                                      const std::string& ctx, bool check_supported = true) {
  if (end - pos < kCentralBytes || le32(data + pos) != kCentralSig)
    return makeError(ctx + ": corrupt central directory at offset " + std::to_string(pos));
  const uint8_t* h = data + pos;
  const size_t n = le16(h + 28), x = le16(h + 30), k = le16(h + 32);
  if (end - pos - kCentralBytes < n + x + k)
    return makeError(ctx + ": corrupt central directory at offset " + std::to_string(pos));
  CentralEntry c;
  c.name.assign(reinterpret_cast<const char*>(h + kCentralBytes), n);
  c.flags = le16(h + 8);
  c.method = le16(h + 10);
  c.crc = le32(h + 16);
  c.csize = le32(h + 20);
  c.usize = le32(h + 24);
  c.local_offset = le32(h + 42);
  const std::string ectx = ctx + "/" + printable(c.name);
  if (Status st = applyZip64Extra(h + kCentralBytes + n, x, c, ectx); !st) return st.error();
  if (check_supported)
    if (Status st = checkSupported(c, ectx); !st) return st.error();
  pos += kCentralBytes + n + x + k;
  return c;
}

Result<std::vector<CentralEntry>> readCentralDirectory(const uint8_t* data, const Directory& dir,
                                                       const ZipLimits& limits,
                                                       const std::string& ctx, bool lazy = false) {
  if (dir.entries > limits.max_entries)
    return makeError(ctx + ": " + std::to_string(dir.entries) + " entries exceed the limit of " +
                     std::to_string(limits.max_entries));
  std::vector<CentralEntry> entries;
  entries.reserve(dir.entries);
  size_t pos = dir.cd_offset;
  uint64_t total = 0;
  for (uint64_t i = 0; i < dir.entries; ++i) {
    Result<CentralEntry> c = readCentralEntry(data, pos, dir.cd_offset + dir.cd_size, ctx, !lazy);
    if (!c) return c.error();
    c->data_end = dir.cd_offset;
    if (lazy) {
      entries.push_back(std::move(*c));
      continue;
    }
    if (c->usize > limits.max_total_uncompressed - total)
      return makeError(ctx + ": declared uncompressed size exceeds the limit of " +
                       std::to_string(limits.max_total_uncompressed) + " bytes at '" +
                       printable(c->name) + "'");
    total += c->usize;
    entries.push_back(std::move(*c));
  }
  return entries;
}

// Checks the local header against the central entry; returns the data offset.
Result<size_t> locateData(const uint8_t* data, const CentralEntry& c, uint64_t data_end,
                          const std::string& ectx) {
  if (c.local_offset > data_end || data_end - c.local_offset < kLocalBytes ||
      le32(data + c.local_offset) != kLocalSig)
    return makeError(ectx + ": local header offset " + std::to_string(c.local_offset) +
                     " is out of range or corrupt");
  const uint8_t* h = data + c.local_offset;
  const size_t n = le16(h + 26), x = le16(h + 28);
  const uint64_t start = c.local_offset + kLocalBytes + n + x;
  if (start > data_end || c.csize > data_end - start)
    return makeError(ectx + ": entry data (" + std::to_string(c.csize) + " bytes at offset " +
                     std::to_string(start) + ") lies outside the archive");
  if (n != c.name.size() || std::memcmp(h + kLocalBytes, c.name.data(), n) != 0 ||
      le16(h + 8) != c.method)
    return makeError(ectx + ": local header disagrees with the central directory");
  return static_cast<size_t>(start);
}

// One inflate() step into `out` (or, once `out` is full, into a spill byte
// whose use proves the entry is larger than declared).
Status inflateStep(z_stream& zs, uint8_t* out, size_t out_size, uint64_t& out_pos,
                   const std::string& ectx, bool& done) {
  uint8_t spill = 0;
  const bool full = out_pos == out_size;
  const uInt room =
      full ? 1 : static_cast<uInt>(std::min<uint64_t>(out_size - out_pos, kZlibChunk));
  zs.next_out = full ? &spill : out + out_pos;
  zs.avail_out = room;
  const uInt in_before = zs.avail_in;
  const int ret = inflate(&zs, Z_NO_FLUSH);
  const uInt produced = room - zs.avail_out;
  if (full && produced > 0)
    return makeError(ectx + ": deflate data inflates to more than the declared " +
                     std::to_string(out_size) + " bytes");
  out_pos += produced;
  done = ret == Z_STREAM_END;
  if (ret != Z_OK && ret != Z_STREAM_END && ret != Z_BUF_ERROR)
    return makeError(ectx + ": corrupt deflate data (" +
                     (zs.msg ? zs.msg : "zlib error " + std::to_string(ret)) + ")");
  if (!done && produced == 0 && in_before == zs.avail_in && zs.avail_in > 0)
    return makeError(ectx + ": corrupt deflate data (no progress)");
  return Status();
}

Status inflateInto(const uint8_t* in, uint64_t csize, uint8_t* out, size_t out_size,
                   const std::string& ectx) {
  z_stream zs{};
  if (inflateInit2(&zs, -15) != Z_OK) return makeError(ectx + ": cannot initialise zlib");
  uint64_t in_pos = 0, out_pos = 0;
  bool done = false;
  Status st;
  while (st && !done) {
    if (zs.avail_in == 0) {
      if (in_pos == csize) {
        st = makeError(ectx + ": truncated deflate data");
        break;
      }
      zs.next_in = const_cast<Bytef*>(in + in_pos);  // zlib's API is not const-correct
      zs.avail_in = static_cast<uInt>(std::min(csize - in_pos, kZlibChunk));
      in_pos += zs.avail_in;
    }
    st = inflateStep(zs, out, out_size, out_pos, ectx, done);
  }
  inflateEnd(&zs);
  if (st && out_pos != out_size)
    st = makeError(ectx + ": deflate data inflates to " + std::to_string(out_pos) +
                   " bytes; declared " + std::to_string(out_size));
  return st;
}

// libdeflate's CRC-32 (carry-less multiply where the CPU has it): ~10x zlib's.
uint32_t crc32Of(const uint8_t* bytes, size_t size) { return libdeflate_crc32(0, bytes, size); }

// Whole-member inflate in one libdeflate call (the declared size is known, so
// the output buffer is exact); on any failure zlib's streaming inflate above
// runs again on the same bytes, only to name the problem exactly (corrupt,
// truncated, larger or smaller than declared).
Status inflateMember(const uint8_t* in, uint64_t csize, uint8_t* out, size_t out_size,
                     const std::string& ectx) {
  struct Free {
    void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
  };
  static thread_local std::unique_ptr<libdeflate_decompressor, Free> d(
      libdeflate_alloc_decompressor());
  if (d && libdeflate_deflate_decompress(d.get(), in, static_cast<size_t>(csize), out, out_size,
                                         nullptr) == LIBDEFLATE_SUCCESS)
    return Status();
  Status st = inflateInto(in, csize, out, out_size, ectx);
  if (st)
    return makeError(ectx +
                     ": corrupt deflate data (refused by libdeflate)");  // zlib alone accepts it
  return st;
}

// The member's bytes: a view of the archive for a stored member (no copy),
// else inflated into `owned` (default-initialised: no zero fill). CRC-checked.
Result<ZipBytes> extractBytes(const uint8_t* data, const CentralEntry& c, uint64_t data_end,
                              const std::string& ctx) {
  const std::string ectx = ctx + "/" + printable(c.name);
  Result<size_t> start = locateData(data, c, data_end, ectx);
  if (!start) return start.error();
  ZipBytes b;
  if (c.method == 0) {
    b.data = data + *start;
    b.size = static_cast<size_t>(c.csize);
  } else {
    if (Status st = b.charge.add(c.usize, ectx, "inflating the member"); !st) return st.error();
    b.owned.reset(new uint8_t[c.usize]);  // bounded by the limits and the deflate ratio
    adviseHugePages(b.owned.get(), static_cast<size_t>(c.usize));
    b.data = b.owned.get();
    b.size = static_cast<size_t>(c.usize);
    if (Status st = inflateMember(data + *start, c.csize, b.owned.get(), b.size, ectx); !st)
      return st.error();
  }
  const uint32_t crc = crc32Of(b.data, b.size);
  if (crc != c.crc)
    return makeError(ectx + ": CRC mismatch: expected " + hex32(c.crc) + ", found " + hex32(crc));
  return b;
}

Result<ZipEntry> extractEntry(const uint8_t* data, const CentralEntry& c, uint64_t data_end,
                              const std::string& ctx) {
  Result<ZipBytes> b = extractBytes(data, c, data_end, ctx);  // stored: a view, not a copy
  if (!b) return b.error();
  ZipEntry e;
  e.name = c.name;
  // The copy is charged while the inflated buffer (if any) still is.
  if (Status st = e.charge.add(b->size, ctx + "/" + printable(c.name), "inflating the member"); !st)
    return st.error();
  e.data.assign(b->data, b->data + b->size);
  return e;
}

// The checks every extraction of a listed member makes first.
Status checkExtractable(const uint8_t* data, size_t size, const ZipMember& member,
                        const std::string& ectx, const ZipLimits& limits) {
  if (data == nullptr || member.data_end > size)
    return makeError(ectx + ": member lies outside the archive");
  if (Status st = checkSupported(member, ectx); !st) return st;
  if (member.usize > limits.max_total_uncompressed)
    return makeError(ectx + ": declared uncompressed size " + std::to_string(member.usize) +
                     " exceeds the limit of " + std::to_string(limits.max_total_uncompressed) +
                     " bytes");
  return Status();
}

}  // namespace

Result<std::vector<ZipMember>> listZip(const uint8_t* data, size_t size, const std::string& context,
                                       const ZipLimits& limits) {
  if (data == nullptr) size = 0;
  Result<Directory> dir = readDirectory(data, size, context);
  if (!dir) return dir.error();
  return readCentralDirectory(data, *dir, limits, context, /*lazy=*/true);
}

Result<ZipEntry> extractZipMember(const uint8_t* data, size_t size, const ZipMember& member,
                                  const std::string& context, const ZipLimits& limits) {
  if (Status st =
          checkExtractable(data, size, member, context + "/" + printable(member.name), limits);
      !st)
    return st.error();
  return extractEntry(data, member, member.data_end, context);  // charged to the memory budget
}

Result<ZipBytes> viewZipMember(const uint8_t* data, size_t size, const ZipMember& member,
                               const std::string& context, const ZipLimits& limits) {
  if (Status st =
          checkExtractable(data, size, member, context + "/" + printable(member.name), limits);
      !st)
    return st.error();
  return extractBytes(data, member, member.data_end, context);
}

Result<std::vector<uint8_t>> readZipMemberPrefix(const uint8_t* data, size_t size,
                                                 const ZipMember& member, size_t max_bytes,
                                                 const std::string& context) {
  const std::string ectx = context + "/" + printable(member.name);
  if (data == nullptr || member.data_end > size)
    return makeError(ectx + ": member lies outside the archive");
  if (Status st = checkSupported(member, ectx); !st) return st.error();
  Result<size_t> start = locateData(data, member, member.data_end, ectx);
  if (!start) return start.error();
  std::vector<uint8_t> out(static_cast<size_t>(std::min<uint64_t>(max_bytes, member.usize)));
  if (member.method == 0) {
    if (*start > member.data_end || out.size() > member.data_end - *start)
      return makeError(ectx + ": stored member is shorter than its declared size");
    if (!out.empty())
      std::memcpy(out.data(), data + *start, out.size());  // memcpy(nullptr, ..) is UB
    return out;
  }
  z_stream zs{};
  if (inflateInit2(&zs, -15) != Z_OK) return makeError(ectx + ": cannot initialise zlib");
  zs.next_in = const_cast<Bytef*>(data + *start);  // zlib's API is not const-correct
  zs.avail_in = static_cast<uInt>(std::min<uint64_t>(member.csize, kZlibChunk));
  zs.next_out = out.data();
  zs.avail_out = static_cast<uInt>(out.size());
  int ret = Z_OK;
  while (zs.avail_out > 0 && ret == Z_OK) ret = inflate(&zs, Z_NO_FLUSH);
  const size_t produced = out.size() - zs.avail_out;
  inflateEnd(&zs);
  if (ret != Z_OK && ret != Z_STREAM_END && ret != Z_BUF_ERROR)
    return makeError(ectx + ": corrupt deflate data");
  out.resize(produced);
  return out;
}

Result<std::vector<ZipEntry>> readZip(const uint8_t* data, size_t size, const std::string& context,
                                      const ZipLimits& limits) {
  if (data == nullptr) size = 0;
  Result<Directory> dir = readDirectory(data, size, context);
  if (!dir) return dir.error();
  Result<std::vector<CentralEntry>> central = readCentralDirectory(data, *dir, limits, context);
  if (!central) return central.error();
  std::vector<ZipEntry> entries;
  entries.reserve(central->size());
  for (const CentralEntry& c : *central) {
    Result<ZipEntry> e = extractEntry(data, c, dir->cd_offset, context);
    if (!e) return e.error();
    entries.push_back(std::move(*e));
  }
  return entries;
}

}  // namespace smpl
