#!/usr/bin/env bash
# Files laid out as released (model side): the SMPL-X release npz
# (object-array keys, UVs), AMASS stage-II motions, per-frame betas, --uv
# none / numpy pairs, a model folder with three genders and a mixed-gender
# batch. Fixtures: tests/fixtures/make_released_layouts.py.
# Usage: released_layouts_test.sh SMPL_EXPORT FIXTURE_DIR
set -u
exe=$1 fixtures=$2
rel=$fixtures/released
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
py=/usr/bin/python3

check() {  # name, status (saved before the name is expanded: $(...) in it resets $?)
  if [ "$2" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1"; fi
}

# Vertex count and whether TEXCOORD_0 is present, read from the GLB's JSON chunk.
glb_info() {
  $py - "$1" <<'PY'
import json, struct, sys
data = open(sys.argv[1], "rb").read()
n = struct.unpack_from("<I", data, 12)[0]
g = json.loads(data[20:20 + n])
attrs = g["meshes"][0]["primitives"][0]["attributes"]
print(g["accessors"][attrs["POSITION"]]["count"], "TEXCOORD_0" in attrs)
PY
}

# Expected asset vertices: distinct (vertex, uv) corners of f/ft, computed by numpy.
expected=$($py -c "
import numpy as np, sys
d = np.load('$rel/smplx_release.npz', allow_pickle=True)
print(len(set(zip(d['f'].ravel().tolist(), d['ft'].ravel().tolist()))), len(d['v_template']))")
split=${expected% *} plain=${expected#* }

# 1. SMPL-X release layout: loads, UVs from the file are used (seams split).
"$exe" --model "$rel/smplx_release.npz" --out "$work/release.glb" >"$work/out" 2>&1
st=$?; check "release npz exports: $(cat "$work/out")" $st
[ "$(glb_info "$work/release.glb")" = "$split True" ]; st=$?; check "model UVs used: $(glb_info "$work/release.glb"), expected $split True" $st
# --uv none: no UVs, the model's own vertices.
"$exe" --model "$rel/smplx_release.npz" --out "$work/nouv.glb" --uv none -q
st=$?; check "--uv none exports" $st
[ "$(glb_info "$work/nouv.glb")" = "$plain False" ]; st=$?; check "--uv none: $(glb_info "$work/nouv.glb"), expected $plain False" $st
# --uv numpy pair (either file) and OBJ give the same mesh as the model's UVs.
for uv in smplx_pair_uv.npy smplx_pair_ft.npy smplx_release_uv.obj; do
  "$exe" --model "$rel/smplx_release.npz" --out "$work/pair.glb" --uv "$rel/$uv" -q
  st=$?; check "--uv $uv exports" $st
  [ "$(glb_info "$work/pair.glb")" = "$split True" ]; st=$?; check "--uv $uv: $(glb_info "$work/pair.glb")" $st
done
"$exe" --model "$rel/smplx_release.npz" --out "$work/bad.glb" --uv "$rel/lonely_uv.npy" >"$work/out" 2>&1
[ $? = 2 ]; st=$?; check "missing UV partner exits 2 (an input cannot be loaded)" $st
grep -q "Error loading $rel/lonely_uv.npy: its partner lonely_ft.npy does not exist" "$work/out"; st=$?; check "partner error: $(cat "$work/out")" $st
"$exe" --model "$rel/smpl_bad_ft.npz" --out "$work/bad.glb" >"$work/out" 2>&1
[ $? = 2 ]; st=$?; check "bad ft exits 2" $st
grep -q "smpl_bad_ft.npz: 'ft' has index" "$work/out"; st=$?; check "bad ft error: $(cat "$work/out")" $st
[ "$(wc -l <"$work/out")" = 1 ]; st=$?; check "bad ft error is one line" $st

# 2. AMASS stage-II motion with an object key bakes.
"$exe" --model "$rel/smplx_release.npz" --motion "$rel/amass_stageii.npz" --out "$work/stageii.glb" >"$work/out" 2>&1
st=$?; check "stage-II motion bakes: $(cat "$work/out")" $st
grep -q "animation: 30 frames" "$work/out"; st=$?; check "stage-II frames: $(cat "$work/out")" $st

# 3. Per-frame betas: differing rows -> mean + note; identical rows -> no note; --betas-file too.
"$exe" --model "$fixtures/models/smpl_small.npz" --motion "$rel/betas_rows_differ.npz" --out "$work/d.glb" >"$work/out" 2>&1
st=$?; check "per-frame betas motion: $(cat "$work/out")" $st
grep -q "^note: betas_rows_differ: betas: 30 per-frame rows differ (largest deviation from their mean " "$work/out"
st=$?; check "per-frame betas note: $(cat "$work/out")" $st
$py - "$work/d.glb.smpl.json" "$rel/betas_rows_expected.npz" <<'PY'
import json, sys, numpy as np
meta = json.load(open(sys.argv[1]))
betas = meta.get("betas") or meta.get("model", {}).get("betas")
mean = np.load(sys.argv[2])["mean"]
sys.exit(0 if np.allclose(betas[:10], mean, atol=1e-9) else 1)
PY
st=$?; check "metadata betas are numpy's mean" $st
"$exe" --model "$fixtures/models/smpl_small.npz" --motion "$rel/betas_rows_same.npz" --out "$work/s.glb" >"$work/out" 2>&1
st=$?; check "identical per-frame betas: $(cat "$work/out")" $st
! grep -q "per-frame rows" "$work/out"; st=$?; check "no note for identical rows: $(cat "$work/out")" $st
"$exe" --model "$fixtures/models/smpl_small.npz" --betas-file "$rel/betas_rows_differ.npy" --out "$work/f.glb" >"$work/out" 2>&1
st=$?; check "--betas-file per-frame: $(cat "$work/out")" $st
grep -q "rows differ" "$work/out"; st=$?; check "--betas-file note: $(cat "$work/out")" $st

# 7. Model folder: gendered file per motion; neutral without a motion.
folder=$rel/smpl_folder
"$exe" --model "$folder" --motion "$rel/mixed_gender/f_walk.npz" --out "$work/fw.glb" >"$work/out" 2>&1
st=$?; check "folder + female motion: $(cat "$work/out")" $st
grep -qx "model: $folder/SMPL_FEMALE.pkl" "$work/out"; st=$?; check "female model named: $(cat "$work/out")" $st
"$exe" --model "$folder" --out "$work/n.glb" >"$work/out" 2>&1
st=$?; check "folder, no motion: $(cat "$work/out")" $st
grep -qx "model: $folder/SMPL_NEUTRAL.npz" "$work/out"; st=$?; check "neutral model named: $(cat "$work/out")" $st
# Mixed-gender batch: each output's summary line and metadata name its model.
"$exe" --model "$folder" --motion-dir "$rel/mixed_gender" --out-dir "$work/batch" --threads 2 >"$work/out" 2>&1
st=$?; check "mixed-gender batch: $(cat "$work/out")" $st
for pair in f_walk:SMPL_FEMALE.pkl m_walk:SMPL_MALE.pkl n_walk:SMPL_NEUTRAL.npz; do
  name=${pair%%:*} model=${pair#*:}
  grep -q "^\[[1-3]/3\] $work/batch/$name.glb: .*, model $folder/$model" "$work/out"; st=$?; check "batch line for $name names $model: $(cat "$work/out")" $st
  grep -q "\"$model\"" "$work/batch/$name.glb.smpl.json"; st=$?; check "metadata of $name names $model" $st
done
# The female and male outputs differ (different models), proving the pick is used.
! cmp -s "$work/batch/f_walk.glb" "$work/batch/m_walk.glb"; st=$?; check "female and male outputs differ" $st

# A folder of symbolic links (how clusters share the licensed models): file links
# whose targets have other names, and a kind folder that is a link. Each pick is
# the link's name, and the export equals the one from the real folder.
mkdir -p "$work/store/v1" "$work/links"
cp "$folder/SMPL_FEMALE.pkl" "$work/store/v1/a1b2c3"
cp "$folder/SMPL_NEUTRAL.npz" "$work/store/v1/d4e5f6"
ln -s "$work/store/v1/a1b2c3" "$work/links/SMPL_FEMALE.pkl"
ln -s ../store/v1/d4e5f6 "$work/links/SMPL_NEUTRAL.npz"
ln -s "$work/store/v1" "$work/links/smpl"  # a link to a folder (holds no released names)
mkdir -p "$work/kindlink/real/smpl"
cp "$folder/SMPL_MALE.pkl" "$work/kindlink/real/smpl/SMPL_MALE.pkl"
mkdir -p "$work/links2"; ln -s "$work/kindlink/real/smpl" "$work/links2/smpl"
"$exe" --model "$work/links" --motion "$rel/mixed_gender/f_walk.npz" --out "$work/lf.glb" >"$work/out" 2>&1
st=$?; check "folder of links + female motion: $(cat "$work/out")" $st
grep -qx "model: $work/links/SMPL_FEMALE.pkl" "$work/out"; st=$?; check "linked female model named by its link: $(cat "$work/out")" $st
cmp -s "$work/lf.glb" "$work/fw.glb"; st=$?; check "export through a link equals the real file's" $st
"$exe" --model "$work/links" --out "$work/ln.glb" >"$work/out" 2>&1
grep -qx "model: $work/links/SMPL_NEUTRAL.npz" "$work/out"; st=$?; check "relative link to the neutral model: $(cat "$work/out")" $st
"$exe" --model "$work/links2" --motion "$rel/mixed_gender/m_walk.npz" --out "$work/lm.glb" >"$work/out" 2>&1
grep -qx "model: $work/links2/smpl/SMPL_MALE.pkl" "$work/out"; st=$?; check "kind folder that is a link: $(cat "$work/out")" $st
# A dangling link with a released name: the load error names it and the reason.
mkdir -p "$work/dangling"; ln -s "$work/nowhere.npz" "$work/dangling/SMPLX_NEUTRAL.npz"
"$exe" --model "$work/dangling" --out "$work/d.glb" >"$work/out" 2>&1
[ $? = 2 ]; st=$?; check "dangling link exits 2" $st
grep -q "$work/dangling/SMPLX_NEUTRAL.npz.*No such file" "$work/out"; st=$?; check "dangling link error: $(cat "$work/out")" $st
# A folder with files but no released names: the error lists what it saw.
mkdir -p "$work/other"; cp "$folder/SMPL_NEUTRAL.npz" "$work/other/my_model.npz"
"$exe" --model "$work/other" --out "$work/o.glb" >"$work/out" 2>&1
grep -q "no model files with the released names.*files seen: my_model.npz" "$work/out"; st=$?; check "unrecognised names are listed: $(cat "$work/out")" $st

# A folder without released names, or without the motion's kind: one error line, exit 2.
mkdir -p "$work/empty"
"$exe" --model "$work/empty" --out "$work/e.glb" >"$work/out" 2>&1
[ $? = 2 ]; st=$?; check "empty model folder exits 2" $st
grep -q "^Error loading $work/empty: .*no model files with the released names" "$work/out"; st=$?; check "empty folder error: $(cat "$work/out")" $st
"$exe" --model "$folder" --motion "$rel/amass_stageii.npz" --out "$work/e.glb" >"$work/out" 2>&1
[ $? = 2 ]; st=$?; check "no SMPL-X model in folder exits 2" $st
grep -q "no male SMPL-X model" "$work/out"; st=$?; check "missing kind error: $(cat "$work/out")" $st
[ ! -e "$work/e.glb" ]; st=$?; check "no output after a folder error" $st
# Batch with one unloadable model file: exit 2 before any motion (as before folders existed).
head -c 3000 "$rel/smpl_folder/SMPL_NEUTRAL.npz" >"$work/cut.npz"
"$exe" --model "$work/cut.npz" --motion-dir "$rel/mixed_gender" --out-dir "$work/batch2" >"$work/out" 2>&1
[ $? = 2 ]; st=$?; check "batch with a broken model exits 2: $(cat "$work/out")" $st
[ "$(wc -l <"$work/out")" = 1 ]; st=$?; check "batch with a broken model: one error line" $st

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
