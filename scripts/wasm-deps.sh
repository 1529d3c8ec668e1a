#!/usr/bin/env bash
# Builds the WebAssembly (emscripten) libraries smpl-export needs from
# Debian's source packages (Debian ships none of them for wasm32), into
# PREFIX, with Debian's emscripten:
#   zlib           PREFIX/lib/libz.a, include/zlib.h, zconf.h
#   libdeflate     PREFIX/lib/libdeflate.a, include/libdeflate.h, lib/pkgconfig/libdeflate.pc
#   libmd          PREFIX/lib/libmd.a, include/sha2.h (SHA-256: core/io/sha256_digest_libmd.cpp)
#   meshoptimizer  PREFIX/lib/libmeshoptimizer.a, include/meshoptimizer.h
#   musl's libm    PREFIX/lib/libsmpl_m.a (scripts/portable-libm.sh --target wasm)
# and stages Debian's header-only packages (Eigen, nlohmann-json, TinyGLTF)
# under PREFIX/include with their CMake package files, as windows-deps.sh does.
# Nothing of theirs is committed. Idempotent: a library whose stamp names the
# Debian source version apt offers now is not rebuilt.
#   scripts/wasm-deps.sh PREFIX     (Debian packages: scripts/setup-deps.sh --wasm)
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
[[ $# -eq 1 ]] || { echo "usage: $0 PREFIX" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$1"
PREFIX=$(cd "$1" && pwd)
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}  # emcc's acorn (Debian's node-acorn)
step() { echo "wasm-deps: $*"; }
die() { echo "wasm-deps: error: $*" >&2; exit 1; }
for tool in emcc em++ emar dpkg-source apt-get; do
  command -v "$tool" >/dev/null || die "$tool not found (Debian packages: emscripten dpkg-dev)"
done
# shellcheck source=scripts/debian-source.sh
source "$here/debian-source.sh"
debsrc_init "$PREFIX/.src"
stamps=$PREFIX/share/smpl-wasm-deps
mkdir -p "$stamps" "$PREFIX/lib/pkgconfig" "$PREFIX/include"
step "emcc $(emcc --version | head -n1 | awk '{print $(NF-1)}'), prefix $PREFIX"

# build NAME LIBRARY BUILD-FUNCTION: fetch the source and run the function in it, unless stamped
build() {
  local name=$1 lib=$2 fn=$3 ver
  ver=$(debsrc_version "$name")
  [[ -n $ver ]] || die "apt knows no source package $name"
  if [[ -f $PREFIX/lib/$lib && $(cat "$stamps/$name.version" 2>/dev/null) == "$ver" ]]; then
    step "$name $ver already in $PREFIX/lib/$lib, skipped"
    return
  fi
  local src
  src=$(debsrc_fetch "$name" "$ver") || die "cannot get the source of $name"
  rm -f "$PREFIX/lib/$lib"
  # (set -e does not apply inside a function called from a || list: each step returns 1 itself)
  (cd "$src" && "$fn") >"$PREFIX/.src/$name-build.log" 2>&1 && [[ -f $PREFIX/lib/$lib ]] ||
    die "$name build failed ($PREFIX/.src/$name-build.log)"
  echo "$ver" >"$stamps/$name.version"
  step "$name $ver: installed $PREFIX/lib/$lib"
}

zlib_build() {
  local objs=()
  for c in adler32 compress crc32 deflate gzclose gzlib gzread gzwrite infback inffast inflate \
    inftrees trees uncompr zutil; do
    emcc -O2 -include unistd.h -c "$c.c" -o "$c.o" || return 1  # unistd.h: what ./configure finds
    objs+=("$c.o")
  done
  rm -f "$PREFIX/lib/libz.a" && emar rcs "$PREFIX/lib/libz.a" "${objs[@]}"
  install -m644 zlib.h zconf.h "$PREFIX/include/"
}

libdeflate_build() {
  make -j2 CC=emcc AR=emar DISABLE_SHARED=1 libdeflate.a || return 1
  install -m644 libdeflate.a "$PREFIX/lib/libdeflate.a"
  install -m644 libdeflate.h "$PREFIX/include/libdeflate.h"
  cat >"$PREFIX/lib/pkgconfig/libdeflate.pc" <<PC
prefix=$PREFIX
includedir=\${prefix}/include
libdir=\${prefix}/lib

Name: libdeflate
Description: libdeflate (static, wasm32-emscripten)
Version: 1.14
Libs: -L\${libdir} -ldeflate
Cflags: -I\${includedir}
PC
}

# libmd's SHA-2 only (src/sha2.c; its configure-made config.h is not needed).
libmd_build() {
  mkdir -p cfg && : >cfg/config.h
  emcc -O2 -Icfg -Iinclude -c src/sha2.c -o sha2.o || return 1
  rm -f "$PREFIX/lib/libmd.a" && emar rcs "$PREFIX/lib/libmd.a" sha2.o
  install -m644 include/sha2.h "$PREFIX/include/sha2.h"
}

meshoptimizer_build() {
  local objs=()
  for c in src/*.cpp; do
    em++ -O2 -c "$c" -o "${c%.cpp}.o" || return 1
    objs+=("${c%.cpp}.o")
  done
  rm -f "$PREFIX/lib/libmeshoptimizer.a" && emar rcs "$PREFIX/lib/libmeshoptimizer.a" "${objs[@]}"
  install -m644 src/meshoptimizer.h "$PREFIX/include/meshoptimizer.h"
}

build zlib libz.a zlib_build
build libdeflate libdeflate.a libdeflate_build
build libmd libmd.a libmd_build
build meshoptimizer libmeshoptimizer.a meshoptimizer_build
"$here/portable-libm.sh" --target wasm "$PREFIX"

# Header-only Debian packages: symlinks plus their CMake package files.
mkdir -p "$PREFIX/share/eigen3/cmake" "$PREFIX/share/cmake/nlohmann_json"
ln -sfn /usr/include/eigen3 "$PREFIX/include/eigen3"
cp -f /usr/share/eigen3/cmake/*.cmake "$PREFIX/share/eigen3/cmake/"
ln -sfn /usr/include/nlohmann "$PREFIX/include/nlohmann"
cp -f /usr/share/cmake/nlohmann_json/*.cmake "$PREFIX/share/cmake/nlohmann_json/"
ln -sfn /usr/include/tiny_gltf.h "$PREFIX/include/tiny_gltf.h"
mkdir -p "$PREFIX/lib/cmake/TinyGLTF" "$PREFIX/lib/cmake/meshoptimizer"
cat >"$PREFIX/lib/cmake/TinyGLTF/TinyGLTFConfig.cmake" <<'CM'
# Written by scripts/wasm-deps.sh: the TinyGLTF header (libtinygltf-dev); the
# project compiles its implementation (writers/gltf/static/tinygltf_impl.cpp).
get_filename_component(_p "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET TinyGLTF::TinyGLTF)
  add_library(TinyGLTF::TinyGLTF INTERFACE IMPORTED)
  set_target_properties(TinyGLTF::TinyGLTF PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_p}/include")
endif()
set(TinyGLTF_FOUND TRUE)
CM
cat >"$PREFIX/lib/cmake/meshoptimizer/meshoptimizerConfig.cmake" <<'CM'
# Written by scripts/wasm-deps.sh: static meshoptimizer for wasm32-emscripten.
get_filename_component(_p "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET meshoptimizer::meshoptimizer)
  add_library(meshoptimizer::meshoptimizer STATIC IMPORTED)
  set_target_properties(meshoptimizer::meshoptimizer PROPERTIES
    IMPORTED_LOCATION "${_p}/lib/libmeshoptimizer.a" INTERFACE_INCLUDE_DIRECTORIES "${_p}/include")
endif()
set(meshoptimizer_FOUND TRUE)
CM
step "header-only packages staged in $PREFIX/include: eigen3 nlohmann_json tiny_gltf.h"
