// glTF writer stage: the serialised text and container: tinygltf's JSON, the
// metadata spliced over its placeholders, the GLB chunks laid out around the
// one binary buffer, and an external buffer's URI (gltf_stages.h).
#include <tiny_gltf.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <exception>
#include <sstream>
#include <string>

#include "writers/gltf/gltf_stages.h"

namespace smpl {
namespace gltf {
namespace {

void putU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xFF));
}

uint32_t getU32(const std::string& in, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(in[at + size_t(i)])) << (8 * i);
  return v;
}

// The JSON chunk of tinygltf's GLB (whose buffer is empty).
Result<std::string> jsonChunk(const std::string& glb) {
  if (glb.size() < 20 || glb.compare(0, 4, "glTF") != 0 || getU32(glb, 16) != 0x4E4F534Au ||
      20 + size_t(getU32(glb, 12)) > glb.size())
    return makeError("glTF writer: tinygltf produced an unexpected GLB layout");
  return glb.substr(20, getU32(glb, 12));
}

// RFC 3986 percent-encoding of a file name for a glTF "uri".
std::string uriEscape(const std::string& name) {
  static const char hex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~')
      out += static_cast<char>(c);
    else
      out += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

}  // namespace

// The placeholder's string value (without its quotes).
std::string placeholderText(const char* quoted) {
  const std::string q(quoted);
  return q.substr(1, q.size() - 2);
}

// Replaces `placeholder` (which must occur exactly once) by `text`.
Status splice(std::string& json, const std::string& placeholder, const std::string& text) {
  const size_t at = json.find(placeholder);
  if (at == std::string::npos || json.find(placeholder, at + 1) != std::string::npos)
    return makeError("glTF writer: a name in the asset collides with a placeholder");
  json.replace(at, placeholder.size(), text);
  return Status::success();
}

Status spliceMetadata(std::string& json, const std::string& metadata) {
  Status st = splice(json, kMetadataPlaceholder, metadata);
  if (st) st = splice(json, kScenePlaceholder, metadata);
  return st;
}

// GLB up to the BIN chunk's data: header, JSON chunk (space-padded), the BIN
// chunk's header when there is a buffer; the file is this + the buffer.
std::string glbHead(std::string json, size_t bin_size) {
  json.resize(align4(json.size()), ' ');
  std::string out;
  out.reserve(28 + json.size());
  out += "glTF";
  putU32(out, 2);
  putU32(out, uint32_t(12 + 8 + json.size() + (bin_size == 0 ? 0 : 8 + bin_size)));
  putU32(out, uint32_t(json.size()));
  putU32(out, 0x4E4F534Au);
  out += json;
  if (bin_size > 0) {
    putU32(out, uint32_t(bin_size));
    putU32(out, 0x004E4942u);
  }
  return out;
}

Result<std::string> serializeJson(tinygltf::Model& model, bool binary) {
  std::ostringstream stream;
  try {
    tinygltf::TinyGLTF gltf;
    // .gltf is for reading: indent it; GLB stays compact.
    if (!gltf.WriteGltfSceneToStream(&model, stream, !binary, binary))
      return makeError("glTF writer: tinygltf failed to serialise the model");
  } catch (const std::exception& e) {
    return makeError(std::string("glTF writer: cannot serialise: ") + e.what());
  }
  if (binary) return jsonChunk(stream.str());
  return stream.str();
}

// A pretty-printed .gltf whose (empty, placeholder-named) buffer becomes the
// external file `uri` of `size` bytes: tinygltf's stream writer can only
// embed, so its buffer entry is rewritten in place.
Status pointBufferAt(std::string& json, const std::string& uri, size_t size) {
  const std::string data_uri = "\"uri\": \"data:application/octet-stream;base64,\"";
  const size_t name = json.find(kBufferPlaceholder);
  const size_t length = name == std::string::npos ? name : json.rfind("\"byteLength\": 0,", name);
  const size_t data = name == std::string::npos ? name : json.find(data_uri, name);
  if (length == std::string::npos || data == std::string::npos)
    return makeError("glTF writer: the buffer entry was not found in the serialised JSON");
  json.replace(data, data_uri.size(), "\"uri\": \"" + uriEscape(uri) + "\"");
  json.replace(name, std::strlen(kBufferPlaceholder), "\"" + uriEscape(uri) + "\"");
  json.replace(length, std::strlen("\"byteLength\": 0,"),
               "\"byteLength\": " + std::to_string(size) + ",");
  return Status();
}

}  // namespace gltf
}  // namespace smpl
