// SHA-256 moved to core/io/sha256.h (the sidecar records the digest of every
// output file, written by the exporter layer); this header keeps cli's
// includes working.
#pragma once

#include "core/io/sha256.h"
