#!/usr/bin/env bash
# Build the libFuzzer targets with clang and run each for SECONDS (default 30)
# on the seed corpus plus generated fixtures. Any crash, leak or sanitizer
# report fails the run.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSMPL_FUZZ=ON \
  -DSMPL_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j"$(nproc)"
for exe in build-fuzz/tests/fuzz/*_fuzz; do
  name=$(basename "$exe" _fuzz)
  corpus=build-fuzz/corpus/$name
  mkdir -p "$corpus"
  seeds=()
  [ -d "tests/fuzz/seeds/$name" ] && seeds+=("tests/fuzz/seeds/$name")
  echo "fuzz $name: ${seconds}s"
  "$exe" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    "$corpus" "${seeds[@]}" 2>"build-fuzz/$name.log" || { tail -40 "build-fuzz/$name.log"; exit 1; }
  grep -E "stat::number_of_executed_units" "build-fuzz/$name.log" || true
done
echo "fuzz: no findings"
