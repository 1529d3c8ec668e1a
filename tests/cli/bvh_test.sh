#!/usr/bin/env bash
# BVH output from the command line: a motion and the rest pose export (the
# file's frame count and time, units, deterministic bytes, the sidecar, batch
# mode), and everything that makes no sense for a skeleton-only format is
# refused with one line, exit 1 and no output.
# Usage: bvh_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
motion=$fixtures/motions/smpl_72.npz  # 60 frames at 30 fps, SMPL (24 joints)

check() {  # name, condition result (callers pass $? first)
  if [ "$2" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi
}

expect_failure() {  # name, expected stderr text, args... (exit 1, one line, no output)
  local name=$1 text=$2; shift 2
  rm -rf "$work"/out.* "$work/batch"
  "$exe" "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" = 1 ]; check "$name: exit $got, expected 1" $?
  grep -qF -- "$text" "$work/stderr"; check "$name: stderr lacks '$text': $(cat "$work/stderr")" $?
  [ "$(wc -l <"$work/stderr")" = 1 ]; check "$name: error is not one line" $?
  local left
  left=$(ls "$work" | grep -E '^out\.|^batch$' || true)
  [ -z "$left" ]; check "$name: left output $left" $?
}

value_of() {  # file, line prefix: the rest of the first line that starts with it
  grep -m1 "^$2" "$1" | sed "s/^$2//"
}

# A motion: one frame line per baked frame, the frame time from the rate.
"$exe" --model builtin --motion "$motion" --out "$work/walk.bvh" >"$work/summary" 2>&1
check "export walk.bvh: $(cat "$work/summary")" $?
[ "$(head -1 "$work/walk.bvh")" = HIERARCHY ]; check "walk.bvh starts with HIERARCHY" $?
[ "$(value_of "$work/walk.bvh" "Frames: ")" = 60 ]; check "walk.bvh: 60 frames" $?
[ "$(value_of "$work/walk.bvh" "Frame Time: ")" = 0.0333333333 ]; check "walk.bvh: 1/30 s" $?
after=$(sed -n '/^Frame Time:/,$p' "$work/walk.bvh" | tail -n +2 | wc -l)
[ "$after" = 60 ]; check "walk.bvh: $after frame lines, expected 60" $?
values=$(sed -n '/^Frame Time:/{n;p;q}' "$work/walk.bvh" | wc -w)
[ "$values" = $((6 + 23 * 3)) ]; check "walk.bvh: $values values a frame, expected 75" $?
[ "$(grep -c "^[[:space:]]*JOINT " "$work/walk.bvh")" = 23 ]; check "walk.bvh: 23 JOINTs" $?
grep -q "^ROOT pelvis$" "$work/walk.bvh"; check "walk.bvh: ROOT pelvis" $?
grep -q "JOINT left_hip$" "$work/walk.bvh" && grep -q "JOINT right_hand$" "$work/walk.bvh"
check "walk.bvh: the authors' joint names" $?
grep -q "walk.bvh: 24 joints, skeleton only, " "$work/summary"; check "summary: skeleton only" $?
grep -q "walk.bvh: 24 joints, skeleton only, " "$work/summary"; check "summary: skeleton only" $?
grep -q "animation: 60 frames" "$work/summary"; check "summary: animation line" $?
! grep -q "skinning error\|morph targets" "$work/summary"; check "summary: no skin or morph lines" $?
[ -s "$work/walk.bvh.smpl.json" ]; check "sidecar written" $?
"$exe" --model builtin --motion "$motion" --out "$work/again.bvh" -q
cmp -s "$work/walk.bvh" "$work/again.bvh"; check "BVH output is deterministic" $?

# --fps: 30 -> 10 fps keeps every third frame; --bvh-units cm: offsets x 100.
"$exe" --model builtin --motion "$motion" --fps 10 --bvh-units cm --out "$work/cm.bvh" -q
check "export --fps 10 --bvh-units cm" $?
[ "$(value_of "$work/cm.bvh" "Frames: ")" = 20 ]; check "--fps 10: 20 frames" $?
[ "$(value_of "$work/cm.bvh" "Frame Time: ")" = 0.1000000000 ]; check "--fps 10: 0.1 s" $?
paste <(grep OFFSET "$work/walk.bvh") <(grep OFFSET "$work/cm.bvh") | awk '
  { for (i = 2; i <= 4; ++i) if ((d = $(i + 4) - 100 * $i) > 1e-5 || d < -1e-5) bad = 1; n++ }
  END { exit bad || n < 24 }'
check "--bvh-units cm: every OFFSET is 100 x the metre one" $?

# No motion: one frame, the rest pose (the T-pose), at 30 fps.
"$exe" --model builtin --out "$work/rest.bvh" -q; check "export rest.bvh" $?
[ "$(value_of "$work/rest.bvh" "Frames: ")" = 1 ]; check "rest.bvh: 1 frame" $?
[ "$(value_of "$work/rest.bvh" "Frame Time: ")" = 0.0333333333 ]; check "rest.bvh: 1/30 s" $?
rest=$(tail -1 "$work/rest.bvh" | tr ' ' '\n' | tail -n +4 | sort -u)
[ "$rest" = 0.000000 ]; check "rest.bvh: every rotation 0 ($rest)" $?

# Batch mode writes <stem>.bvh.
mkdir -p "$work/in" && cp "$motion" "$work/in/"
"$exe" --model builtin --motion-dir "$work/in" --out-dir "$work/baked" --format bvh -q
check "batch --format bvh" $?
cmp -s "$work/baked/smpl_72.bvh" "$work/walk.bvh"; check "batch output equals the single export" $?

# Refused: mesh options, other formats' options, a second motion.
m=(--model builtin --motion "$motion" --out "$work/out.bvh")
for option in "--max-influences 8" "--skin-weights truncated" "--correctives none" \
  "--corrective-weights split" "--corrective-basis 4" "--shape-keys 2" "--expression-keys 2" \
  "--uv none" "--name body" "--dmpl d.npz" "--dmpl-count 2" "--dmpl-joints regressed"; do
  # shellcheck disable=SC2086  # option and value as two words
  expect_failure "bvh $option" "${option%% *} needs an output format with a mesh; bvh output has none" \
    "${m[@]}" $option
done
expect_failure "bvh --draco" "--draco applies only to .glb, .gltf output" "${m[@]}" --draco
expect_failure "bvh --quantize-morphs" "--quantize-morphs applies only to .glb, .gltf output" "${m[@]}" --quantize-morphs
expect_failure "bvh --corrective-epsilon" "--corrective-epsilon applies only to .glb, .gltf output" "${m[@]}" --corrective-epsilon 0.001
expect_failure "bvh --fbx-units" "--fbx-units applies only to .fbx output" "${m[@]}" --fbx-units cm
expect_failure "glb --bvh-units" "--bvh-units applies only to .bvh output" --model builtin --out "$work/out.glb" --bvh-units cm
expect_failure "bvh --bvh-units in" "--bvh-units: expected 'm' or 'cm', got 'in'" "${m[@]}" --bvh-units in
expect_failure "bvh two motions" "--motion: bvh output holds one motion; got 2 (one output per motion: --motion-dir)" \
  "${m[@]}" --motion "$motion"
expect_failure "batch bvh --max-influences" "--max-influences needs an output format with a mesh; bvh output has none" \
  --model builtin --motion-dir "$work/in" --out-dir "$work/batch" --format bvh --max-influences 8

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
