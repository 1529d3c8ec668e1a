#!/usr/bin/env bash
# Builds the Windows (x86_64-w64-mingw32) third-party libraries that Debian
# does not ship for mingw, from Debian's own source packages, into PREFIX:
#   libdeflate     PREFIX/lib/libdeflate.a, include/libdeflate.h,
#                  lib/pkgconfig/libdeflate.pc, lib/cmake/libdeflate/
#   meshoptimizer  (optional, --meshopt) PREFIX/lib/libmeshoptimizer.a,
#                  include/meshoptimizer.h, lib/cmake/meshoptimizer/
# and stages Debian's header-only packages (libeigen3-dev, nlohmann-json3-dev,
# libtinygltf-dev) under PREFIX, as symlinks to /usr/include plus their CMake
# package files, so that find_package() finds them with the toolchain's
# CMAKE_FIND_ROOT_PATH_MODE_PACKAGE=ONLY without putting the build machine's
# /usr/include on the include path.
#
# Usage: scripts/windows-deps.sh [--meshopt] PREFIX
# Needs: mingw-w64 (x86_64-w64-mingw32-gcc-posix), dpkg-dev, make, cmake (for
# --meshopt), libeigen3-dev nlohmann-json3-dev libtinygltf-dev, and Debian's
# apt mirror. The system's apt configuration is not changed: a private
# sources list (deb-src, bookworm) and private list/cache folders under
# PREFIX/.src are used. Idempotent: a library whose PREFIX stamp names the
# Debian source version that apt offers now is not rebuilt.
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail

MESHOPT=0
PREFIX=""
for arg in "$@"; do
  case "$arg" in
    --meshopt) MESHOPT=1 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    -*) echo "windows-deps: unknown option $arg" >&2; exit 2 ;;
    *) PREFIX="$arg" ;;
  esac
done
[ -n "$PREFIX" ] || { echo "usage: $0 [--meshopt] PREFIX" >&2; exit 2; }
mkdir -p "$PREFIX"
PREFIX="$(cd "$PREFIX" && pwd)"

TRIPLE=x86_64-w64-mingw32
CC="${TRIPLE}-gcc-posix"
CXX="${TRIPLE}-g++-posix"
AR="${TRIPLE}-ar"
SUITE="${SMPL_WIN_DEPS_SUITE:-bookworm}"
MIRROR="${SMPL_WIN_DEPS_MIRROR:-http://deb.debian.org/debian}"
KEYRING="${SMPL_WIN_DEPS_KEYRING:-/usr/share/keyrings/debian-archive-keyring.gpg}"
JOBS="${SMPL_WIN_DEPS_JOBS:-2}"
WORK="$PREFIX/.src"
STAMPS="$PREFIX/share/smpl-win-deps"
mkdir -p "$STAMPS"

step() { echo "windows-deps: $*"; }
die() { echo "windows-deps: error: $*" >&2; exit 1; }

for tool in "$CC" "$CXX" "$AR" apt-get apt-cache dpkg-source make; do
  command -v "$tool" >/dev/null || die "$tool not found (Debian packages: mingw-w64 dpkg-dev make)"
done
step "toolchain $("$CC" -dumpversion) ($CC), prefix $PREFIX"

# --- Debian source packages through a private apt state (scripts/debian-source.sh)
# shellcheck source=scripts/debian-source.sh
source "$(dirname "$0")/debian-source.sh"
SMPL_DEB_SUITE=$SUITE SMPL_DEB_MIRROR=$MIRROR SMPL_DEB_KEYRING=$KEYRING debsrc_init "$WORK"
step "apt source index ($SUITE, deb-src) updated"
src_version() { debsrc_version "$1"; }
fetch_source() { debsrc_fetch "$1" "$2" || die "cannot get the source of $1=$2"; }

# up_to_date NAME FILE VERSION: FILE exists and the stamp names VERSION
up_to_date() {
  [ -f "$2" ] && [ -f "$STAMPS/$1.version" ] &&
    { [ -z "$3" ] || [ "$(cat "$STAMPS/$1.version")" = "$3" ]; }
}

