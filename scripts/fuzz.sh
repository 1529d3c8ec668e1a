#!/usr/bin/env bash
# Build the libFuzzer targets with clang and run each for SECONDS (default 30)
# on the seed corpus plus generated fixtures, as many at once as there are
# cores (each fuzzer still gets SECONDS of one core). Any crash, leak or sanitizer
# report fails the run. BUILD_DIR: an existing -DSMPL_FUZZ=ON build whose fuzz
# targets are already built (scripts/test.sh passes its sanitizer build);
# default: configure and build build-fuzz.
#   scripts/fuzz.sh [SECONDS [BUILD_DIR]]
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
build=${2:-}
jobs=$(nproc)
if [ -z "$build" ]; then
  build=build-fuzz
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSMPL_FUZZ=ON \
    -DSMPL_BUILD_TESTS=OFF "${launcher[@]}" >/dev/null
  cmake --build "$build" -j"$jobs" --target fuzzers
fi
ls "$build"/tests/fuzz/*_fuzz >/dev/null || { echo "fuzz: no fuzz targets in $build/tests/fuzz"; exit 1; }
# One fuzzer per core at a time: each still gets SECONDS of one core.
fuzz_one() {
  local exe=$1 name corpus seeds=()
  name=$(basename "$exe" _fuzz)
  corpus=$build/corpus/$name
  mkdir -p "$corpus"
  [ -d "tests/fuzz/seeds/$name" ] && seeds+=("tests/fuzz/seeds/$name")
  if ! "$exe" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
      "$corpus" "${seeds[@]}" 2>"$build/$name.log"; then
    echo "fuzz $name: FAILED"; tail -40 "$build/$name.log"; touch "$build/$name.failed"; return 1
  fi
  echo "fuzz $name: ${seconds}s, $(grep -E "stat::number_of_executed_units" "$build/$name.log" || true)"
}
rm -f "$build"/*.failed
for exe in "$build"/tests/fuzz/*_fuzz; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  fuzz_one "$exe" &
done
wait
if ls "$build"/*.failed >/dev/null 2>&1; then exit 1; fi
echo "fuzz: no findings"
