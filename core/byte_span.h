// A run of bytes owned elsewhere: one part of a file written in parts
// (core/io/file_io.h FileContent::tail, writers/writer.h Writer::Files).
#pragma once

#include <cstddef>

namespace smpl {

struct ByteSpan {
  const void* data = nullptr;  // not owned; may be null when size is 0
  size_t size = 0;
};

}  // namespace smpl