# --- libdeflate ----------------------------------------------------------
LD_VER="$(src_version libdeflate)"
if up_to_date libdeflate "$PREFIX/lib/libdeflate.a" "$LD_VER"; then
  step "libdeflate $(cat "$STAMPS/libdeflate.version") already in $PREFIX/lib/libdeflate.a, skipped"
else
  [ -n "$LD_VER" ] || die "apt knows no source package libdeflate in $SUITE"
  step "libdeflate $LD_VER: downloading the Debian source package"
  SRC="$(fetch_source libdeflate "$LD_VER")"
  step "libdeflate $LD_VER: unpacked in $SRC"
  # Upstream's Makefile detects mingw from '$CC -dumpmachine' and names the
  # static library libdeflatestatic.lib; only the library is built.
  make -C "$SRC" -j"$JOBS" CC="$CC" AR="$AR" DISABLE_SHARED=1 libdeflatestatic.lib \
    >"$WORK/libdeflate-build.log" 2>&1 || die "libdeflate build failed (see $WORK/libdeflate-build.log)"
  step "libdeflate $LD_VER: built with $CC"
  mkdir -p "$PREFIX/include" "$PREFIX/lib/pkgconfig" "$PREFIX/lib/cmake/libdeflate"
  install -m644 "$SRC/libdeflatestatic.lib" "$PREFIX/lib/libdeflate.a"
  install -m644 "$SRC/libdeflate.h" "$PREFIX/include/libdeflate.h"
  upstream="${LD_VER%-*}"
  cat >"$PREFIX/lib/pkgconfig/libdeflate.pc" <<EOF
prefix=$PREFIX
exec_prefix=\${prefix}
includedir=\${prefix}/include
libdir=\${prefix}/lib

Name: libdeflate
Description: Fast implementation of DEFLATE, zlib, and gzip (static, $TRIPLE)
Version: $upstream
Libs: -L\${libdir} -ldeflate
Cflags: -I\${includedir}
EOF
  cat >"$PREFIX/lib/cmake/libdeflate/libdeflate-config.cmake" <<'EOF'
# Written by scripts/windows-deps.sh: static libdeflate for x86_64-w64-mingw32.
get_filename_component(_libdeflate_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET libdeflate::libdeflate_static)
  add_library(libdeflate::libdeflate_static STATIC IMPORTED)
  set_target_properties(libdeflate::libdeflate_static PROPERTIES
    IMPORTED_LOCATION "${_libdeflate_prefix}/lib/libdeflate.a"
    INTERFACE_INCLUDE_DIRECTORIES "${_libdeflate_prefix}/include")
  add_library(libdeflate::libdeflate INTERFACE IMPORTED)
  set_target_properties(libdeflate::libdeflate PROPERTIES
    INTERFACE_LINK_LIBRARIES libdeflate::libdeflate_static)
endif()
unset(_libdeflate_prefix)
set(libdeflate_FOUND TRUE)
EOF
  printf 'set(PACKAGE_VERSION "%s")\nif(PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)\n  set(PACKAGE_VERSION_COMPATIBLE FALSE)\nelse()\n  set(PACKAGE_VERSION_COMPATIBLE TRUE)\n  if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)\n    set(PACKAGE_VERSION_EXACT TRUE)\n  endif()\nendif()\n' \
    "$upstream" >"$PREFIX/lib/cmake/libdeflate/libdeflate-config-version.cmake"
  echo "$LD_VER" >"$STAMPS/libdeflate.version"
  step "libdeflate $LD_VER: installed $PREFIX/lib/libdeflate.a"
fi

