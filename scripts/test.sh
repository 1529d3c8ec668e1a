#!/usr/bin/env bash
# The whole test suite, from a fresh Debian machine: install dependencies,
# build five times (Release for the integration tests; the static release
# binary, from the same objects; the Windows executable, mingw-w64; the
# WebAssembly build, emscripten; clang
# ASan + UBSan for the unit tests and the fuzzers), run each libFuzzer target briefly, then every
# CTest test (unit tests sanitized; CLI, reliability, headless-Blender round
# trips, glTF validator, web, runtimes, C# on the Release binaries); ctest's
# summaries and then the wall time of each phase are the last things printed.
# Exit status is non-zero if anything fails.
#   scripts/test.sh [--no-fuzz]
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

# Each phase's wall time, printed as it ends and again as a table at the end
# (the README's test-time figure comes from this table).
times=()
phase() {  # phase NAME COMMAND...
  local name=$1 start=$SECONDS rc=0
  shift
  "$@" || rc=$?
  times+=("$(printf '%-28s %5d s' "$name" $((SECONDS - start)))")
  echo "== phase $name: $((SECONDS - start)) s"
  return $rc
}
report_times() {
  echo "== test.sh phases (wall time, $(nproc) cores):"
  printf '   %s\n' "${times[@]}"
  echo "   total                        $SECONDS s"
}

phase dependencies scripts/setup-deps.sh
phase "validator (npm ci)" bash -c 'cd tests/validator && npm ci --no-audit --no-fund --loglevel=error'
# three.js, puppeteer-core (drives Debian's chromium; downloads no browser): tests/web
phase "web (npm ci)" bash -c 'cd web && npm ci --no-audit --no-fund --loglevel=error'

# ccache (a test dependency) makes rebuilds of an unchanged tree nearly free.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Five builds, each source file compiled once per build:
#  build-test  Release (the quick start's flags): smpl-export, the tools and the
#              integration tests (CLI, reliability, Blender, validator, web,
#              runtimes, C#, package), which so run the binaries users run.
#  build-windows smpl-export.exe, cross-compiled (scripts/build-windows.sh);
#              the package tests run it under wine against build-test's binary.
#  build-wasm  smpl-export.js + .wasm and smpl-export-web.mjs + .wasm
#              (scripts/build-wasm.sh): the package tests run the CLI and the
#              JS API in node and the viewer's convert panel in Chromium.
#  build-static  the release binary (SMPL_STATIC=ON: no shared library, no
#              loader) and its installed files only; compiled with
#              build-test's flags, so its objects come from ccache. The
#              package tests of build-test run it in an empty chroot and
#              install its .deb.
#  build-san   clang with AddressSanitizer + UBSan and libFuzzer coverage on
#              every library: the unit tests and the fuzz targets share it.
#              -O1 -g1 (ASan's recommended level, line tables for its stack
#              traces); clang compiles this configuration in a third to a half
#              of g++'s CPU time (demo_body_test.cpp: 21 s vs 58 s).
# build-test and build-san use one fixture folder (generated once, by the first build).
# Options given explicitly: a build-test left by an older test.sh (sanitized) is reconfigured.
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=Release -DSMPL_SANITIZE=OFF -DSMPL_FUZZ=OFF \
  -DSMPL_RELIABILITY_EXE= -DSMPL_TEST_SET=integration -DSMPL_STATIC_BUILD_DIR="$PWD/build-static" \
  -DSMPL_WINDOWS_BUILD_DIR="$PWD/build-windows" -DSMPL_WASM_BUILD_DIR="$PWD/build-wasm" \
  "${launcher[@]}" >/dev/null
phase "release build (integration)" cmake --build build-test -j"$jobs"
cmake -S . -B build-static -DCMAKE_BUILD_TYPE=Release -DSMPL_STATIC=ON -DSMPL_BUILD_TESTS=OFF \
  "${launcher[@]}" >/dev/null
phase "static build (release binary)" cmake --build build-static -j"$jobs"
# smpl-export.exe (mingw-w64; libdeflate, meshoptimizer and musl's libm from
# Debian's source packages): package.windows_wine runs it under wine.
phase "windows build (mingw-w64)" scripts/build-windows.sh
# smpl-export.js + .wasm (emscripten; zlib, libdeflate, libmd, meshoptimizer,
# musl's libm from Debian's source packages): package.wasm_node, .wasm_api
# (node) and .wasm_browser (Chromium) run it.
phase "wasm build (emscripten)" scripts/build-wasm.sh
CC=clang CXX=clang++ cmake -S . -B build-san -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DSMPL_FUZZ=ON -DSMPL_TEST_SET=unit \
  -DSMPL_FIXTURE_DIR="$PWD/build-test/fixtures" "${launcher[@]}" >/dev/null
phase "sanitizer build (unit, fuzz)" cmake --build build-san -j"$jobs" --target unit_tests fuzzers
# Blender embeds its own allocator; sanitizers stay in our binaries only.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

if [[ "${1:-}" != "--no-fuzz" ]]; then
  # 20 s per fuzzer on top of the seed corpus: a smoke run (scripts/fuzz.sh SECONDS for longer).
  phase "fuzz (20 s each)" scripts/fuzz.sh 20 build-san
fi
status=0
phase "ctest unit (sanitized)" bash -c 'cd build-san && ctest --output-on-failure -j"$0" --timeout 900' "$jobs" || status=$?
phase "ctest integration" bash -c 'cd build-test && ctest --output-on-failure -j"$0" --timeout 900' "$jobs" || status=$?
report_times
exit $status
