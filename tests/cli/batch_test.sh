#!/usr/bin/env bash
# Batch mode: `smpl-export --model builtin --motion-dir D --out-dir O`.
# A bad motion fails alone (one "Error loading" line, exit 3) while the good
# ones convert; a second run skips up-to-date outputs; touching a motion
# reconverts only it; outputs are byte-identical across runs and out dirs;
# motions of one subject fit the skin once, and their outputs equal
# single-file exports byte for byte.
# Usage: batch_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

check() {  # name, status (captured with st=$? before the name expands: a $(...) in it resets $?)
  if [ "$2" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi
}

motions=$work/motions out=$work/out
mkdir -p "$motions"
good="amass_smplh.npz smpl_72.npz plain.json"
for f in $good bad_trans.npz; do cp "$fixtures/motions/$f" "$motions/" || exit 1; done

run() {  # out dir, expected exit, expected summary; leaves stdout/stderr in $work
  "$exe" --model builtin --motion-dir "$motions" --out-dir "$1" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" = "$2" ]; st=$?; check "exit $got, expected $2 ($3)" "$st"
  grep -qxF "$3" "$work/stdout"; st=$?; check "stdout lacks '$3': $(tail -n 1 "$work/stdout")" "$st"
  grep -qF "Error loading $motions/bad_trans.npz: " "$work/stderr"
  st=$?; check "no 'Error loading $motions/bad_trans.npz: ...' line: $(cat "$work/stderr")" "$st"
  [ "$(grep -c '^Error' "$work/stderr")" = 1 ]; st=$?; check "expected exactly one Error line: $(cat "$work/stderr")" "$st"
}

outputs() {  # the files an out dir must hold, sorted
  for f in $good; do echo "${f%.*}.glb" "${f%.*}.glb.smpl.json"; done | tr ' ' '\n' | sort
}

# 1. First run: 3 converted, 1 failed, nothing written for the bad one.
run "$out" 3 "batch: 3 converted, 0 up to date, 1 failed, 0 skipped (no pose data)"
[ "$(ls "$out" | sort)" = "$(outputs)" ]; st=$?; check "outputs: $(ls "$out" | tr '\n' ' ')" "$st"
(cd "$out" && sha256sum $(outputs)) >"$work/first.sha"
# The throughput line of the 3 converted, before the counts; its stage shares sum to 100 (rounded).
line=$(grep '^batch: 3 motions in ' "$work/stdout")
[[ "$line" =~ ^batch:\ 3\ motions\ in\ [0-9.]+\ s\ \([0-9.]+\ motions/s\)\;\ time\ in\ read\ ([0-9]+)%,\ fit\ ([0-9]+)%,\ bake\ ([0-9]+)%,\ write\ ([0-9]+)%$ ]]
st=$?; check "throughput line: '$line'" "$st"
sum=$(( ${BASH_REMATCH[1]:-0} + ${BASH_REMATCH[2]:-0} + ${BASH_REMATCH[3]:-0} + ${BASH_REMATCH[4]:-0} ))
[ "$sum" -ge 98 ] && [ "$sum" -le 102 ]; st=$?; check "stage shares sum to $sum, not 100: '$line'" "$st"
[ "${BASH_REMATCH[4]:-0}" -gt 0 ]; st=$?; check "write share 0: '$line'" "$st"
[ "$(grep -n '^batch: 3 motions in ' "$work/stdout" | cut -d: -f1)" -lt "$(grep -n '^batch: 3 converted' "$work/stdout" | cut -d: -f1)" ]
st=$?; check "the throughput line is not before the counts" "$st"

# 2. Nothing changed: all up to date, the bad one still fails.
run "$out" 3 "batch: 0 converted, 3 up to date, 1 failed, 0 skipped (no pose data)"

# 3. A touched motion is reconverted alone, to the same bytes.
sleep 1
touch "$motions/smpl_72.npz"
run "$out" 3 "batch: 1 converted, 2 up to date, 1 failed, 0 skipped (no pose data)"
[ "$out/smpl_72.glb" -nt "$out/amass_smplh.glb" ]; st=$?; check "smpl_72.glb was not rewritten" "$st"
(cd "$out" && sha256sum -c --quiet "$work/first.sha"); st=$?; check "outputs changed after reconverting" "$st"

# 4. Determinism across out dirs (fresh run, any thread schedule).
run "$work/out2" 3 "batch: 3 converted, 0 up to date, 1 failed, 0 skipped (no pose data)"
(cd "$work/out2" && sha256sum -c --quiet "$work/first.sha"); st=$?; check "a fresh out dir differs from the first" "$st"

# 5. The outputs are real animated GLBs: glTF magic and an "animations" array.
for f in $good; do
  glb=$out/${f%.*}.glb
  [ "$(head -c 4 "$glb")" = "glTF" ]; st=$?; check "$glb: not a GLB" "$st"
  grep -qa '"animations"' "$glb"; st=$?; check "$glb: no animations" "$st"
done

# 6. Motions of one subject (same betas): the skin fit and refit run once and
# are reused; each output equals the single-file export of its motion.
same=$work/same
mkdir -p "$same"
for i in 1 2 3; do cp "$fixtures/motions/smpl_72.npz" "$same/walk$i.npz" || exit 1; done
"$exe" --model builtin --motion-dir "$same" --out-dir "$work/same_out" >"$work/stdout" 2>"$work/stderr"
st=$?; check "batch of one subject: exit $st: $(cat "$work/stderr")" "$st"
line="batch: skin fit computed for 1 subject, reused for 2 motions (same model, betas and skin options)"
grep -qxF "$line" "$work/stdout"; st=$?; check "stdout lacks '$line': $(cat "$work/stdout")" "$st"
for i in 1 3; do
  "$exe" --model builtin --motion "$same/walk$i.npz" --out "$work/single$i.glb" -q; st=$?
  check "single export of walk$i.npz: exit $st" "$st"
  cmp -s "$work/single$i.glb" "$work/same_out/walk$i.glb"; st=$?
  check "batch output walk$i.glb (skin reused) differs from its single-file export" "$st"
done

echo "batch_test: $passed passed, $failed failed"
[ "$failed" = 0 ]
