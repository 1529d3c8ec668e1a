#include "writers/fbx/fbx_encoder.h"

#include <libdeflate.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>
#include <string_view>
#include <thread>
#include <type_traits>
#include <unordered_map>

#include "core/heap_trim.h"
#include "core/parallel.h"

namespace smpl {
namespace {

const char kMagic[] = "Kaydara FBX Binary  \x00\x1a\x00";  // 23 bytes with the NULs
constexpr size_t kMagicSize = 23;
// Fixed footer bytes every reader and writer we know of uses.
const unsigned char kFooterId[16] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                     0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
const unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                        0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

// Little-endian append, independent of the host byte order.
template <class T>
void putLE(std::string& out, T value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof(T));
  for (size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
}

bool hostIsLittleEndian() {
  const uint16_t one = 1;
  uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <class T>
void patchLE(std::string& out, size_t at, T value) {
  for (size_t i = 0; i < sizeof(T); ++i)
    out[at + i] = static_cast<char>((uint64_t(value) >> (8 * i)) & 0xff);
}

FbxProperty scalar(char type, std::string payload) {
  return FbxProperty{type, std::move(payload), false, nullptr};
}

template <class T>
std::string encodeScalar(T v) {
  std::string s;
  putLE(s, v);
  return s;
}

// Array payload: count, encoding (0 raw, 1 zlib), byte length, data. Large
// arrays keep count + raw bytes and are deflated later by deflateAll().
template <class T>
FbxProperty encodeArray(char type, const std::vector<T>& values) {
  std::string payload;
  payload.reserve(12 + values.size() * sizeof(T));
  putLE(payload, static_cast<uint32_t>(values.size()));
  const bool deflate = values.size() * sizeof(T) > kFbxCompressThreshold;
  if (!deflate) {
    putLE(payload, uint32_t(0));
    putLE(payload, static_cast<uint32_t>(values.size() * sizeof(T)));
  }
  if (hostIsLittleEndian()) {  // the values' bytes are already the file's
    payload.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  } else {
    for (const T& v : values) putLE(payload, v);
  }
  return FbxProperty{type, std::move(payload), deflate, nullptr};
}

// count + raw -> count, encoding 1, compressed length, zlib stream (raw
// storage, encoding 0, without a compressor: level 0, or out of memory).
// libdeflate compresses the whole buffer in one call, several times faster
// than zlib's compress2 at the same level; the stream is a standard zlib one.
std::string deflatePayload(libdeflate_compressor* compressor, const std::string& pending) {
  const char* raw = pending.data() + 4;
  const size_t raw_size = pending.size() - 4;
  std::string out;
  size_t packed = 0;
  if (compressor) {
    out.resize(12 + libdeflate_zlib_compress_bound(compressor, raw_size));
    packed = libdeflate_zlib_compress(compressor, raw, raw_size, &out[12], out.size() - 12);
  }
  if (packed == 0) {
    out = pending.substr(0, 4);
    putLE(out, uint32_t(0));
    putLE(out, static_cast<uint32_t>(raw_size));
    return out + pending.substr(4);
  }
  out.resize(12 + packed);
  std::memcpy(&out[0], pending.data(), 4);
  patchLE(out, 4, uint32_t(1));
  patchLE(out, 8, static_cast<uint32_t>(packed));
  return out;
}

// A deferred array's payload, and the same string when the encoder may free
// it once compressed (a payload of nodes handed over, not shared).
struct Pending {
  const std::string* bytes;
  std::string* owned;
};

// Node is FbxNode (nodes handed over: their own payloads may be freed) or
// const FbxNode.
template <class Node>
void collectDeflates(Node& n, std::vector<Pending>* pending) {
  for (auto& p : n.properties) {
    if (!p.deflate) continue;
    std::string* owned = nullptr;
    if constexpr (!std::is_const_v<Node>)
      if (!p.shared) owned = &p.payload;
    pending->push_back({&p.bytes(), owned});
  }
  for (auto& child : n.children) collectDeflates(child, pending);
}

// The compressed arrays: one stream per distinct payload, the stream of each
// deferred payload (by its address: a shared payload has one) and how many
// properties still have to write each (a stream is freed after its last).
struct Deflated {
  std::vector<std::string> streams;
  std::vector<size_t> uses;
  std::unordered_map<const std::string*, size_t> stream_of;
  const std::string& of(const std::string* payload) const { return streams[stream_of.at(payload)]; }
};

// Each deferred payload's stream: a shared payload (one address) and arrays
// with the same bytes (a shape's zero normal deltas, the Indexes of shapes
// that move every vertex) get one, so each distinct payload is compressed
// once; the file is the same as with every array compressed. Returns the
// first payload of each stream.
std::vector<Pending> assignStreams(const std::vector<Pending>& pending, Deflated* d) {
  std::vector<Pending> distinct;
  std::unordered_map<std::string_view, size_t> seen;
  for (const Pending& p : pending) {
    if (auto known = d->stream_of.find(p.bytes); known != d->stream_of.end()) {
      ++d->uses[known->second];  // a shared payload met before
      continue;
    }
    const auto [it, added] = seen.emplace(std::string_view(*p.bytes), distinct.size());
    if (added) distinct.push_back(p), d->uses.push_back(0);
    d->stream_of.emplace(p.bytes, it->second);
    ++d->uses[it->second];
  }
  return distinct;
}

// Compress every deferred array on `threads` workers (0: all cores); the
// result is independent of the thread count (each array is compressed on
// its own, by its own call). Level 0 stores them raw.
// With owned payloads (nodes handed over) each is freed once compressed.
Deflated deflateAll(const std::vector<Pending>& pending, const FbxEncodeOptions& options) {
  Deflated d;
  const std::vector<Pending> distinct = assignStreams(pending, &d);
  for (const Pending& p : pending)  // a copy of an earlier payload is not read again
    if (p.owned && distinct[d.stream_of.at(p.bytes)].bytes != p.bytes) std::string().swap(*p.owned);
  d.streams.resize(distinct.size());
  std::atomic<size_t> next{0};
  auto work = [&] {
    libdeflate_compressor* compressor =
        options.compress_level > 0 ? libdeflate_alloc_compressor(options.compress_level) : nullptr;
    for (size_t j; (j = next++) < distinct.size();) {
      d.streams[j] = deflatePayload(compressor, *distinct[j].bytes);
      if (distinct[j].owned) std::string().swap(*distinct[j].owned);
    }
    if (compressor) libdeflate_free_compressor(compressor);
  };
  const size_t wanted = options.threads > 0 ? size_t(options.threads) : size_t(hardwareThreads());
  const size_t threads = std::min<size_t>(wanted, distinct.size());
  runWorkers(int(threads), [&](int, int) { work(); });
  return d;
}

struct Encoder {
  Deflated* deflated = nullptr;
  bool release = false;  // free each stream after its last use
  size_t freed = 0;      // bytes freed since the heap was last trimmed
  bool stored = false;   // level 0: deferred arrays written raw (encoding 0)
  bool wide = false;     // 64-bit record headers (7500+)
  std::string out;
  std::string error;

  size_t headerSize() const { return wide ? 24 : 12; }

  void putHeaderField(uint64_t v) {
    if (wide)
      putLE(out, v);
    else
      putLE(out, static_cast<uint32_t>(v));
  }

  void patchHeaderField(size_t at, uint64_t v) {
    if (wide)
      patchLE(out, at, v);
    else
      patchLE(out, at, static_cast<uint32_t>(v));
  }

  void nullRecord() { out.append(headerSize() + 1, '\0'); }

  // A deferred array's payload is count + raw bytes; stored, it gains the
  // encoding (0) and byte length after the count.
  size_t payloadSize(const FbxProperty& p) const {
    if (!p.deflate) return p.bytes().size();
    return stored ? p.bytes().size() + 8 : deflated->of(&p.bytes()).size();
  }
  void putPayload(const FbxProperty& p) {
    if (!p.deflate) {
      out += p.bytes();
    } else if (!stored) {
      const size_t s = deflated->stream_of.at(&p.bytes());
      out += deflated->streams[s];
      if (release && --deflated->uses[s] == 0) releaseStream(&deflated->streams[s]);
    } else {
      const std::string& raw = p.bytes();
      out.append(raw, 0, 4);
      putLE(out, uint32_t(0));
      putLE(out, static_cast<uint32_t>(raw.size() - 4));
      out.append(raw, 4, std::string::npos);
    }
  }

  // Frees a written stream; every 16 MB the freed pages go back to the
  // system (heap_trim.h), so the output grows into the memory they leave.
  void releaseStream(std::string* stream) {
    freed += stream->size();
    std::string().swap(*stream);
    if (freed < (16u << 20)) return;
    returnFreedHeap();
    freed = 0;
  }

  // An upper bound of the encoded size of `n` (reserved once: no regrowth).
  size_t sizeBound(const FbxNode& n) const {
    size_t bytes = 2 * headerSize() + 2 + n.name.size();
    for (const FbxProperty& p : n.properties) bytes += 1 + payloadSize(p);
    for (const FbxNode& child : n.children) bytes += sizeBound(child);
    return bytes;
  }

  bool node(const FbxNode& n) {
    if (n.name.empty() || n.name.size() > 255) {
      error = "FBX node name '" + n.name.substr(0, 40) + "' must be 1..255 bytes";
      return false;
    }
    size_t header_at = out.size();
    uint64_t prop_bytes = 0;
    for (const FbxProperty& p : n.properties) prop_bytes += 1 + payloadSize(p);
    putHeaderField(0);  // end offset, patched below
    putHeaderField(n.properties.size());
    putHeaderField(prop_bytes);
    out.push_back(static_cast<char>(n.name.size()));
    out += n.name;
    for (const FbxProperty& p : n.properties) {
      out.push_back(p.type);
      putPayload(p);
    }
    for (const FbxNode& child : n.children)
      if (!node(child)) return false;
    // Readers detect "has nested block" by end offset > end of properties.
    if (!n.children.empty() || n.properties.empty()) nullRecord();
    if (!wide && out.size() > std::numeric_limits<uint32_t>::max()) {
      error = "FBX 7400 file exceeds 4 GiB at node '" + n.name + "'; use FBX 7500";
      return false;
    }
    patchHeaderField(header_at, out.size());
    return true;
  }

  void footer(uint32_t version) {
    out.append(reinterpret_cast<const char*>(kFooterId), 16);
    out.append(4, '\0');
    size_t pad = 16 - (out.size() % 16);  // a full 16 when already aligned
    out.append(pad, '\0');
    putLE(out, version);
    out.append(120, '\0');
    out.append(reinterpret_cast<const char*>(kFooterMagic), 16);
  }
};

}  // namespace

FbxNode& FbxNode::add(std::string child_name) {
  children.emplace_back(std::move(child_name));
  return children.back();
}

FbxNode& FbxNode::addBool(bool v) {
  properties.push_back(scalar('C', std::string(1, v ? '\x01' : '\x00')));
  return *this;
}
FbxNode& FbxNode::addInt16(int16_t v) {
  properties.push_back(scalar('Y', encodeScalar(v)));
  return *this;
}
FbxNode& FbxNode::addInt32(int32_t v) {
  properties.push_back(scalar('I', encodeScalar(v)));
  return *this;
}
FbxNode& FbxNode::addInt64(int64_t v) {
  properties.push_back(scalar('L', encodeScalar(v)));
  return *this;
}
FbxNode& FbxNode::addFloat(float v) {
  properties.push_back(scalar('F', encodeScalar(v)));
  return *this;
}
FbxNode& FbxNode::addDouble(double v) {
  properties.push_back(scalar('D', encodeScalar(v)));
  return *this;
}

FbxNode& FbxNode::addString(const std::string& v) {
  properties.push_back(scalar('S', encodeScalar(static_cast<uint32_t>(v.size())) + v));
  return *this;
}
FbxNode& FbxNode::addRaw(const std::string& v) {
  properties.push_back(scalar('R', encodeScalar(static_cast<uint32_t>(v.size())) + v));
  return *this;
}
FbxNode& FbxNode::addFloatArray(const std::vector<float>& v) {
  properties.push_back(encodeArray('f', v));
  return *this;
}
FbxNode& FbxNode::addDoubleArray(const std::vector<double>& v) {
  properties.push_back(encodeArray('d', v));
  return *this;
}
FbxNode& FbxNode::addInt32Array(const std::vector<int32_t>& v) {
  properties.push_back(encodeArray('i', v));
  return *this;
}
FbxNode& FbxNode::addInt64Array(const std::vector<int64_t>& v) {
  properties.push_back(encodeArray('l', v));
  return *this;
}
FbxNode& FbxNode::addShared(const FbxProperty& p) {
  properties.push_back(p);  // copies the shared_ptr, not the payload
  return *this;
}

namespace {

FbxProperty sharedProperty(FbxProperty p) {
  p.shared = std::make_shared<const std::string>(std::move(p.payload));
  p.payload.clear();
  return p;
}

}  // namespace

FbxProperty fbxSharedInt64Array(const std::vector<int64_t>& v) {
  return sharedProperty(encodeArray('l', v));
}

FbxProperty fbxSharedDoubleArray(const std::vector<double>& v) {
  return sharedProperty(encodeArray('d', v));
}

namespace {

Status checkEncoding(uint32_t version, const FbxEncodeOptions& options) {
  if (version < 7000 || version >= 8000)
    return makeError("FBX: unsupported version " + std::to_string(version) +
                     "; expected 7400 or 7500");
  if (options.compress_level < 0 || options.compress_level > kFbxMaxZlibLevel)
    return makeError("FBX: compression level " + std::to_string(options.compress_level) +
                     "; expected 0 (stored) to 12");
  return Status();
}

// `pending`: the deferred arrays of `top` (none at level 0: the Encoder
// stores them raw); `release`: they may be freed as they are used.
Result<std::string> encode(const std::vector<FbxNode>& top, const std::vector<Pending>& pending,
                           uint32_t version, const FbxEncodeOptions& options, bool release) {
  Deflated deflated = deflateAll(pending, options);
  if (release) returnFreedHeap();  // the arrays compressed and freed
  Encoder enc;
  enc.deflated = &deflated;
  enc.release = release;
  enc.stored = options.compress_level == 0;
  enc.wide = version >= 7500;
  size_t bound = 27 + enc.headerSize() + 1 + 200;  // header, top null record, footer
  for (const FbxNode& n : top) bound += enc.sizeBound(n);
  enc.out.reserve(bound);
  enc.out.append(kMagic, kMagicSize);
  putLE(enc.out, version);
  for (const FbxNode& n : top)
    if (!enc.node(n)) return makeError(enc.error);
  enc.nullRecord();
  enc.footer(version);
  return std::move(enc.out);
}

}  // namespace

Result<std::string> encodeFbx(const std::vector<FbxNode>& top, uint32_t version,
                              const FbxEncodeOptions& options) {
  if (Status st = checkEncoding(version, options); !st) return st.error();
  std::vector<Pending> pending;
  if (options.compress_level > 0)
    for (const FbxNode& n : top) collectDeflates(n, &pending);
  return encode(top, pending, version, options, false);
}

Result<std::string> encodeFbx(std::vector<FbxNode>&& top, uint32_t version,
                              const FbxEncodeOptions& options) {
  if (Status st = checkEncoding(version, options); !st) return st.error();
  std::vector<Pending> pending;
  if (options.compress_level > 0)
    for (FbxNode& n : top) collectDeflates(n, &pending);
  Result<std::string> bytes = encode(top, pending, version, options, true);
  top.clear();  // its arrays are gone: nothing is left to read
  return bytes;
}

}  // namespace smpl
