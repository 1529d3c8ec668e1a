// A minimal .npz writer for the MJCF writer's reference motion
// (<stem>.qpos.npz, mjcf_writer.h): an uncompressed zip (method 0, "stored")
// of .npy version 1.0 members, as np.savez writes them, readable by
// np.load(allow_pickle=False) and by core/io/npz.h.
//
// Deterministic bytes: members in the given order, every timestamp
// 1980-01-01 00:00 (the zip epoch), no extra fields. Formats: the zip
// application note (PKWARE APPNOTE.TXT 4.3.7 local header, 4.3.12 central
// directory, 4.3.16 end of central directory) and numpy's NEP 1 .npy format
// (magic, version 1.0, little-endian header length, a Python dict literal
// padded with spaces to a multiple of 64 bytes and ending in '\n').
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/result.h"

namespace smpl {

struct NpyMember {
  std::string name;           // "qpos" (stored as "qpos.npy")
  std::string descr;          // numpy dtype text: "<f8" or "<U12"
  std::vector<size_t> shape;  // {} a scalar, {T, nq}, ...
  std::string data;           // the raw little-endian elements, C order
};

// float64 (little-endian) members.
NpyMember npyDoubles(const std::string& name, std::vector<size_t> shape,
                     const std::vector<double>& values);
// A 1-D array of numpy unicode strings (dtype "<U<longest>", UTF-32LE code
// points, shorter strings padded with zeros). Errors: a name that is not
// valid UTF-8.
Result<NpyMember> npyStrings(const std::string& name, const std::vector<std::string>& values);

// The .npz bytes of `members`. Errors: a member over 4 GiB (no zip64 here).
Result<std::string> npzBytes(const std::vector<NpyMember>& members);

}  // namespace smpl
