// sniffContainer / containerKeys / readDataTree: which container a file is,
// from its bytes, and the reader for it. Files are memory-mapped
// (core/io/mapped_file.h): a large .pt or joblib file is not copied, and the
// arrays are copied out of the mapping into the tree.
#include "core/io/tree/data_tree.h"

#include <cstring>
#include <string_view>

#include "core/io/file_io.h"
#include "core/io/mapped_file.h"
#include "core/io/npz.h"
#include "core/io/pickle/pickle_tree.h"
#include "core/io/tree/json_tree.h"
#include "core/io/tree/npz_tree.h"
#include "core/io/zip.h"

namespace smpl {
namespace {

bool startsWith(const uint8_t* data, size_t size, const char* prefix, size_t n) {
  return size >= n && std::memcmp(data, prefix, n) == 0;
}

// Opcodes a protocol 0/1 pickle can start with (protocols 2-5 start with PROTO, 0x80).
bool pickleStart(uint8_t c) { return c && std::strchr("(}])cNILFSVJKMGUTX", c); }

// A zip: torch's data.pkl record (at the top or one folder down) or .npy members.
Result<Container> sniffZip(const uint8_t* data, size_t size, const std::string& context) {
  Result<std::vector<ZipMember>> members = listZip(data, size, context);
  if (!members) return members.error();
  bool npy = members->empty();
  for (const ZipMember& m : *members) {
    const size_t slash = m.name.find('/');
    if (m.name == (slash == std::string::npos ? "" : m.name.substr(0, slash + 1)) + "data.pkl")
      return Container::TorchZip;
    npy |= hasSuffix(m.name, ".npy");
  }
  return npy ? Container::Npz : Container::Unknown;
}

// The first bytes, for an "unknown container" error.
std::string firstBytes(const uint8_t* data, size_t size) {
  std::string text;
  char hex[8];
  for (size_t i = 0; i < size && i < 8; ++i) {
    std::snprintf(hex, sizeof hex, "%s%02x", i ? " " : "", data[i]);
    text += hex;
  }
  return size == 0 ? "it is empty" : "it starts with " + text;
}

}  // namespace

const char* containerName(Container container) {
  switch (container) {
    case Container::Npz:
      return "npz archive";
    case Container::TorchZip:
      return "torch archive";
    case Container::Pickle:
      return "pickle";
    case Container::Joblib:
      return "joblib file";
    case Container::JoblibCompressed:
      return "compressed joblib file";
    case Container::Npy:
      return "npy file";
    case Container::Json:
      return "JSON file";
    case Container::Unknown:
      break;
  }
  return "unknown";
}

Result<Container> sniffContainer(const uint8_t* data, size_t size, const std::string& context) {
  if (size == 0) data = nullptr;
  if (startsWith(data, size, "PK\x03\x04", 4) || startsWith(data, size, "PK\x05\x06", 4))
    return sniffZip(data, size, context);
  if (startsWith(data, size, "\x93NUMPY", 6)) return Container::Npy;
  if (isLegacyTorchFile(data, size) || (size > 262 && std::memcmp(data + 257, "ustar", 5) == 0))
    return makeError(context + ": " + kLegacyTorchMessage);
  const JoblibCompression compression = joblibCompression(data, size);
  if (compression == JoblibCompression::Zfile) return makeError(context + ": " + kZfileMessage);
  if (compression != JoblibCompression::None) return Container::JoblibCompressed;
  size_t i = startsWith(data, size, "\xef\xbb\xbf", 3) ? 3 : 0;  // UTF-8 byte order mark
  while (i < size && std::strchr(" \t\r\n", data[i]) && data[i]) ++i;
  if (i < size && (data[i] == '{' || data[i] == '[')) return Container::Json;
  if (size > 0 && (data[0] == 0x80 || pickleStart(data[0]))) {
    static const char kWrapper[] = "joblib.numpy_pickle";
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const bool joblib = bytes.find(kWrapper) != std::string_view::npos;
    return joblib ? Container::Joblib : Container::Pickle;
  }
  return Container::Unknown;
}

Result<Container> sniffContainer(const std::string& path) {
  Result<MappedFile> file = MappedFile::open(path);
  if (!file) return file.error();
  Result<Container> container = sniffContainer(file->data(), file->size(), baseName(path));
  if (Status st = file->intact(); !st) return st.error();  // shrank while read (mapping_guard.h)
  return container;
}

Result<std::vector<std::string>> containerKeys(const std::string& path) {
  Result<Container> container = sniffContainer(path);
  if (!container) return container.error();
  if (*container != Container::Npz)
    return makeError(baseName(path) + ": a " + containerName(*container) +
                     ", not an .npz: read it with readDataTree");
  Result<NpzArchive> npz = NpzArchive::open(path);
  if (!npz) return npz.error();
  return npz->keys();
}

namespace {

Result<DataNode> readAs(Container container, const uint8_t* data, size_t size,
                        const std::string& context, const std::vector<std::string>& npz_keys) {
  switch (container) {
    case Container::Npz: {
      Result<NpzArchive> npz = NpzArchive::fromBytes(data, size, context);
      if (!npz) return npz.error();
      return readNpzTree(*npz, npz_keys);
    }
    case Container::TorchZip:
      return parseTorchZip(data, size, context);
    case Container::Pickle:
    case Container::Joblib:
      return parsePickleTree(data, size, context);
    case Container::JoblibCompressed:
      return parseJoblib(data, size, context);
    case Container::Npy:
      return parseNpyTree(data, size, context);
    case Container::Json:
      return parseJsonTree(data, size, context);
    case Container::Unknown:
      break;
  }
  return makeError(context + ": not a container smpl-export reads (" + firstBytes(data, size) +
                   "; expected an .npz or torch .pt zip, a pickle or joblib file, an .npy or "
                   "JSON)");
}

}  // namespace

Result<DataNode> readDataTree(const uint8_t* data, size_t size, const std::string& context,
                              const std::vector<std::string>& npz_keys) {
  Result<Container> container = sniffContainer(data, size, context);
  if (!container) return container.error();
  return readAs(*container, data, size, context, npz_keys);
}

Result<DataNode> readDataTree(const std::string& path, const std::vector<std::string>& npz_keys) {
  Result<MappedFile> file = MappedFile::open(path);
  if (!file) return file.error();
  const std::string context = baseName(path);
  Result<Container> container = sniffContainer(file->data(), file->size(), context);
  if (!container) return container.error();
  if (*container != Container::Npz) {
    Result<DataNode> tree = readAs(*container, file->data(), file->size(), context, npz_keys);
    if (Status st = file->intact(); !st) return st.error();  // shrank while read: zeros were read
    return tree;
  }
  Result<NpzArchive> npz = NpzArchive::open(path);  // mapped, members read lazily
  if (!npz) return npz.error();
  return readNpzTree(*npz, npz_keys);
}

}  // namespace smpl
