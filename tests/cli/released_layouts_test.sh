#!/usr/bin/env bash
# Files laid out as released (issue 11, model side): the SMPL-X release npz
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

check() {  # name, condition result
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
check "release npz exports: $(cat "$work/out")" $?
[ "$(glb_info "$work/release.glb")" = "$split True" ]; check "model UVs used: $(glb_info "$work/release.glb"), expected $split True" $?
# --uv none: no UVs, the model's own vertices.
"$exe" --model "$rel/smplx_release.npz" --out "$work/nouv.glb" --uv none -q
check "--uv none exports" $?
[ "$(glb_info "$work/nouv.glb")" = "$plain False" ]; check "--uv none: $(glb_info "$work/nouv.glb"), expected $plain False" $?
# --uv numpy pair (either file) and OBJ give the same mesh as the model's UVs.
for uv in smplx_pair_uv.npy smplx_pair_ft.npy smplx_release_uv.obj; do
  "$exe" --model "$rel/smplx_release.npz" --out "$work/pair.glb" --uv "$rel/$uv" -q
  check "--uv $uv exports" $?
  [ "$(glb_info "$work/pair.glb")" = "$split True" ]; check "--uv $uv: $(glb_info "$work/pair.glb")" $?
done
"$exe" --model "$rel/smplx_release.npz" --out "$work/bad.glb" --uv "$rel/missing_uv.npy" >"$work/out" 2>&1
[ $? = 3 ]; check "missing UV partner exits 3" $?
grep -q "its partner missing_ft.npy does not exist" "$work/out"; check "partner error: $(cat "$work/out")" $?
"$exe" --model "$rel/smpl_bad_ft.npz" --out "$work/bad.glb" >"$work/out" 2>&1
[ $? = 2 ]; check "bad ft exits 2" $?
grep -q "smpl_bad_ft.npz: 'ft' has index" "$work/out"; check "bad ft error: $(cat "$work/out")" $?
[ "$(wc -l <"$work/out")" = 1 ]; check "bad ft error is one line" $?

# 2. AMASS stage-II motion with an object key bakes.
"$exe" --model "$rel/smplx_release.npz" --motion "$rel/amass_stageii.npz" --out "$work/stageii.glb" >"$work/out" 2>&1
check "stage-II motion bakes: $(cat "$work/out")" $?
grep -q "animation: 30 frames" "$work/out"; check "stage-II frames: $(cat "$work/out")" $?

# 3. Per-frame betas: differing rows -> mean + note; identical rows -> no note; --betas-file too.
"$exe" --model "$fixtures/models/smpl_small.npz" --motion "$rel/betas_rows_differ.npz" --out "$work/d.glb" >"$work/out" 2>&1
check "per-frame betas motion: $(cat "$work/out")" $?
grep -q "^note: betas_rows_differ: betas: 30 per-frame rows differ (largest deviation from their mean " "$work/out"
check "per-frame betas note: $(cat "$work/out")" $?
mean=$($py -c "import numpy as np; print(np.load('$rel/betas_rows_expected.npz')['mean'][0])")
$py - "$work/d.glb.smpl.json" "$rel/betas_rows_expected.npz" <<'PY'
import json, sys, numpy as np
meta = json.load(open(sys.argv[1]))
betas = meta.get("betas") or meta.get("model", {}).get("betas")
mean = np.load(sys.argv[2])["mean"]
sys.exit(0 if np.allclose(betas[:10], mean, atol=1e-9) else 1)
PY
check "metadata betas are numpy's mean" $?
"$exe" --model "$fixtures/models/smpl_small.npz" --motion "$rel/betas_rows_same.npz" --out "$work/s.glb" >"$work/out" 2>&1
check "identical per-frame betas: $(cat "$work/out")" $?
! grep -q "per-frame rows" "$work/out"; check "no note for identical rows: $(cat "$work/out")" $?
"$exe" --model "$fixtures/models/smpl_small.npz" --betas-file "$rel/betas_rows_differ.npy" --out "$work/f.glb" >"$work/out" 2>&1
check "--betas-file per-frame: $(cat "$work/out")" $?
grep -q "rows differ" "$work/out"; check "--betas-file note: $(cat "$work/out")" $?

# 7. Model folder: gendered file per motion; neutral without a motion.
folder=$rel/smpl_folder
"$exe" --model "$folder" --motion "$rel/mixed_gender/f_walk.npz" --out "$work/fw.glb" >"$work/out" 2>&1
check "folder + female motion: $(cat "$work/out")" $?
grep -qx "model: $folder/SMPL_FEMALE.pkl" "$work/out"; check "female model named: $(cat "$work/out")" $?
"$exe" --model "$folder" --out "$work/n.glb" >"$work/out" 2>&1
check "folder, no motion: $(cat "$work/out")" $?
grep -qx "model: $folder/SMPL_NEUTRAL.npz" "$work/out"; check "neutral model named: $(cat "$work/out")" $?
# Mixed-gender batch: each output's summary line and metadata name its model.
"$exe" --model "$folder" --motion-dir "$rel/mixed_gender" --out-dir "$work/batch" --threads 2 >"$work/out" 2>&1
check "mixed-gender batch: $(cat "$work/out")" $?
for pair in f_walk:SMPL_FEMALE.pkl m_walk:SMPL_MALE.pkl n_walk:SMPL_NEUTRAL.npz; do
  name=${pair%%:*} model=${pair#*:}
  grep -q "^$work/batch/$name.glb: .*, model $folder/$model" "$work/out"; check "batch line for $name names $model: $(cat "$work/out")" $?
  grep -q "\"$model\"" "$work/batch/$name.glb.smpl.json"; check "metadata of $name names $model" $?
done
# The female and male outputs differ (different models), proving the pick is used.
! cmp -s "$work/batch/f_walk.glb" "$work/batch/m_walk.glb"; check "female and male outputs differ" $?

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
