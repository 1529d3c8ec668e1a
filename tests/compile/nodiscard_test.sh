#!/usr/bin/env bash
# A dropped Status or Result is a compile error in this project's flags
# (core/result.h [[nodiscard]] + -Werror=unused-result, CMakeLists.txt): the
# snippet must fail to compile, naming both calls, and compile with (void).
#   nodiscard_test.sh CXX SOURCE_DIR
set -uo pipefail
cxx=$1 src=$2
flags=(-std=c++17 -fsyntax-only -Wall -Wextra -Werror=unused-result -I"$src")
if ! "$cxx" "${flags[@]}" -DSMPL_CAST_TO_VOID "$src/tests/compile/dropped_result.cpp"; then
  echo "FAIL: the (void)-cast snippet does not compile"
  exit 1
fi
out=$("$cxx" "${flags[@]}" "$src/tests/compile/dropped_result.cpp" 2>&1) && {
  echo "FAIL: dropping a Status and a Result compiled without an error"
  exit 1
}
n=$(grep -c "error:.*\(nodiscard\|unused-result\|warn_unused_result\)" <<<"$out")
if [[ $n -ne 2 ]]; then
  echo "FAIL: expected 2 unused-result errors, got $n:"
  echo "$out"
  exit 1
fi
echo "ok: dropped Status and Result are compile errors (2), (void) casts compile"
