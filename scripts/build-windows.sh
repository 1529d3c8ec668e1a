#!/usr/bin/env bash
# smpl-export.exe for Windows x86_64, cross-compiled with Debian's mingw-w64
# (POSIX thread model) into build-windows/cli/smpl-export.exe: one static
# executable that needs only Windows' own DLLs. The libraries Debian does not
# ship for mingw-w64 (libdeflate, meshoptimizer) are built from Debian's
# source packages first (scripts/windows-deps.sh, into build-windows-deps/;
# nothing of theirs is committed). Draco is off in this build (--draco is
# refused). ccache, when present, caches every compile.
#   scripts/build-windows.sh            (Debian packages: scripts/setup-deps.sh --windows)
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
cd "$(dirname "$0")/.."
deps=$PWD/build-windows-deps
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
scripts/windows-deps.sh --meshopt "$deps"
cmake -S . -B build-windows -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/mingw-w64-x86_64.cmake" \
  -DSMPL_WIN_DEPS_PREFIX="$deps" -DCMAKE_BUILD_TYPE=Release -DSMPL_BUILD_TESTS=OFF \
  "${launcher[@]}" >"$deps/configure.log" 2>&1 || {
  tail -20 "$deps/configure.log" >&2
  echo "build-windows.sh: configure failed ($deps/configure.log)" >&2
  exit 1
}
cmake --build build-windows -j"$(nproc)" --target smpl-export
echo "build-windows.sh: $(ls -l build-windows/cli/smpl-export.exe | awk '{print $5}') bytes, build-windows/cli/smpl-export.exe"
