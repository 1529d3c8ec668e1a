#!/usr/bin/env bash
# DMPL soft tissue from the command line (fixtures: tests/fixtures/make_dmpl.py):
# bad inputs fail with one line naming the file and leave no output; the notes
# for a motion without `dmpls` and for `dmpls` without a basis; static export at
# weight 0; --dmpl-count; --dmpl DIR (AMASS layout) with --model DIR, single and
# batch; the fixed-joint cost the CLI prints equals numpy's (dmpl_cost.py).
# Usage: dmpl_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
dm=$fixtures/dmpl model=$fixtures/models/smplh_small.npz basis=$fixtures/dmpl/dmpl_smplh_small.npz
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

check() {  # status, name
  if [ "$1" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $2"; fi
}
meta() {  # sidecar, python expression on d -> printed
  /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"
}

# 1. Bad inputs: exit 2, one "Error" line naming the file, no output or sidecar.
bad() {  # name, expected text, args...
  local name=$1 text=$2; shift 2
  "$exe" --model "$model" --out "$work/bad.glb" "$@" >"$work/stdout" 2>"$work/stderr"
  local status=$?
  [ "$status" = 2 ]; check $? "$name: exit $status, expected 2: $(cat "$work/stderr")"
  [ "$(wc -l <"$work/stderr")" = 1 ] && grep -q "^Error loading .*$text" "$work/stderr"
  check $? "$name: expected one line with '$text': $(cat "$work/stderr")"
  [ ! -e "$work/bad.glb" ] && [ ! -e "$work/bad.glb.smpl.json" ]; check $? "$name: output written"
}
bad vertices "bad_vertices.npz: 'eigvec' has shape (618,3,8); expected (N,3,D) with N=624" \
  --motion "$dm/amass_smplh_dmpl.npz" --dmpl "$dm/bad_vertices.npz"
bad width "bad_width.npz: 'dmpls' has 6 columns; the DMPL basis .*dmpl_smplh_small.npz has 8" \
  --motion "$dm/bad_width.npz" --dmpl "$basis"
bad nan "bad_nan.npz: 'dmpls' contains NaN" --motion "$dm/bad_nan.npz" --dmpl "$basis"
bad missing "none.npz" --dmpl "$work/none.npz"
bad count "--dmpl-count 9: the basis has 8" --dmpl "$basis" --dmpl-count 9
# A malformed `dmpls` does not matter without --dmpl (unneeded keys never fail).
"$exe" --model "$model" --motion "$dm/bad_nan.npz" --out "$work/nan_ok.glb" -q; check $? "bad dmpls without --dmpl failed"

# 2. Notes: dmpls without a basis (how to include them), a basis without dmpls (no targets).
"$exe" --model "$model" --motion "$dm/amass_smplh_dmpl.npz" --out "$work/plain.glb" >"$work/stdout" 2>&1
check $? "no --dmpl: $(cat "$work/stdout")"
grep -qF "note: amass_smplh_dmpl: the motion has DMPL soft-tissue coefficients 'dmpls' (8 per frame), not baked: add --dmpl" \
  "$work/stdout"; check $? "no how-to note: $(cat "$work/stdout")"
"$exe" --model "$model" --motion "$dm/amass_smplh_no_dmpls.npz" --dmpl "$basis" --out "$work/nod.glb" >"$work/stdout" 2>&1
check $? "basis without dmpls: $(cat "$work/stdout")"
grep -qF "note: --dmpl: no motion has 'dmpls' (DMPL coefficients): no DMPL targets exported" "$work/stdout"
check $? "no no-dmpls note: $(cat "$work/stdout")"
[ "$(meta "$work/nod.glb.smpl.json" "'dmpl' in d or any(n.startswith('dmpl_') for n in d['morph_targets'])")" = False ]
check $? "basis without dmpls: DMPL targets exported"

# 3. Static export: 8 targets at weight 0 (scale 1, offset 0), and --dmpl-count 3.
"$exe" --model "$model" --dmpl "$basis" --out "$work/static.glb" -q; check $? "static export"
[ "$(meta "$work/static.glb.smpl.json" "[(t['target'], t['scale'], t['offset']) for t in d['dmpl']['targets']][7]")" = "('dmpl_7', 1.0, 0.0)" ]
check $? "static: dmpl_7 not at weight 0: $(meta "$work/static.glb.smpl.json" "d['dmpl']")"
"$exe" --model "$model" --motion "$dm/amass_smplh_dmpl.npz" --dmpl "$basis" --dmpl-count 3 --out "$work/three.glb" -q
check $? "--dmpl-count 3"
[ "$(meta "$work/three.glb.smpl.json" "[n for n in d['morph_targets'] if n.startswith('dmpl_')]")" = "['dmpl_0', 'dmpl_1', 'dmpl_2']" ]
check $? "--dmpl-count 3: $(meta "$work/three.glb.smpl.json" "d['morph_targets'][-4:]")"
# Weights of an animated export stay in [0, 1] (scale * c + offset over the motion).
[ "$(meta "$work/three.glb.smpl.json" "all(t['scale'] > 0 and 0 <= t['offset'] <= 1 for t in d['dmpl']['targets'])")" = True ]
check $? "encoding out of range"

# 4. --dmpl DIR and --model DIR in AMASS's layout (smplh/female, dmpls/female); batch too.
"$exe" --model "$dm/amass" --dmpl "$dm/amass" --motion "$dm/amass_smplh_dmpl.npz" --out "$work/dir.glb" -q
check $? "--dmpl DIR"
[ "$(meta "$work/dir.glb.smpl.json" "len(d['dmpl']['targets'])")" = 8 ]; check $? "--dmpl DIR: no targets"
mkdir -p "$work/motions" && cp "$dm/amass_smplh_dmpl.npz" "$work/motions/"
"$exe" --model "$dm/amass" --dmpl "$dm/amass" --motion-dir "$work/motions" --out-dir "$work/batch" -q >/dev/null
check $? "batch with --dmpl DIR"
[ "$(meta "$work/batch/amass_smplh_dmpl.glb.smpl.json" "d['dmpl']['basis']")" = model.npz ]; check $? "batch: no DMPL"
# Up to date while the basis is unchanged; a changed basis inside --dmpl DIR rebuilds.
cp -r "$dm/amass" "$work/amass"
"$exe" --model "$work/amass" --dmpl "$work/amass" --motion-dir "$work/motions" --out-dir "$work/batch2" -q >/dev/null
check $? "batch copy"
"$exe" --model "$work/amass" --dmpl "$work/amass" --motion-dir "$work/motions" --out-dir "$work/batch2" >"$work/stdout"
tail -n 1 "$work/stdout" | grep -qF "batch: 0 converted, 1 up to date"; check $? "unchanged basis rebuilt: $(tail -n 1 "$work/stdout")"
/usr/bin/python3 -c "import numpy as np, sys; p = sys.argv[1]; e = np.load(p)['eigvec']; np.savez(p, eigvec=0.5 * e)" \
  "$work/amass/dmpls/female/model.npz"
"$exe" --model "$work/amass" --dmpl "$work/amass" --motion-dir "$work/motions" --out-dir "$work/batch2" >"$work/stdout"
tail -n 1 "$work/stdout" | grep -qF "batch: 1 converted, 0 up to date"; check $? "changed basis not rebuilt: $(tail -n 1 "$work/stdout")"
"$exe" --model "$dm/amass" --dmpl "$work" --motion "$dm/amass_smplh_dmpl.npz" --out "$work/nodir.glb" 2>"$work/stderr" >/dev/null
[ $? = 2 ] && grep -qF "no DMPL basis for gender 'female'" "$work/stderr"; check $? "--dmpl DIR without a basis: $(cat "$work/stderr")"

# 5. The printed fixed-joint cost equals numpy's (max over every frame, mm, 3 decimals).
"$exe" --model "$model" --motion "$dm/amass_smplh_dmpl.npz" --dmpl "$basis" --skin-weights truncated --out "$work/cost.glb" >"$work/stdout" 2>&1
got=$(sed -n 's/.*fixed joints) costs up to \([0-9.]*\) mm.*/\1/p' "$work/stdout")
want=$(/usr/bin/python3 "$here/dmpl_cost.py" "$model" "$dm/amass_smplh_dmpl.npz" "$basis" 4)
[ -n "$got" ] && [ "$got" = "$want" ]; check $? "fixed-joint cost: CLI '$got' mm, numpy '$want' mm"

# 6. Option checks (exit 1).
"$exe" --model "$model" --dmpl-count 2 --out "$work/u.glb" 2>/dev/null; [ $? = 1 ]; check $? "--dmpl-count without --dmpl"
"$exe" --model "$model" --dmpl "$basis" --dmpl-joints bones --out "$work/u.glb" 2>/dev/null; [ $? = 1 ]; check $? "--dmpl-joints bones"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
