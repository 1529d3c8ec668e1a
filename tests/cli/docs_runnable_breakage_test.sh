#!/bin/sh
# samples/run.py runs the docs pages' commands too: a copy of docs/ whose
# runnable block (`<!-- runnable -->` before a fence, docs/getting-started.md)
# has a misspelt option must make it exit 1 and name that command; every
# other example still passes.
# usage: docs_runnable_breakage_test.sh PYTHON SOURCE_DIR SMPL_EXPORT FIXTURES
set -u
python=$1 src=$2 exe=$3 fixtures=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$src/docs" "$work/docs"
sed -i 's/^smpl-export --model builtin --out demo.glb$/smpl-export --model builtin --outz demo.glb/' \
  "$work/docs/getting-started.md"
grep -q -- '--outz' "$work/docs/getting-started.md" || { echo "FAIL: the runnable block of docs/getting-started.md changed; update this test"; exit 1; }
"$python" "$src/samples/run.py" --exe "$exe" --fixtures "$fixtures" --docs "$work/docs" \
  --work "$work/run" > "$work/out.txt" 2>&1
rc=$?
cat "$work/out.txt"
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 for a broken runnable docs command, got $rc"; exit 1; }
grep -q '^FAIL smpl-export --model builtin --outz demo.glb' "$work/out.txt" || { echo "FAIL: the broken command is not named"; exit 1; }
grep -q ' 1 failed$' "$work/out.txt" || { echo "FAIL: expected exactly one failure"; exit 1; }
echo "ok: a misspelt option in a runnable docs block fails samples/run.py"
