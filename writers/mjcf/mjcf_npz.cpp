// The .npz writer (mjcf_npz.h): stored zip members of .npy arrays.
#include "writers/mjcf/mjcf_npz.h"

#include <libdeflate.h>

#include <cstdint>
#include <cstring>
#include <limits>

#include "core/utf8.h"

namespace smpl {
namespace {

void put16(std::string* out, uint32_t v) {
  out->push_back(char(v & 0xff));
  out->push_back(char((v >> 8) & 0xff));
}

void put32(std::string* out, uint32_t v) {
  put16(out, v & 0xffff);
  put16(out, v >> 16);
}

// The .npy bytes: magic, version 1.0, header dict padded to 64, data.
std::string npyBytes(const NpyMember& m) {
  std::string shape;
  for (size_t d : m.shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
  shape = "(" + shape + (m.shape.size() == 1 ? ",)" : ")");  // (), (3,), (3, 4)
  std::string dict =
      "{'descr': '" + m.descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  const size_t prefix = 10;  // magic (6), version (2), header length (2)
  while ((prefix + dict.size() + 1) % 64 != 0) dict += ' ';
  dict += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  put16(&out, uint32_t(dict.size()));
  return out + dict + m.data;
}

constexpr uint32_t kDosDate = (0u << 9) | (1u << 5) | 1u;  // 1980-01-01; time 00:00:00 is 0

// The header fields shared by the local header and the central directory:
// version needed 2.0, no flags, method stored, time, date, crc, sizes.
void commonFields(std::string* out, uint32_t crc, uint32_t size) {
  put16(out, 20);
  put16(out, 0);
  put16(out, 0);
  put16(out, 0);
  put16(out, kDosDate);
  put32(out, crc);
  put32(out, size);
  put32(out, size);
}

}  // namespace

NpyMember npyDoubles(const std::string& name, std::vector<size_t> shape,
                     const std::vector<double>& values) {
  NpyMember m{name, "<f8", std::move(shape), std::string()};
  m.data.reserve(values.size() * 8);
  for (double v : values) {
    uint64_t bits;
    std::memcpy(&bits, &v, 8);
    for (int b = 0; b < 8; ++b) m.data.push_back(char((bits >> (8 * b)) & 0xff));
  }
  return m;
}

Result<NpyMember> npyStrings(const std::string& name, const std::vector<std::string>& values) {
  std::vector<std::vector<uint32_t>> points(values.size());
  size_t longest = 1;  // numpy's dtype of empty strings is "<U1"
  for (size_t i = 0; i < values.size(); ++i) {
    const std::string& s = values[i];
    for (size_t at = 0; at < s.size();) {
      uint32_t cp = 0;
      const size_t length = utf8SequenceLength(s, at, &cp);
      if (length == 0)
        return makeError("npz writer: '" + name + "' entry " + std::to_string(i) + " is not UTF-8");
      points[i].push_back(cp);
      at += length;
    }
    if (points[i].size() > longest) longest = points[i].size();
  }
  NpyMember m{name, "<U" + std::to_string(longest), {values.size()}, std::string()};
  for (const auto& p : points)
    for (size_t k = 0; k < longest; ++k) put32(&m.data, k < p.size() ? p[k] : 0);
  return m;
}

Result<std::string> npzBytes(const std::vector<NpyMember>& members) {
  std::string out, central;
  for (const NpyMember& m : members) {
    const std::string npy = npyBytes(m);
    const std::string file = m.name + ".npy";
    if (npy.size() >= std::numeric_limits<uint32_t>::max() ||
        out.size() + npy.size() >= std::numeric_limits<uint32_t>::max())
      return makeError("npz writer: '" + m.name + "' exceeds 4 GiB (no zip64)");
    const uint32_t crc = libdeflate_crc32(0, npy.data(), npy.size());
    const auto offset = uint32_t(out.size()), size = uint32_t(npy.size());
    put32(&out, 0x04034b50);  // local file header
    commonFields(&out, crc, size);
    put16(&out, uint32_t(file.size()));
    put16(&out, 0);
    out += file + npy;
    put32(&central, 0x02014b50);  // central directory header
    put16(&central, 20);          // version made by: MS-DOS, 2.0
    commonFields(&central, crc, size);
    put16(&central, uint32_t(file.size()));
    for (int field = 0; field < 4; ++field) put16(&central, 0);  // extra, comment, disk, internal
    put32(&central, 0);                                          // external attributes
    put32(&central, offset);
    central += file;
  }
  const auto at = uint32_t(out.size());
  out += central;
  put32(&out, 0x06054b50);  // end of central directory
  put16(&out, 0);
  put16(&out, 0);
  put16(&out, uint32_t(members.size()));
  put16(&out, uint32_t(members.size()));
  put32(&out, uint32_t(central.size()));
  put32(&out, at);
  put16(&out, 0);
  return out;
}

}  // namespace smpl
