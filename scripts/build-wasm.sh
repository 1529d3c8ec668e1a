#!/usr/bin/env bash
# smpl-export for WebAssembly with Debian's emscripten, into
# build-wasm/cli/smpl-export.js + smpl-export.wasm: run it with node
# (`node build-wasm/cli/smpl-export.js --model builtin --out body.glb`); the
# same options and the same output bytes as the native binary, one thread.
# Also build-wasm/cli/smpl-export-web.mjs + .wasm: the in-memory module behind
# the JS API exportAsset() (web/smpl-export-wasm/index.mjs), for browsers and node.
# The libraries come from Debian's source packages (scripts/wasm-deps.sh,
# into build-wasm-deps/; nothing of theirs is committed). ccache, when
# present, caches the compiles.
#   scripts/build-wasm.sh            (Debian packages: scripts/setup-deps.sh --wasm)
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
cd "$(dirname "$0")/.."
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}  # emcc's acorn (Debian's node-acorn)
deps=$PWD/build-wasm-deps
scripts/wasm-deps.sh "$deps"
cmake -S . -B build-wasm -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/wasm.cmake" -DSMPL_WASM_DEPS_PREFIX="$deps" \
  -DCMAKE_BUILD_TYPE=Release -DSMPL_BUILD_TESTS=OFF >"$deps/configure.log" 2>&1 || {
  tail -20 "$deps/configure.log" >&2
  echo "build-wasm.sh: configure failed ($deps/configure.log)" >&2
  exit 1
}
cmake --build build-wasm -j"$(nproc)" --target smpl-export smpl-export-web
# The npm package folder: web/smpl-export-wasm/ and the two built files.
rm -rf build-wasm/npm && cp -r web/smpl-export-wasm build-wasm/npm
cp build-wasm/cli/smpl-export.js build-wasm/cli/smpl-export.wasm build-wasm/cli/smpl-export-web.mjs \
  build-wasm/cli/smpl-export-web.wasm build-wasm/npm/
echo "build-wasm.sh: $(stat -c %s build-wasm/cli/smpl-export.wasm) bytes, build-wasm/cli/smpl-export.js + .wasm; npm package folder build-wasm/npm"
