#!/bin/sh
# samples/run.py must fail when a README example breaks: a copy of the README
# whose first example has a misspelt option (--betas -> --betaz) must make it
# exit 1 and name that example; the unmodified examples still pass.
# usage: readme_samples_breakage_test.sh PYTHON SOURCE_DIR SMPL_EXPORT FIXTURES
set -u
python=$1 src=$2 exe=$3 fixtures=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed 's/^    smpl-export --model SMPL_NEUTRAL.npz --betas /    smpl-export --model SMPL_NEUTRAL.npz --betaz /' \
  "$src/README.md" > "$work/README.md"
grep -q -- '--betaz' "$work/README.md" || { echo "FAIL: the README's first example changed; update this test"; exit 1; }
"$python" "$src/samples/run.py" --exe "$exe" --fixtures "$fixtures" --readme "$work/README.md" \
  --work "$work/run" > "$work/out.txt" 2>&1
rc=$?
cat "$work/out.txt"
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 for a broken README example, got $rc"; exit 1; }
grep -q '^FAIL smpl-export --model SMPL_NEUTRAL.npz --betaz' "$work/out.txt" || { echo "FAIL: the broken example is not named"; exit 1; }
grep -q ' 1 failed$' "$work/out.txt" || { echo "FAIL: expected exactly one failure"; exit 1; }
echo "ok: a misspelt option in a README example fails samples/run.py"
