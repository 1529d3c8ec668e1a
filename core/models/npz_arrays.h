// The loaders' way into .npz files: only the keys a loader needs are read
// (NpzArchive is lazy), and a needed key that numpy stored as an object array
// ('|O', e.g. the dicts in the SMPL-X release or AMASS stage-II files) is
// decoded by the data-only unpickler. Keys not asked for are never touched, so
// they cannot make a load fail.
#pragma once

#include <string>
#include <vector>

#include "core/array.h"
#include "core/io/npz.h"
#include "core/result.h"

namespace smpl {

// Decode `key` from `npz`: numeric/text members by the .npy reader, object
// members by parseObjectNpy. Errors: "<context>: '<key>': <reason>".
Result<Array> readNpzMember(const NpzArchive& npz, const std::string& key);

// The present ones among `keys`, from the .npz at `path`; absent keys are left
// out (the caller decides what is required). `context` names the file in
// errors (default: its base name).
Result<ArrayDict> readNpzArrays(const std::string& path, const std::vector<std::string>& keys,
                                const std::string& context = "");

}  // namespace smpl
