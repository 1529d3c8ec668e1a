// parseTorchZip: torch.save's zip archive (torch >= 1.6; torch/serialization.py
// _save and _load, torch 1.13 and 2.x). The archive has one root folder (the
// saved name, or "archive") holding data.pkl, data/<key> for each storage,
// version, and in torch 2.x byteorder, .format_version, .storage_alignment
// and .data/serialization_id; records are stored, data 64-byte aligned via
// extra fields (which the zip reader skips). TorchScript archives
// (torch.jit.save) also have constants.pkl and code/: not tensors to read.
#include <map>

#include "core/io/pickle/pickle_internal.h"
#include "core/io/pickle/pickle_tree.h"
#include "core/io/printable.h"
#include "core/io/zip.h"

namespace smpl {
namespace {

// The root folder of the archive's data.pkl ("archive/"), or an error.
Result<std::string> rootOf(const std::vector<ZipMember>& members, const std::string& context) {
  std::string root;
  int found = 0;
  for (const ZipMember& m : members) {
    const size_t slash = m.name.find('/');
    const std::string head = slash == std::string::npos ? "" : m.name.substr(0, slash + 1);
    if (m.name != head + "data.pkl") continue;
    root = head;
    ++found;
  }
  if (found == 0)
    return makeError(context + ": not a torch.save archive (no <name>/data.pkl record)");
  if (found > 1) return makeError(context + ": more than one data.pkl record");
  for (const ZipMember& m : members)
    if (m.name == root + "constants.pkl")
      return makeError(context +
                       ": a TorchScript archive (torch.jit.save), not data saved with torch.save");
  return root;
}

const ZipMember* findMember(const std::vector<ZipMember>& members, const std::string& name) {
  for (const ZipMember& m : members)
    if (m.name == name) return &m;
  return nullptr;
}

// The `byteorder` record: true for "big"; absent means little-endian.
Result<bool> bigEndian(const uint8_t* data, size_t size, const std::vector<ZipMember>& members,
                       const std::string& root, const std::string& context) {
  const ZipMember* m = findMember(members, root + "byteorder");
  if (!m) return false;
  Result<std::vector<uint8_t>> text = readZipMemberPrefix(data, size, *m, 16, context);
  if (!text) return text.error();
  const std::string order(text->begin(), text->end());
  if (order != "little" && order != "big")
    return makeError(context + "/" + printable(m->name) + ": unknown byte order '" +
                     printable(order) + "' (expected little or big)");
  return order == "big";
}

// A compressed storage record may be inflated: it declares no more bytes
// than its storage needs, and with the records inflated before it stays
// within the input-scaled bound.
Status checkInflatable(const ZipMember& m, uint64_t nbytes, uint64_t bound, uint64_t inflated,
                       const std::string& context) {
  const std::string ectx = context + "/" + printable(m.name);
  if (m.usize > nbytes)
    return makeError(ectx + ": compressed record declares " + std::to_string(m.usize) +
                     " bytes; its storage needs " + std::to_string(nbytes));
  if (m.usize > bound || inflated > bound - m.usize)
    return makeError(ectx + ": compressed storages inflate past " + formatBytes(bound) +
                     " (the input-scaled bound: a compressed record may not inflate beyond it; "
                     "--memory-limit caps it further)");
  return Status();
}

}  // namespace

Result<DataNode> parseTorchZip(const uint8_t* data, size_t size, const std::string& context,
                               const PickleLimits& limits) {
  using namespace pickle;
  Result<std::vector<ZipMember>> members = listZip(data, size, context);
  if (!members) return members.error();
  Result<std::string> root = rootOf(*members, context);
  if (!root) return root.error();
  Result<bool> big = bigEndian(data, size, *members, *root, context);
  if (!big) return big.error();
  const ZipMember* pkl = findMember(*members, *root + "data.pkl");
  Result<ZipBytes> pickle_bytes = viewZipMember(data, size, *pkl, context);
  if (!pickle_bytes) return pickle_bytes.error();
  // Storages are viewed in place (stored records) or inflated once each; the
  // views live until the tree is built.
  std::map<std::string, ZipBytes> storages;
  // Compressed records are inflated whole, so before that each is held to
  // what its storage declares and all of them to the input-scaled bound: a
  // small archive cannot make gigabytes out of one deflated record.
  const uint64_t bound = heapByteLimit(limits, size);
  uint64_t inflated = 0;
  VmOptions options;
  options.tree = true;
  options.torch_big_endian = *big;
  options.torch_storage = [&](const std::string& key, uint64_t nbytes) -> Result<StorageBytes> {
    auto it = storages.find(key);
    if (it == storages.end()) {
      const std::string name = *root + "data/" + key;
      const ZipMember* m =
          key.empty() || key.find('/') != std::string::npos ? nullptr : findMember(*members, name);
      if (!m)
        return makeError(context + ": no record '" + printable(name) + "' for storage key '" +
                         printable(key) + "'");
      if (m->method != 0) {
        if (Status st = checkInflatable(*m, nbytes, bound, inflated, context); !st)
          return st.error();
        inflated += m->usize;
      }
      Result<ZipBytes> b = viewZipMember(data, size, *m, context);
      if (!b) return b.error();
      it = storages.emplace(key, std::move(*b)).first;
    }
    return StorageBytes{it->second.data, it->second.size};
  };
  const std::string pctx = context + "/" + printable(pkl->name);
  Heap heap(pctx, limits, size, std::move(options));
  Result<Ref> top = runPickle(heap, pickle_bytes->data, pickle_bytes->size, limits);
  if (!top) return top.error();
  return toTree(heap, *top);
}

}  // namespace smpl
