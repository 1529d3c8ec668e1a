#include "core/load/motion_read.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/io/file_io.h"
#include "core/io/npz.h"
#include "core/io/pickle/pickle.h"
#include "core/io/printable.h"
#include "core/load/npz_arrays.h"

namespace smpl {
namespace {

// A zip (npz) by its first bytes, without reading the file.
bool isZip(const std::string& path) {
  char magic[2] = {0, 0};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  const size_t n = std::fread(magic, 1, 2, f);
  std::fclose(f);
  return n == 2 && magic[0] == 'P' && magic[1] == 'K';
}

// Nested rectangular JSON number arrays -> Array (shape inferred, C order).
Status jsonToArray(const nlohmann::json& j, Array* out, size_t depth = 0) {
  if (j.is_number()) {
    if (depth == 0) out->shape.clear();
    out->data.push_back(j.get<double>());
    return Status();
  }
  if (!j.is_array() || depth > 4) return makeError("expected nested arrays of numbers");
  const int64_t n = static_cast<int64_t>(j.size());
  if (out->shape.size() == depth)
    out->shape.push_back(n);
  else if (out->shape[depth] != n)
    return makeError("ragged array");
  for (const auto& item : j)
    if (Status s = jsonToArray(item, out, depth + 1); !s) return s;
  return Status();
}

Result<ArrayDict> readJsonArrays(const std::vector<uint8_t>& bytes, const std::string& path) {
  // A parsed JSON value takes 16 bytes and a number at least 2 characters ("0,"),
  // and each number is then copied into a double: at most 12 bytes per byte of text.
  MemoryCharge parse;
  if (Status st = parse.add(bytes.size() * 12, path, "parsing the JSON"); !st) return st.error();
  nlohmann::json j =
      nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return makeError(path + ": not a JSON object");
  ArrayDict arrays;
  for (const auto& [key, value] : j.items()) {
    Array a;
    if (value.is_string()) {
      a.dtype = "<U";
      a.strings = {value.get<std::string>()};
    } else if (Status s = jsonToArray(value, &a); !s) {
      return makeError(path + ": '" + printable(key, 64) + "': " + s.message());
    } else if (a.size() != static_cast<int64_t>(a.data.size())) {
      return makeError(path + ": '" + printable(key, 64) + "': ragged array");
    }
    arrays[key] = std::move(a);
  }
  return arrays;
}

// Member names as None nodes: what a layout's `matches` sees of an .npz.
DataNode namesOf(const std::vector<std::string>& names) {
  DataNode root;
  root.kind = DataNode::Kind::Dict;
  root.keys = names;
  root.children.resize(names.size());
  return root;
}

Result<MotionFile> readNpz(const std::string& path, bool decode) {
  Result<NpzArchive> npz =
      NpzArchive::open(path);  // errors name the base name, as the model loader's
  if (!npz) return npz.error();
  MotionFile file;
  file.container = kNpzFile;
  file.root = namesOf(npz->keys());
  file.layout = findLayout(file.root, kNpzFile);
  if (!decode || !file.layout) return file;
  ArrayDict arrays;  // only the layout's keys (NpzArchive is lazy)
  for (const std::string& key : file.layout->keys) {
    if (!npz->has(key)) continue;
    Result<Array> a = readNpzMember(*npz, key);
    if (!a) return a.error();
    arrays[key] = std::move(*a);
  }
  file.root = nodeOf(std::move(arrays));
  return file;
}

Result<MotionFile> readBytes(const std::string& path) {
  Result<std::vector<uint8_t>> bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  const std::vector<uint8_t>& b = *bytes;
  MotionFile file;
  Result<ArrayDict> arrays = ArrayDict();
  const size_t first = static_cast<size_t>(
      std::find_if(b.begin(), b.end(), [](uint8_t c) { return !std::isspace(c); }) - b.begin());
  if (!b.empty() && (b[0] == 0x80 || b[0] == '(' || b[0] == '}' || b[0] == ']')) {
    file.container = kPickleFile;
    arrays = parsePickle(b.data(), b.size(), path);
  } else if (hasSuffix(path, ".json") || (first < b.size() && b[first] == '{')) {
    file.container = kJsonFile;
    arrays = readJsonArrays(b, path);
  } else {
    Result<ArrayDict> npz = parseNpz(b.data(), b.size(), path);  // its error says what a zip needs
    if (!npz) return npz.error();
    return makeError(path + ": not a motion file");
  }
  if (!arrays) return arrays.error();
  file.root = nodeOf(std::move(*arrays));
  file.layout = findLayout(file.root, file.container);
  return file;
}

}  // namespace

Result<MotionFile> readMotionFile(const std::string& path) {
  if (isZip(path)) return readNpz(path, /*decode=*/true);
  return readBytes(path);
}

Result<MotionFile> probeMotionFile(const std::string& path) {
  if (isZip(path)) return readNpz(path, /*decode=*/false);  // the member names decide
  return readBytes(path);
}

}  // namespace smpl