# --- meshoptimizer (optional) ---------------------------------------------
if [ "$MESHOPT" = 1 ]; then
  MO_VER="$(src_version meshoptimizer)"
  if up_to_date meshoptimizer "$PREFIX/lib/libmeshoptimizer.a" "$MO_VER"; then
    step "meshoptimizer $(cat "$STAMPS/meshoptimizer.version") already in $PREFIX/lib/libmeshoptimizer.a, skipped"
  else
    [ -n "$MO_VER" ] || die "apt knows no source package meshoptimizer in $SUITE"
    command -v cmake >/dev/null || die "cmake not found"
    step "meshoptimizer $MO_VER: downloading the Debian source package"
    SRC="$(fetch_source meshoptimizer "$MO_VER")"
    step "meshoptimizer $MO_VER: unpacked in $SRC"
    TOOLCHAIN="$(cd "$(dirname "$0")/.." && pwd)/cmake/mingw-w64-x86_64.cmake"
    [ -f "$TOOLCHAIN" ] || die "toolchain file $TOOLCHAIN not found"
    rm -rf "$WORK/meshoptimizer-build"
    { cmake -S "$SRC" -B "$WORK/meshoptimizer-build" -DCMAKE_TOOLCHAIN_FILE="$TOOLCHAIN" \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$PREFIX" -DCMAKE_INSTALL_LIBDIR=lib \
        -DMESHOPT_BUILD_SHARED_LIBS=OFF -DMESHOPT_BUILD_GLTFPACK=OFF -DMESHOPT_BUILD_DEMO=OFF &&
      cmake --build "$WORK/meshoptimizer-build" -j"$JOBS" &&
      cmake --install "$WORK/meshoptimizer-build"; } >"$WORK/meshoptimizer-build.log" 2>&1 ||
      die "meshoptimizer build failed (see $WORK/meshoptimizer-build.log)"
    echo "$MO_VER" >"$STAMPS/meshoptimizer.version"
    step "meshoptimizer $MO_VER: installed $PREFIX/lib/libmeshoptimizer.a"
  fi
fi

# --- musl's libm (core/math/libm.h), from Debian's musl source package -----
"$(dirname "$0")/portable-libm.sh" --target mingw "$PREFIX"

# --- header-only Debian packages, staged for find_package() --------------
# Symlinks to the build machine's headers (nothing copied) plus the packages'
# relocatable CMake files, so that their targets point at PREFIX/include/...
# and never add -isystem /usr/include (which would shadow mingw's C headers).
mkdir -p "$PREFIX/include" "$PREFIX/share/eigen3/cmake" "$PREFIX/share/cmake/nlohmann_json" \
         "$PREFIX/lib/cmake/TinyGLTF"
staged=""
if [ -d /usr/include/eigen3 ] && [ -f /usr/share/eigen3/cmake/Eigen3Config.cmake ]; then
  ln -sfn /usr/include/eigen3 "$PREFIX/include/eigen3"
  cp -f /usr/share/eigen3/cmake/*.cmake "$PREFIX/share/eigen3/cmake/"
  staged="$staged eigen3"
fi
if [ -d /usr/include/nlohmann ] && [ -f /usr/share/cmake/nlohmann_json/nlohmann_jsonConfig.cmake ]; then
  ln -sfn /usr/include/nlohmann "$PREFIX/include/nlohmann"
  cp -f /usr/share/cmake/nlohmann_json/*.cmake "$PREFIX/share/cmake/nlohmann_json/"
  staged="$staged nlohmann_json"
fi
if [ -f /usr/include/tiny_gltf.h ]; then
  ln -sfn /usr/include/tiny_gltf.h "$PREFIX/include/tiny_gltf.h"
  # Header only: the project compiles the implementation itself (as for
  # SMPL_STATIC, writers/gltf/static/tinygltf_impl.cpp); Debian's
  # libtinygltf.so is a Linux library.
  cat >"$PREFIX/lib/cmake/TinyGLTF/TinyGLTFConfig.cmake" <<'EOF'
# Written by scripts/windows-deps.sh: TinyGLTF header (libtinygltf-dev) for
# x86_64-w64-mingw32; link nothing, compile TINYGLTF_IMPLEMENTATION yourself.
get_filename_component(_tinygltf_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET TinyGLTF::TinyGLTF)
  add_library(TinyGLTF::TinyGLTF INTERFACE IMPORTED)
  set_target_properties(TinyGLTF::TinyGLTF PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${_tinygltf_prefix}/include")
endif()
unset(_tinygltf_prefix)
set(TinyGLTF_FOUND TRUE)
EOF
  staged="$staged TinyGLTF(header)"
fi
step "header-only packages staged in $PREFIX/include:${staged:- none}"
step "done; configure with -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake -DSMPL_WIN_DEPS_PREFIX=$PREFIX"
