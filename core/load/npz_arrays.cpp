#include "core/load/npz_arrays.h"

#include <utility>

#include "core/io/npy.h"
#include "core/io/pickle/pickle.h"

namespace smpl {

Result<Array> readNpzMember(const NpzArchive& npz, const std::string& key) {
  Result<std::vector<uint8_t>> bytes = npz.memberBytes(key);
  if (!bytes) return bytes.error();
  const std::string mctx = npz.context() + ": '" + key + "'";
  Result<NpyHeaderInfo> h = parseNpyHeader(bytes->data(), bytes->size(), mctx);
  if (!h) return h.error();
  if (isObjectDescr(h->descr)) return parseObjectNpy(bytes->data(), bytes->size(), mctx);
  return npz.get(key);
}

Result<ArrayDict> readNpzArrays(const std::string& path, const std::vector<std::string>& keys,
                                const std::string& context) {
  Result<NpzArchive> npz = NpzArchive::open(path, context);
  if (!npz) return npz.error();
  ArrayDict arrays;
  for (const std::string& key : keys) {
    if (!npz->has(key) || arrays.count(key)) continue;
    Result<Array> a = readNpzMember(*npz, key);
    if (!a) return a.error();
    arrays.emplace(key, std::move(*a));
  }
  return arrays;
}

}  // namespace smpl
