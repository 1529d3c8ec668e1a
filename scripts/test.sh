#!/usr/bin/env bash
# The whole test suite, from a fresh Debian machine: install dependencies,
# build with AddressSanitizer + UBSan, run each libFuzzer target briefly, then
# every CTest test (unit, CLI, headless-Blender round trips, glTF validator,
# C#); ctest's summary is the last thing printed. Exit status is non-zero if
# anything fails.
#   scripts/test.sh [--no-fuzz]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

scripts/setup-deps.sh
(cd tests/validator && npm ci --no-audit --no-fund --loglevel=error)
# three.js, puppeteer-core (drives Debian's chromium; downloads no browser): tests/web
(cd web && npm ci --no-audit --no-fund --loglevel=error)

# ccache (a test dependency) makes rebuilds of an unchanged tree nearly free.
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# The quick-start build (Release, no tests): the reliability suite runs this
# product binary (peak memory, address-space limits); everything else runs the
# sanitized build.
cmake -S . -B build -DSMPL_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build build -j"$jobs"
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSMPL_SANITIZE=ON "${launcher[@]}" \
  -DSMPL_RELIABILITY_EXE="$PWD/build/cli/smpl-export" >/dev/null
cmake --build build-test -j"$jobs"
# Blender embeds its own allocator; sanitizers stay in our binaries only.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

if [[ "${1:-}" != "--no-fuzz" ]]; then
  scripts/fuzz.sh 30
fi
(cd build-test && ctest --output-on-failure -j"$jobs" --timeout 900)
