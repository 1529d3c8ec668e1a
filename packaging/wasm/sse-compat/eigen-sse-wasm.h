/* Forced first include (-include) of the WebAssembly build: Eigen's SSE2
   path on emscripten's SSE emulation, as on x86-64. Eigen 3.4 treats
   clang (which reports __GNUC__ 4.2) as a gcc older than 6.3 and then uses
   x86 inline assembly for pmin/pmax; with the compiler macro taken as a
   recent gcc it uses the intrinsics. */
#pragma once
#if __has_include(<Eigen/src/Core/util/Macros.h>)
#include <Eigen/src/Core/util/Macros.h>
#undef EIGEN_COMP_GNUC
#define EIGEN_COMP_GNUC 120
#endif
