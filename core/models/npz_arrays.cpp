#include "core/models/npz_arrays.h"

#include <utility>

#include "core/io/npy.h"
#include "core/io/pickle/pickle.h"
#include "core/io/printable.h"

namespace smpl {

Result<Array> readNpzMember(const NpzArchive& npz, const std::string& key) {
  Result<bool> object = npz.isObjectArray(key);  // from the header: each member is inflated once
  if (!object) return object.error();
  if (!*object) return npz.get(key);
  Result<ZipEntry> e = npz.memberBytes(key);
  if (!e) return e.error();
  return parseObjectNpy(e->data.data(), e->data.size(),
                        npz.context() + ": '" + printable(key) + "'");
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
