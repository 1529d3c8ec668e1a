#!/usr/bin/env bash
# Motion inputs users have (fixtures: tests/fixtures/make_motion_formats.py):
# an AMASS-like subject folder in batch mode (shape files skipped and named,
# exit 0; a broken motion still fails), the frame-rate note and
# --source-fps, SMPLCodec .smpl, SMPLify-X PCA-hand fits, AIST++, and
# --shard/--manifest (N shards as N processes cover every motion once).
# Usage: motion_formats_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
formats=$fixtures/formats models=$fixtures/models
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

check() {  # status, name: `check $? "name"` ($? comes first: expansions in the name would reset it)
  if [ "$1" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi
}

# 1. AMASS-like subject folder: shape.npz and S1_stagei.npz skipped, named, not failed.
cp -r "$formats/subject" "$work/subject"
"$exe" --model "$models/smplh_small.npz" --motion-dir "$work/subject" --out-dir "$work/out1" >"$work/stdout" 2>"$work/stderr"
status=$?
[ "$status" = 0 ]; check $? "subject folder: exit $status, expected 0: $(cat "$work/stderr")"
for f in shape.npz S1_stagei.npz; do
  grep -qE "^\[[1-4]/4\] $work/subject/$f: skipped, no pose data" "$work/stdout"; check $? "no skip line for $f: $(cat "$work/stdout")"
  [ ! -e "$work/out1/${f%.npz}.glb" ]; check $? "$f produced an output"
done
tail -n 1 "$work/stdout" | grep -qxF "batch: 2 converted, 0 up to date, 0 failed, 2 skipped (no pose data)"
check $? "subject summary: $(tail -n 1 "$work/stdout")"
[ -s "$work/out1/walk_poses.glb" ] && [ -s "$work/out1/run_stageii.glb" ]; check $? "subject motions not converted"
! grep -qv "^note: " "$work/stderr"; check $? "subject folder wrote more than notes to stderr: $(cat "$work/stderr")"

# 2. A file that claims to be a motion and is broken still fails (exit 3).
cp "$formats/broken_poses.npz" "$work/subject/"
"$exe" --model "$models/smplh_small.npz" --motion-dir "$work/subject" --out-dir "$work/out1" >"$work/stdout" 2>"$work/stderr"
status=$?
[ "$status" = 3 ]; check $? "broken motion: exit $status, expected 3"
grep -qF "broken_poses.npz" "$work/stderr"; check $? "broken motion not named: $(cat "$work/stderr")"
tail -n 1 "$work/stdout" | grep -qxF "batch: 0 converted, 2 up to date, 1 failed, 2 skipped (no pose data)"
check $? "broken summary: $(tail -n 1 "$work/stdout")"
rm "$work/subject/broken_poses.npz"

# 3. Frame rate: a note when assumed; --source-fps states it (10 output frames at 12 fps
#    from 20 source frames at 24 fps, 8 at the assumed 30 fps).
"$exe" --model "$models/smpl_small.npz" --motion "$formats/no_fps.npz" --fps 12 --out "$work/nofps.glb" >"$work/stdout" 2>&1
check $? "no-fps export: $(cat "$work/stdout")"
grep -qF "note: no_fps: no frame rate is stored; assumed 30 fps" "$work/stdout"; check $? "no assumed-fps note: $(cat "$work/stdout")"
grep -qxF "animation: 8 frames" "$work/stdout"; check $? "30 fps assumed: $(grep animation "$work/stdout")"
"$exe" --model "$models/smpl_small.npz" --motion "$formats/no_fps.npz" --fps 12 --source-fps 24 --out "$work/nofps24.glb" >"$work/stdout" 2>&1
check $? "--source-fps export: $(cat "$work/stdout")"
grep -q "assumed" "$work/stdout"; [ $? != 0 ]; check $? "assumed note despite --source-fps"
grep -qxF "animation: 10 frames" "$work/stdout"; check $? "--source-fps 24 not used: $(grep animation "$work/stdout")"
"$exe" --model "$models/smpl_small.npz" --motion "$fixtures/motions/amass_smplh.npz" --source-fps 60 --out "$work/over.glb" >"$work/stdout" 2>&1
grep -qF "stored rate 120 fps is overridden by --source-fps 60" "$work/stdout"; check $? "no override note: $(cat "$work/stdout")"
"$exe" --model builtin --motion "$formats/no_fps.npz" --source-fps 0 --out "$work/bad.glb" >/dev/null 2>"$work/stderr"
[ $? = 1 ]; check $? "--source-fps 0 accepted"

# 4. SMPLCodec .smpl (with and without the root), a PCA-hand fit, AIST++.
for motion in codec_root.smpl codec_noroot.smpl fit_pca.pkl fit_full.npz; do
  "$exe" --model "$models/smplx_small.npz" --motion "$formats/$motion" --out "$work/$motion.glb" >"$work/stdout" 2>&1
  check $? "$motion export: $(cat "$work/stdout")"
done
"$exe" --model "$models/smplx_small.npz" --motion "$formats/codec_noroot.smpl" --out "$work/nr.glb" >"$work/stdout" 2>&1
grep -qF "root stays at rest" "$work/stdout"; check $? "no root note for codec_noroot: $(cat "$work/stdout")"
"$exe" --model "$models/smpl_small.npz" --motion "$formats/fit_pca.pkl" --out "$work/fit_smpl.glb" >"$work/stdout" 2>&1
check $? "PCA fit on SMPL: $(cat "$work/stdout")"
grep -qF "hand poses are dropped" "$work/stdout"; check $? "no dropped-hands note: $(cat "$work/stdout")"
/usr/bin/python3 - "$models/smplx_small.npz" "$work/smplx_nohands.npz" <<'PY'
import sys, numpy as np
d = dict(np.load(sys.argv[1]))
for k in ("hands_componentsl", "hands_componentsr", "hands_meanl", "hands_meanr"):
    d.pop(k)
np.savez(sys.argv[2], **d)
PY
"$exe" --model "$work/smplx_nohands.npz" --motion "$formats/fit_pca.pkl" --out "$work/out.glb" >/dev/null 2>"$work/stderr"
status=$?
[ "$status" = 2 ]; check $? "PCA fit without hands_components: exit $status, expected 2"
grep -qF "'hands_componentsl'" "$work/stderr"; check $? "missing key not named: $(cat "$work/stderr")"
[ "$(wc -l <"$work/stderr")" = 1 ]; check $? "error is not one line"
[ ! -e "$work/out.glb" ]; check $? "output left after failure"
"$exe" --model "$models/smpl_small.npz" --motion "$formats/aist.pkl" --out "$work/aist.glb" >"$work/stdout" 2>&1
check $? "AIST++ export: $(cat "$work/stdout")"
grep -qF "AIST++ stores no frame rate; its documentation gives 60 fps; assumed 60 fps" "$work/stdout"
check $? "no AIST++ fps note: $(cat "$work/stdout")"

# 5. Sharding: 3 shards as 3 processes cover every motion exactly once; the
#    concatenated manifests list each once; sha256 matches the outputs.
dir=$work/all
mkdir -p "$dir"
cp "$formats"/subject/* "$dir/"
cp "$fixtures"/motions/amass_smplh.npz "$fixtures"/motions/smpl_72.npz "$fixtures"/motions/plain.json "$dir/"
cp "$formats/codec_root.smpl" "$formats/aist.pkl" "$dir/"
cp "$formats/no_fps.npz" "$dir/"
all=$(cd "$dir" && find . -maxdepth 1 -type f | sed 's|^\./||' | sort)
pids=""
for i in 0 1 2; do
  "$exe" --model "$models/smplh_small.npz" --motion-dir "$dir" --out-dir "$work/sharded" --shard "$i/3" \
    --manifest "$work/shard$i.jsonl" -q >"$work/shard$i.out" 2>&1 &
  pids="$pids $!"
done
for p in $pids; do wait "$p"; check $? "a shard failed"; done
cat "$work"/shard0.jsonl "$work"/shard1.jsonl "$work"/shard2.jsonl >"$work/all.jsonl"
listed=$(/usr/bin/python3 -c '
import json, sys
for line in open(sys.argv[1]):
    print(json.loads(line)["input"].rsplit("/", 1)[1])' "$work/all.jsonl" | sort)
[ "$listed" = "$all" ]; check $? "manifests list $(echo $listed) instead of $(echo $all)"
[ "$(echo "$listed" | uniq -d)" = "" ]; check $? "a motion is in two shards"
for i in 0 1 2; do [ -s "$work/shard$i.jsonl" ]; check $? "shard $i did nothing"; done
/usr/bin/python3 - "$work/all.jsonl" <<'PY'
import hashlib, json, sys
bad = 0
for line in open(sys.argv[1]):
    e = json.loads(line)
    assert set(e) >= {"input", "output", "bytes", "sha256", "seconds", "status"}, e
    if e["status"] == "converted":
        data = open(e["output"], "rb").read()
        bad += hashlib.sha256(data).hexdigest() != e["sha256"] or len(data) != e["bytes"]
    elif e["status"] != "skipped":
        bad += 1
sys.exit(bad)
PY
check $? "manifest sha256/bytes/status wrong: $(cat "$work/all.jsonl")"
# The sharded outputs equal an unsharded run's, byte for byte.
"$exe" --model "$models/smplh_small.npz" --motion-dir "$dir" --out-dir "$work/whole" --manifest "$work/whole.jsonl" -q
check $? "unsharded run failed"
(cd "$work/whole" && for f in *.glb; do cmp -s "$f" "$work/sharded/$f" || echo "$f"; done) >"$work/diff"
[ ! -s "$work/diff" ] && [ "$(ls "$work/whole" | wc -l)" = "$(ls "$work/sharded" | wc -l)" ]
check $? "sharded outputs differ: $(cat "$work/diff")"
[ "$(wc -l <"$work/whole.jsonl")" = "$(wc -l <"$work/all.jsonl")" ]; check $? "manifest line counts differ"
ls "$work" | grep -q 'tmp'; [ $? != 0 ]; check $? "temporary files left"

echo "motion_formats_test: $passed passed, $failed failed"
[ "$failed" = 0 ]
