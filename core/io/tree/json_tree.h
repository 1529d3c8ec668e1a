// JSON files as DataNode trees (core/data_node.h): EasyMocap's per-frame
// lists of persons, and any JSON a motion layout reads. JSON has no arrays of
// its own, so arrays of numbers become Array leaves by their shape:
//   object                              -> Dict (keys in file order; a
//                                          repeated key keeps its first place
//                                          and its last value, as Python's json)
//   array of numbers (any rectangular   -> Array leaf, C order; dtype "<f8"
//   nesting; true/false count as 0/1)      if any number has a fraction or
//                                          exponent, "|b1" if all are
//                                          booleans, else "<i8"
//   any other array (ragged, mixed, of  -> List, elements converted alike
//   objects or strings; [] too)
//   string                              -> text leaf (one string, shape ())
//   number, true/false                  -> 0-d Array leaf
//   null                                -> None
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/data_node.h"
#include "core/result.h"

namespace smpl {

// Parses `data` (UTF-8 JSON text). Memory: 12 bytes per byte of text are
// charged to the memory budget before parsing (the rule of the JSON motion
// reader: a parsed value takes 16 bytes and a number at least 2 characters),
// and the tree's arrays and nodes as they are built. Errors name `context`:
// "f.json: not valid JSON (syntax error at byte 17)", "f.json: JSON nested
// deeper than 32 levels" (checked before parsing).
Result<DataNode> parseJsonTree(const uint8_t* data, size_t size, const std::string& context);

}  // namespace smpl
