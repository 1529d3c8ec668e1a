/* Eigen's SSE path includes <mmintrin.h> (MMX); emscripten's SSE emulation
   has none and Eigen uses no MMX type: an empty header. */
#pragma once
#include <xmmintrin.h>
