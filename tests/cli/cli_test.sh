#!/usr/bin/env bash
# CLI behaviour: failures print one "Error ..." line naming the file, exit
# non-zero and leave no output; successes are deterministic.
# Usage: cli_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

check() {  # name, condition result (callers pass $? first: expansions in the name would reset it)
  if [ "$2" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi
}

expect_failure() {  # name, expected code, expected stderr text, args...
  local name=$1 code=$2 text=$3; shift 3
  rm -f "$work"/out.*
  "$exe" "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" = "$code" ]; check "$name: exit $got, expected $code" $?
  local err
  err=$(cat "$work/stderr")
  grep -qF -- "$text" "$work/stderr"; check "$name: stderr lacks '$text': $err" $?
  [ "$(wc -l <"$work/stderr")" = 1 ]; check "$name: error is not one line" $?
  local left
  left=$(ls "$work" | grep '^out\.' || true)
  [ -z "$left" ]; check "$name: left output $left" $?
}

models=$fixtures/models
head -c 5000 "$models/smpl_small.npz" >"$work/truncated.npz"
head -c 3000 "$models/smpl_small_p2.pkl" >"$work/truncated.pkl"
# A pickle whose REDUCE would run `touch hostile-ran` if anything executed it.
python3 - "$work" <<'PY'
import os, pickle, sys
class Evil:
    def __reduce__(self):
        return (os.system, ("touch " + os.path.join(sys.argv[1], "hostile-ran"),))
open(os.path.join(sys.argv[1], "hostile.pkl"), "wb").write(pickle.dumps({"v_template": Evil()}, protocol=2))
PY

expect_failure origin-choice 1 "--origin: expected 'model' or 'floor', got 'feet'" --model builtin --out "$work/out.glb" --origin feet
expect_failure root-bone-origin-model 1 "--root-bone conflicts with --origin model" --model builtin --out "$work/out.glb" --root-bone --origin model
expect_failure unknown-option 1 "unknown option '--bogus'" --model builtin --out "$work/out.glb" --bogus 1
expect_failure missing-model 2 "Error loading $work/none.npz" --model "$work/none.npz" --out "$work/out.glb"
expect_failure truncated-npz 2 "truncated.npz" --model "$work/truncated.npz" --out "$work/out.glb"
expect_failure truncated-pkl 2 "truncated.pkl" --model "$work/truncated.pkl" --out "$work/out.glb"
expect_failure hostile-pkl 2 "posix.system" --model "$work/hostile.pkl" --out "$work/out.glb"
expect_failure too-many-betas 1 "Error in arguments: betas: 11 values given" --model "$models/smpl_small.npz" --out "$work/out.glb" --betas 0,0,0,0,0,0,0,0,0,0,1
expect_failure too-many-influences 1 "Error in arguments: --max-influences must be between 1 and 24 (the model's joints) or 'all'" --model "$models/smpl_small.npz" --out "$work/out.glb" --max-influences 25
expect_failure too-many-shape-keys 1 "Error in arguments: --shape-keys 100" --model "$models/smpl_small.npz" --out "$work/out.glb" --shape-keys 100
expect_failure missing-uv 2 "Error loading $work/no_such.obj: cannot open: No such file or directory" --model "$models/smpl_small.npz" --out "$work/out.glb" --uv "$work/no_such.obj"
expect_failure glb-option-in-fbx-batch 1 "--draco applies only to .glb, .gltf output" --model builtin --motion-dir "$work" --out-dir "$work/b" --format fbx --draco
expect_failure meshopt-for-fbx 1 "--meshopt applies only to .glb, .gltf output" --model builtin --out "$work/out.fbx" --meshopt
expect_failure web-preset-for-fbx 1 "--preset web makes glTF files (meshopt, quantised); FBX output has neither" --model builtin --out "$work/out.fbx" --preset web
expect_failure quantize-animation-without-motion 1 "--quantize-animation quantises animation keys; without --motion" --model builtin --out "$work/out.glb" --quantize-animation
expect_failure flag-with-value 1 "option --draco takes no value" --model builtin --out "$work/out.glb" --draco=yes
expect_failure alias-twice 1 "option --quiet given twice" --model builtin --out "$work/out.glb" -q --quiet
expect_failure frames-after-motion 3 "--frames 70:100 is outside the motion's 60 frames" --model builtin --out "$work/out.glb" --motion "$fixtures/motions/smpl_72.npz" --frames 70:100
expect_failure betas-from-motion-without-betas 2 "no betas in the motion (--betas-from-motion)" --model builtin --out "$work/out.glb" --motion "$fixtures/motions/smpl_72.npz" --betas-from-motion
# --frames A:B with B past a motion's end: that motion is baked to its end, with a note.
"$exe" --model builtin --out "$work/clamp.glb" --motion "$fixtures/motions/smpl_72.npz" --frames 10:100 >"$work/stdout" 2>&1
[ $? = 0 ]; check "--frames 10:100 on 60 frames: $(cat "$work/stdout")" $?
grep -q "animation: 50 frames" "$work/stdout"; check "--frames clamp: 50 frames baked" $?
grep -q "note: smpl_72: --frames 10:100 ends after the motion's 60 frames; baked frames 10:60" "$work/stdout"
check "--frames clamp note" $?
# .gltf: the buffer goes to FILE.bin beside it (the JSON names it, with its size); --gltf-embed: one file.
"$exe" --model builtin --out "$work/sep.gltf" -q; check ".gltf export" $?
size=$(stat -c %s "$work/sep.bin" 2>/dev/null)
grep -q "\"byteLength\": $size," "$work/sep.gltf" && grep -q '"uri": "sep.bin"' "$work/sep.gltf"
check ".gltf names sep.bin and its $size bytes" $?
"$exe" --model builtin --out "$work/emb.gltf" --gltf-embed -q; check "--gltf-embed export" $?
[ ! -e "$work/emb.bin" ] && grep -q '"uri": "data:application/octet-stream;base64,' "$work/emb.gltf"
check "--gltf-embed writes one file with a data URI" $?
expect_failure gltf-embed-on-glb 1 "--gltf-embed applies only to .gltf output" --model builtin --out "$work/out.glb" --gltf-embed
expect_failure gltf-bin-unwritable 4 "Error saving" --model builtin --out "$work/no/such/dir/out.gltf"
expect_failure unwritable 4 "Error saving" --model "$models/smpl_small.npz" --out "$work/no/such/dir/out.glb"
[ ! -e "$work/hostile-ran" ]; check "hostile pickle executed something" $?

