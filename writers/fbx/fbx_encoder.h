// Binary FBX encoding: a tree of named nodes with typed properties -> bytes.
// Knows nothing about scenes; fbx_scene.h builds the tree. The layout is the
// one every binary FBX reader expects (Blender's parse_fbx.py, Assimp, ufbx,
// the Autodesk SDK):
//
//   header   "Kaydara FBX Binary  \0" 0x1A 0x00, uint32 version
//   node     endOffset, numProperties, propertyListLen (uint32 for 7400,
//            uint64 for >= 7500), uint8 nameLen, name, properties, children,
//            then a null record if the node has children or no properties
//   top      nodes, then one null record
//   footer   fixed 16-byte id, 4 zero bytes, padding to 16, version,
//            120 zero bytes, fixed 16-byte magic
//
// Property payloads are encoded when added, so a node owns its bytes and the
// encoder only lays them out. Arrays larger than 128 bytes are zlib
// compressed (libdeflate, level FbxEncodeOptions::compress_level; level 0
// stores them raw, array encoding 0); that compression is deferred to
// encodeFbx(), which runs it on FbxEncodeOptions::threads workers (it is most
// of the time of a file with hundreds of blend shapes). Each array is
// compressed on its own, so the bytes do not depend on the thread count.
//
//   FbxNode root;
//   FbxNode& n = root.add("Vertices");
//   n.addDoubleArray(positions);
//   Result<std::string> bytes = encodeFbx(root.children, 7400);
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

struct FbxProperty {
  char type = 0;         // C Y I L F D S R f d l i b
  std::string payload;   // encoded bytes after the type code (empty when `shared`)
  bool deflate = false;  // payload is count + raw array bytes, compressed by encodeFbx()
  // Non-null: the payload, held once for every node that has it (an array
  // several nodes repeat: the key times of every curve of a clip); it is
  // compressed once and written at each place.
  std::shared_ptr<const std::string> shared;
  const std::string& bytes() const { return shared ? *shared : payload; }
};

// An array property encoded once, for FbxNode::addShared on several nodes.
FbxProperty fbxSharedInt64Array(const std::vector<int64_t>& v);
FbxProperty fbxSharedDoubleArray(const std::vector<double>& v);

struct FbxNode {
  std::string name;
  std::vector<FbxProperty> properties;
  std::vector<FbxNode> children;

  FbxNode() = default;
  explicit FbxNode(std::string n) : name(std::move(n)) {}

  // Appends a child and returns it (reference valid until the next add()).
  FbxNode& add(std::string child_name);

  FbxNode& addBool(bool v);
  FbxNode& addInt16(int16_t v);
  FbxNode& addInt32(int32_t v);
  FbxNode& addInt64(int64_t v);
  FbxNode& addFloat(float v);
  FbxNode& addDouble(double v);
  FbxNode& addString(const std::string& v);
  FbxNode& addRaw(const std::string& v);
  FbxNode& addFloatArray(const std::vector<float>& v);
  FbxNode& addDoubleArray(const std::vector<double>& v);
  FbxNode& addInt32Array(const std::vector<int32_t>& v);
  FbxNode& addInt64Array(const std::vector<int64_t>& v);
  FbxNode& addShared(const FbxProperty& p);  // p from fbxShared*Array: its payload is not copied
};

// Arrays whose raw size exceeds this many bytes are deflated.
constexpr size_t kFbxCompressThreshold = 128;
// Default compression level (libdeflate) for arrays: fast. Same level, same bytes.
constexpr int kFbxZlibLevel = 1;
constexpr int kFbxMaxZlibLevel = 12;  // libdeflate's highest

struct FbxEncodeOptions {
  // 0: arrays stored uncompressed (encoding 0, what the FBX SDK writes for
  // EXP_FBX_COMPRESS_LEVEL 0); 1..12: libdeflate level (encoding 1, zlib).
  int compress_level = kFbxZlibLevel;
  int threads = 0;  // compression workers; 0 = all cores. Never changes the bytes.
};

// Serialises top-level nodes as a complete binary FBX file. version is 7400
// (32-bit record headers) or 7500 (64-bit). Fails on names longer than 255
// bytes, for 7400 on files beyond 4 GiB, and on a level outside 0..12.
Result<std::string> encodeFbx(const std::vector<FbxNode>& top, uint32_t version,
                              const FbxEncodeOptions& options = FbxEncodeOptions());
// The same bytes from nodes handed over: each array is freed once compressed
// and each compressed array once written, so a large file (a long clip's
// curves) is not in memory as arrays, compressed arrays and output at once.
// `top` is left empty.
Result<std::string> encodeFbx(std::vector<FbxNode>&& top, uint32_t version,
                              const FbxEncodeOptions& options = FbxEncodeOptions());

}  // namespace smpl
