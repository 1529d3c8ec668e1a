#!/usr/bin/env bash
# What goes where (docs/cli.md "Outputs"): the summary on stdout; notes and
# warnings on stderr; --quiet hides the notes and the summary but keeps the
# warnings; batch mode prints "[k/N] <output>: ..." per finished file (with
# "ETA" only on a terminal) and a note every motion repeats once, with its
# count; on a terminal a single export draws a "baking NAME [...] ETA" bar.
# Usage: output_streams_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

check() {  # name, status (saved before the name is expanded)
  if [ "$2" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi
}
out=$work/stdout err=$work/stderr

# 1. A note (no frame rate stored): on stderr, not stdout; -q hides it and the summary.
"$exe" --model builtin --motion "$fixtures/formats/no_fps.npz" --out "$work/a.glb" >"$out" 2>"$err"
st=$?; check "export with a note: $(cat "$err")" $st
grep -q "^note: no_fps: no frame rate is stored" "$err"; st=$?; check "note on stderr: $(cat "$err")" $st
! grep -q "note:" "$out"; st=$?; check "no note on stdout: $(cat "$out")" $st
grep -q "^$work/a.glb: .* vertices, " "$out"; st=$?; check "summary on stdout: $(cat "$out")" $st
"$exe" --model builtin --motion "$fixtures/formats/no_fps.npz" --out "$work/a.glb" -q >"$out" 2>"$err"
st=$?; check "-q export" $st
[ ! -s "$out" ] && [ ! -s "$err" ]; st=$?; check "-q: nothing printed: $(cat "$out" "$err")" $st

# 2. A warning (a model folder without the motion's gender: the neutral model is used):
#    on stderr, and kept by -q.
mkdir -p "$work/models"
cp "$fixtures/released/smpl_folder/SMPL_NEUTRAL.npz" "$work/models/"
"$exe" --model "$work/models" --motion "$fixtures/released/mixed_gender/f_walk.npz" --out "$work/w.glb" -q >"$out" 2>"$err"
st=$?; check "folder fallback export: $(cat "$err")" $st
grep -q "^warning: no female SMPL model in $work/models; using SMPL_NEUTRAL.npz" "$err"; st=$?
check "-q keeps the warning: $(cat "$err")" $st
[ ! -s "$out" ]; st=$?; check "-q: no summary: $(cat "$out")" $st

# 3. Batch: [k/N] per file; the DMPL hint of three motions folded into one line with its count.
mkdir -p "$work/motions"
for name in walk_a walk_b walk_c; do cp "$fixtures/dmpl/amass_smplh_dmpl.npz" "$work/motions/$name.npz"; done
"$exe" --model builtin --motion-dir "$work/motions" --out-dir "$work/batch" --threads 2 >"$out" 2>"$err"
st=$?; check "batch: $(cat "$err")" $st
for k in 1 2 3; do
  grep -q "^\[$k/3\] $work/batch/walk_[abc].glb: 90 frames, " "$out"; st=$?; check "batch line [$k/3]: $(cat "$out")" $st
done
! grep -q "ETA" "$out"; st=$?; check "no ETA when stdout is not a terminal" $st
[ "$(grep -c "DMPL soft-tissue" "$err")" = 1 ]; st=$?; check "one DMPL hint line: $(cat "$err")" $st
grep -q "^note: the motion has DMPL soft-tissue coefficients .* (3 motions)$" "$err"; st=$?
check "folded hint with its count: $(cat "$err")" $st
grep -qx "batch: 3 converted, 0 up to date, 0 failed, 0 skipped (no pose data)" "$out"; st=$?; check "batch totals" $st
"$exe" --model builtin --motion-dir "$work/motions" --out-dir "$work/batch" -q >"$out" 2>"$err"
[ "$(grep -c '^\[' "$out")" = 0 ]; st=$?; check "-q: no per-file lines: $(cat "$out")" $st
! grep -q "note:" "$err"; st=$?; check "-q: no notes in batch: $(cat "$err")" $st

# 4. On a terminal (script(1) gives the run one): batch lines carry the time left, a single
#    export draws its bar with the phase.
if command -v script >/dev/null; then
  script -qec "'$exe' --model builtin --motion-dir '$work/motions' --out-dir '$work/batch_tty' --threads 1" /dev/null >"$out" 2>&1
  grep -q "^\[1/3, ETA [0-9]*:[0-9][0-9]\] " "$out"; st=$?; check "ETA on a terminal: $(cat "$out")" $st
  grep -q "^\[3/3\] " "$out"; st=$?; check "no ETA on the last file: $(cat "$out")" $st
  script -qec "'$exe' --model builtin --motion '$work/motions/walk_a.npz' --out '$work/tty.glb'" /dev/null >"$out" 2>&1
  grep -q "baking walk_a .*\] 100%" "$out"; st=$?; check "progress bar with its phase: $(cat -v "$out")" $st
else
  check "script(1) (bsdutils) is not installed" 1
fi

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
