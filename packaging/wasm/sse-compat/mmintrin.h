/* Eigen's SSE path includes <mmintrin.h> (MMX); emscripten's SSE emulation
   has none and Eigen uses no MMX type: this one only includes the SSE one. */
#pragma once
#include <xmmintrin.h>
