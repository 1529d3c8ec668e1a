#!/bin/sh
# samples/run.py runs the docs pages' commands too. On docs/getting-started.md
# alone (and an empty README, so that the run is short), its runnable block
# (`<!-- runnable -->` before a fence) passes as it is and, with a misspelt
# option, makes samples/run.py exit 1 naming that command.
# usage: docs_runnable_breakage_test.sh PYTHON SOURCE_DIR SMPL_EXPORT FIXTURES
set -u
python=$1 src=$2 exe=$3 fixtures=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/docs" "$work/clean" && : >"$work/README.md"
cp "$src/docs/getting-started.md" "$work/clean/"
"$python" "$src/samples/run.py" --exe "$exe" --fixtures "$fixtures" --readme "$work/README.md" --docs "$work/clean" \
  --min-examples 1 --work "$work/run" > "$work/clean.txt" 2>&1 ||
  { cat "$work/clean.txt"; echo "FAIL: the unmodified runnable block does not pass"; exit 1; }
grep -q '^ok   smpl-export --model builtin --out demo.glb' "$work/clean.txt" || { cat "$work/clean.txt"; echo "FAIL: the runnable block was not run"; exit 1; }
cp "$src/docs/getting-started.md" "$work/docs/"
sed -i 's/^smpl-export --model builtin --out demo.glb$/smpl-export --model builtin --outz demo.glb/' \
  "$work/docs/getting-started.md"
grep -q -- '--outz' "$work/docs/getting-started.md" || { echo "FAIL: the runnable block of docs/getting-started.md changed; update this test"; exit 1; }
"$python" "$src/samples/run.py" --exe "$exe" --fixtures "$fixtures" --readme "$work/README.md" --docs "$work/docs" \
  --min-examples 1 --work "$work/run" > "$work/out.txt" 2>&1
rc=$?
cat "$work/out.txt"
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 for a broken runnable docs command, got $rc"; exit 1; }
grep -q '^FAIL smpl-export --model builtin --outz demo.glb' "$work/out.txt" || { echo "FAIL: the broken command is not named"; exit 1; }
grep -q ' 1 failed$' "$work/out.txt" || { echo "FAIL: expected exactly one failure"; exit 1; }
echo "ok: a misspelt option in a runnable docs block fails samples/run.py"
