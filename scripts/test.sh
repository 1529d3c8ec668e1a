#!/usr/bin/env bash
# The whole test suite, from a fresh Debian machine: install dependencies,
# build with AddressSanitizer + UBSan, run each libFuzzer target briefly, then
# every CTest test (unit, CLI, headless-Blender round trips, glTF validator,
# C#); ctest's summary and then the wall time of each phase are the last
# things printed. Exit status is non-zero if anything fails.
#   scripts/test.sh [--no-fuzz]
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
# The quick-start build (Release, no tests): the reliability suite runs this
# product binary (peak memory, address-space limits); everything else runs the
# sanitized build.
# Only the binary is needed from it (the add-on zip and the tools come from build-test).
cmake -S . -B build -DSMPL_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
phase "release build (smpl-export)" cmake --build build -j"$jobs" --target smpl-export
# -O1 -g1 (AddressSanitizer's recommended level, line tables for its stack
# traces) instead of RelWithDebInfo's -O2 -g: under ASan/UBSan a translation
# unit compiles in about half the CPU time (g++ user time: exporter/animation.cpp
# 20.8 s -> 9.1 s, tests/unit/gltf_writer_test.cpp 70.2 s -> 34.8 s), and this
# build is most of the suite.
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DSMPL_SANITIZE=ON "${launcher[@]}" -DSMPL_RELIABILITY_EXE="$PWD/build/cli/smpl-export" >/dev/null
phase "sanitizer build (all)" cmake --build build-test -j"$jobs"
# Blender embeds its own allocator; sanitizers stay in our binaries only.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

if [[ "${1:-}" != "--no-fuzz" ]]; then
  phase "fuzz (build + 30 s each)" scripts/fuzz.sh 30
fi
status=0
phase ctest bash -c 'cd build-test && ctest --output-on-failure -j"$0" --timeout 900' "$jobs" || status=$?
report_times
exit $status
