#!/bin/sh
# Writes the glTF unit tests' outputs to a temporary directory and runs the
# Khronos validator over them. Usage: tests/validator/check_unit_outputs.sh BUILD_DIR
# Exit status: the unit tests' if they fail, else validate.js's.
set -eu
build=${1:?usage: check_unit_outputs.sh BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
[ -d "$here/node_modules/gltf-validator" ] || (cd "$here" && npm ci --silent)
SMPL_GLTF_OUT_DIR="$out" "$build/tests/unit_tests" --gtest_filter='GltfWriter*' --gtest_brief=1
node "$here/validate.js" "$out"/*
