# CMake toolchain file: Windows x86_64 with Debian's mingw-w64 (GCC 12, POSIX
# thread model, so std::thread/std::mutex work), tested under wine.
#
#   bash scripts/windows-deps.sh /path/to/deps          # libdeflate etc., see there
#   cmake -S . -B build-win -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake \
#         -DSMPL_WIN_DEPS_PREFIX=/path/to/deps
#
# Debian packages: mingw-w64 (g++-mingw-w64-x86-64-posix), libz-mingw-w64-dev,
# wine + wine64 (to run the tests; CMAKE_CROSSCOMPILING_EMULATOR below).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(_smpl_triple x86_64-w64-mingw32)

# The -posix variants: the -win32 thread model has no std::thread in GCC 12.
set(CMAKE_C_COMPILER ${_smpl_triple}-gcc-posix)
set(CMAKE_CXX_COMPILER ${_smpl_triple}-g++-posix)
set(CMAKE_RC_COMPILER ${_smpl_triple}-windres)
set(CMAKE_AR ${_smpl_triple}-ar CACHE FILEPATH "")
set(CMAKE_RANLIB ${_smpl_triple}-ranlib CACHE FILEPATH "")

# Folder made by scripts/windows-deps.sh (libdeflate.a, its pkg-config file
# and CMake package; the header-only Debian packages staged for find_package).
set(SMPL_WIN_DEPS_PREFIX "" CACHE PATH "Prefix filled by scripts/windows-deps.sh")
# try_compile() projects re-read this file: pass the prefix on to them.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES SMPL_WIN_DEPS_PREFIX)

# Search only the mingw sysroot and the deps prefix for headers, libraries and
# packages (never the build machine's /usr/include or /usr/lib); programs
# (python3, pkg-config, ...) come from the build machine.
set(CMAKE_FIND_ROOT_PATH /usr/${_smpl_triple})
if(SMPL_WIN_DEPS_PREFIX)
  list(APPEND CMAKE_FIND_ROOT_PATH ${SMPL_WIN_DEPS_PREFIX})
endif()
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Static archives first (zlib: libz.a, not the import library libz.dll.a).
set(CMAKE_FIND_LIBRARY_SUFFIXES .a .dll.a .lib)
set(ZLIB_USE_STATIC_LIBS ON)

# pkg-config (pkg_check_modules(... libdeflate)): the host pkg-config, reading
# only the target's .pc files; FindPkgConfig passes PKG_CONFIG_LIBDIR through.
set(ENV{PKG_CONFIG_LIBDIR} "${SMPL_WIN_DEPS_PREFIX}/lib/pkgconfig:/usr/${_smpl_triple}/lib/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")

# One self-contained .exe: libgcc, libstdc++ and winpthread linked in, so it
# needs only Windows' own DLLs (KERNEL32, msvcrt, bcrypt, SHELL32, ...).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-static")
set(CMAKE_MODULE_LINKER_FLAGS_INIT "-static")


# ctest / add_test run the .exe files through wine64.
find_program(SMPL_WINE NAMES wine wine64)
if(SMPL_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${SMPL_WINE})
endif()