"$exe" --model "$models/smpl_small.npz" --out "$work/a.glb" --betas 0.5,-1 >"$work/summary" 2>&1
status=$?
check "export smpl_small: $(cat "$work/summary")" $status
grep -q "morph targets" "$work/summary"; check "summary printed" $?
grep -q "skinning error of 4 influences" "$work/summary"; check "pruning error printed" $?
grep -q "optimized mean .* mm, max .* mm with corrective refit; without refit mean .* mm, max .* mm; truncated mean .* mm, max .* mm" "$work/summary"; check "refit, fitted and truncated skin errors printed: $(cat "$work/summary")" $?
expect_failure bad-corrective-refit 1 "--corrective-refit" --model builtin --out "$work/out.glb" --corrective-refit maybe
# --corrective-refit off: the model's posedirs as they are, the summary says nothing of a refit,
# and the file differs from the default (refitted deltas) in its morph deltas only.
"$exe" --model "$models/smpl_small.npz" --out "$work/plain.glb" --betas 0.5,-1 --corrective-refit off >"$work/plain" 2>&1
check "export --corrective-refit off: $(cat "$work/plain")" $?
! grep -q "refit" "$work/plain"; check "--corrective-refit off: no refit in the summary" $?
! cmp -s "$work/a.glb" "$work/plain.glb"; check "--corrective-refit changes the stored deltas" $?
[ -s "$work/a.glb.smpl.json" ]; check "sidecar written" $?
"$exe" --model "$models/smpl_small.npz" --out "$work/b.glb" --betas 0.5,-1 -q
cmp -s "$work/a.glb" "$work/b.glb"; check "GLB output is deterministic" $?
# --origin model is the default: the same bytes as without it (docs/cli.md).
"$exe" --model "$models/smpl_small.npz" --out "$work/c.glb" --betas 0.5,-1 --origin model -q
cmp -s "$work/a.glb" "$work/c.glb"; check "--origin model changed the output" $?
"$exe" --model "$models/smpl_small.npz" --out "$work/d.glb" --origin floor --root-bone >"$work/summary" 2>&1
check "export --root-bone: $(cat "$work/summary")" $?
grep -q "^origin: floor (every position moved +[0-9.]* m in y; root bone 'root' below the pelvis)" "$work/summary"
check "--origin floor summary line: $(cat "$work/summary")" $?
ls "$work" | grep -q tmp; [ $? != 0 ]; check "temporary files left behind" $?

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
