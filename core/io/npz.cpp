// .npz = zip of .npy members (np.savez / np.savez_compressed). Each member is
// parsed as it is reached and its raw bytes released, so peak memory is the
// uncompressed archive plus the converted arrays, not two copies of both.
#include "core/io/npz.h"

#include <utility>
#include <vector>

#include "core/io/file_io.h"
#include "core/io/npy.h"
#include "core/io/printable.h"
#include "core/io/zip.h"

namespace smpl {
namespace {

// np.load's NpzFile drops ".npy" from member names to form the keys.
std::string keyOf(const std::string& member) {
  return hasSuffix(member, ".npy") ? member.substr(0, member.size() - 4) : member;
}

}  // namespace

Result<ArrayDict> parseNpz(const uint8_t* data, size_t size, const std::string& context) {
  Result<std::vector<ZipEntry>> entries = readZip(data, size, context);
  if (!entries) return entries.error();
  ArrayDict arrays;
  for (ZipEntry& e : *entries) {
    if (hasSuffix(e.name, "/") && e.data.empty()) continue;  // directory entry
    const std::string key = keyOf(e.name);
    if (arrays.count(key))
      return makeError(context + "/" + printable(e.name) + ": duplicate member '" + key + "'");
    Result<Array> a = parseNpy(e.data.data(), e.data.size(), context + "/" + printable(e.name));
    if (!a) return a.error();
    std::vector<uint8_t>().swap(e.data);
    arrays.emplace(key, std::move(*a));
  }
  return arrays;
}

Result<ArrayDict> readNpzFile(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  return parseNpz(bytes->data(), bytes->size(), baseName(path));
}

}  // namespace smpl
