# CMake toolchain file: WebAssembly with Debian's emscripten (its own
# toolchain file, then the folder scripts/wasm-deps.sh fills: zlib,
# libdeflate, libmd, meshoptimizer and musl's libm built from Debian's source
# packages, the header-only packages staged).
#   scripts/wasm-deps.sh /path/to/deps
#   cmake -S . -B build-wasm -DCMAKE_TOOLCHAIN_FILE=cmake/wasm.cmake -DSMPL_WASM_DEPS_PREFIX=/path/to/deps
include(/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake)
set(SMPL_WASM_DEPS_PREFIX "" CACHE PATH "Prefix filled by scripts/wasm-deps.sh")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES SMPL_WASM_DEPS_PREFIX)
if(SMPL_WASM_DEPS_PREFIX)
  list(APPEND CMAKE_FIND_ROOT_PATH ${SMPL_WASM_DEPS_PREFIX})
endif()
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(ENV{PKG_CONFIG_LIBDIR} "${SMPL_WASM_DEPS_PREFIX}/lib/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
set(ENV{NODE_PATH} "/usr/share/nodejs")  # emcc's optimizer needs Debian's node-acorn
