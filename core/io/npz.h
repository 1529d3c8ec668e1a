// .npz reader: a zip of .npy files. Keys lose their ".npy" suffix, as numpy's
// np.load does. Errors name the archive and the member:
// "model.npz/shapedirs.npy: truncated data: expected 1653600 bytes, found 1000".
//
// Lazy by design (like np.load's NpzFile): NpzArchive lists the members and
// decodes only the ones a caller asks for, so an unused member, however large
// or odd (object arrays, unsupported compression, a different dtype), costs
// nothing and never makes a load fail. Files are memory-mapped where the OS
// allows it, so unread members are not even paged in.
//
//   Result<NpzArchive> npz = NpzArchive::open("model.npz");
//   Result<ArrayDict> arrays = npz->read({"v_template", "f"});  // absent keys are left out
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/array.h"
#include "core/io/npy.h"
#include "core/io/zip.h"
#include "core/result.h"

namespace smpl {

class NpzArchive {
 public:
  struct Storage;  // the mapped or owned bytes (defined in npz.cpp)

  // Maps (or reads) the file and lists its members; no member is decoded.
  // Errors name `context` (default: the file's base name).
  static Result<NpzArchive> open(const std::string& path, const std::string& context = "");
  // The same over bytes already in memory (copied); `context` names them in errors.
  static Result<NpzArchive> fromBytes(const uint8_t* data, size_t size, const std::string& context);

  const std::string& context() const { return context_; }
  std::vector<std::string> keys() const;  // member names without ".npy", archive order
  bool has(const std::string& key) const;
  // The member's name in the archive ("shapedirs.npy"), for errors; "" if absent.
  std::string memberName(const std::string& key) const;

  // The member's raw .npy bytes (inflated, CRC-checked; `data`), charged to
  // the memory budget while the entry lives.
  Result<ZipEntry> memberBytes(const std::string& key) const;
  // The same bytes as memberBytes, viewed in place for a stored member (valid
  // while this archive lives), inflated once for a deflated one.
  Result<ZipBytes> memberView(const std::string& key) const;
  // Header of the member (dtype, shape) without decoding its data.
  Result<NpyHeaderInfo> header(const std::string& key) const;
  // True if the member is an object array ('|O'): from its first bytes only
  // (no full inflate); errors as header().
  Result<bool> isObjectArray(const std::string& key) const;
  // Decode one member. Object arrays ('|O') are refused here with
  //   "model.npz: 'key' is an object array ('|O'); expected numbers or text"
  // (core/models/npz_arrays decodes them with the data-only unpickler).
  Result<Array> get(const std::string& key) const;
  // Ok while every byte read from the mapping was the file's; after the file
  // shrank under it (mapping_guard.h: zeros were read instead), the error
  // naming the file. Every method above already returns that error; callers
  // that keep reading a memberView's bytes check it when done.
  Status intact() const;
  // Decode the listed keys that are present; absent keys are skipped, so the
  // caller decides which are required.
  Result<ArrayDict> read(const std::vector<std::string>& keys) const;
  // Every member but the object arrays, which are skipped (the eager readers below).
  Result<ArrayDict> readAllNumeric() const;

 private:
  std::shared_ptr<const Storage> storage_;
  std::vector<ZipMember> members_;
  std::vector<std::string> keys_;
  std::string context_;
  const ZipMember* find(const std::string& key) const;
  Status checkDecodedSize(const std::string& key) const;
  static Result<NpzArchive> fromStorage(std::shared_ptr<const Storage> storage,
                                        const std::string& context);
  // `r`, or the lost-mapping error when the file shrank while it was read.
  template <class T>
  Result<T> checked(Result<T> r) const {
    if (Status st = intact(); !st) return st.error();
    return r;
  }
};

// Eager reads of every member (np.load(...) then dict(...)), kept for small
// files such as betas. Object-array members are skipped (they are not numeric
// data; decode them through NpzArchive + core/models/npz_arrays if needed).
Result<ArrayDict> parseNpz(const uint8_t* data, size_t size, const std::string& context);
Result<ArrayDict> readNpzFile(const std::string& path);

// Only the listed keys that are present (lazy; object arrays refused as in get()).
Result<ArrayDict> readNpzFile(const std::string& path, const std::vector<std::string>& keys);

}  // namespace smpl
