// The .usdz zip archive (usdz_archive.h). Record layouts: PKWARE's APPNOTE.TXT
// 4.3.7 (local file header), 4.3.12 (central directory header), 4.3.16 (end
// of central directory record); little-endian.
#include "writers/usd/usdz_archive.h"

#include <zlib.h>

#include <cstdint>
#include <limits>

namespace smpl {
namespace {

constexpr size_t kAlign = 64;
constexpr uint16_t kPaddingId = 0x1986;                 // OpenUSD's padding extra field
constexpr uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01
constexpr uint16_t kStored = 0, kVersion = 10;          // 1.0: stored files

void put16(std::string& out, uint16_t v) {
  out += char(v & 0xff);
  out += char(v >> 8);
}

void put32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
}

struct Entry {
  uint32_t crc = 0, size = 0, offset = 0;
};

// The common part of a local and a central header after the version fields.
void putFileFields(std::string& out, const Entry& e, const std::string& name, size_t extra) {
  put16(out, 0);  // flags
  put16(out, kStored);
  put16(out, 0);  // time 00:00:00
  put16(out, kDosDate);
  put32(out, e.crc);
  put32(out, e.size);  // compressed size = size (stored)
  put32(out, e.size);
  put16(out, uint16_t(name.size()));
  put16(out, uint16_t(extra));
}

// Extra field bytes so that the data after a local header at `at` starts on
// a 64-byte boundary (at least the 4-byte field header, or none).
size_t paddingFor(size_t at, const std::string& name) {
  const size_t data = at + 30 + name.size();
  size_t pad = (kAlign - data % kAlign) % kAlign;
  if (pad != 0 && pad < 4) pad += kAlign;
  return pad;
}

Status checkName(const std::string& name) {
  if (name.empty() || name.size() > 0xffff) return makeError("usdz: empty or overlong file name");
  for (char c : name)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
      return makeError("usdz: file name " + name + " is not printable ASCII");
  return Status();
}

}  // namespace

Result<std::string> usdzArchive(const std::vector<UsdzFile>& files) {
  constexpr uint64_t kLimit = std::numeric_limits<uint32_t>::max();
  if (files.size() > 0xffff) return makeError("usdz: more than 65535 files");
  std::string out;
  std::vector<Entry> entries;
  for (const UsdzFile& f : files) {
    if (Status st = checkName(f.name); !st) return st.error();
    if (out.size() + f.bytes.size() + 256 + f.name.size() > kLimit)
      return makeError("usdz: the archive would exceed 4 GiB (zip64 is not written)");
    Entry e;
    e.offset = uint32_t(out.size());
    e.size = uint32_t(f.bytes.size());
    e.crc = uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(f.bytes.data()), uInt(e.size)));
    const size_t pad = paddingFor(out.size(), f.name);
    put32(out, 0x04034b50);
    put16(out, kVersion);
    putFileFields(out, e, f.name, pad);
    out += f.name;
    if (pad) {
      put16(out, kPaddingId);
      put16(out, uint16_t(pad - 4));
      out.append(pad - 4, '\0');
    }
    out += f.bytes;
    entries.push_back(e);
  }
  const size_t directory = out.size();
  for (size_t i = 0; i < files.size(); ++i) {
    put32(out, 0x02014b50);
    put16(out, kVersion);  // made by: MS-DOS attributes, version 1.0
    put16(out, kVersion);
    putFileFields(out, entries[i], files[i].name, 0);
    put16(out, 0);  // comment
    put16(out, 0);  // disk
    put16(out, 0);  // internal attributes
    put32(out, 0);  // external attributes
    put32(out, entries[i].offset);
    out += files[i].name;
  }
  if (out.size() + 22 > kLimit) return makeError("usdz: the archive would exceed 4 GiB");
  const uint32_t directory_size = uint32_t(out.size() - directory);
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, uint16_t(files.size()));
  put16(out, uint16_t(files.size()));
  put32(out, directory_size);
  put32(out, uint32_t(directory));
  put16(out, 0);
  return out;
}

}  // namespace smpl
