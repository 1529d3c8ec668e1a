#!/usr/bin/env bash
# MJCF output (--out x.xml) read by MuJoCo: export, build the independent
# reference (mjcf_reference.py) and run mjcf_check (MuJoCo's mj_loadXML,
# mj_kinematics, mj_step; see mjcf_check.cpp for the checks).
# Usage: mjcf_test.sh SMPL_EXPORT MJCF_CHECK PYTHON SOURCE_DIR FIXTURE_DIR WORK CASE
#   CASE builtin       the built-in body, hinges, motors; reference from its GLB export
#        smplx         the SMPL-X fixture with betas, --density 985; reference: numpy on the model file
#        smplx_ball    the same with --mjcf-joints ball
#        motion        the SMPL-X fixture with the AMASS SMPL-X motion (120 frames, 60 fps,
#                      Z-up world, trans): the .qpos.npz and keyframes against numpy's posed
#                      joints (mjcf_check --motion), and the wrong readings (Rz Ry Rx, x y z w)
#        motion_ball   the same with --mjcf-joints ball, --frames 10:50 and --fps 30 (every
#                      second source frame: 20 frames)
#        mesh          the built-in body with --mjcf-geoms mesh: the mesh geoms against the
#                      GLB's dominated vertices (mjcf_check --hulls), and the body-frame
#                      reading (--wrong-frame) must miss
#        smplx_mesh    the SMPL-X fixture with --mjcf-geoms mesh and --mjcf-joints ball
#        refusals      hostile values and options that do not apply: one line, exit 1, no file;
#                      and the same bytes twice
set -u
exe=$1 check=$2 python=$3 src=$4 fixtures=$5 work=$6 case=$7
mkdir -p "$work"
ref_py=$src/tests/roundtrip/mjcf_reference.py
model=$fixtures/models/smplx_small.npz
betas=0.5,-0.3,0.2

run() {  # echo and run; any failure ends the test
  echo "+ $*"
  "$@" || { echo "FAIL: $*"; exit 1; }
}

case "$case" in
  builtin)
    run "$exe" --model builtin --out "$work/builtin.xml" --mjcf-motors --quiet
    run "$exe" --model builtin --out "$work/builtin.glb" --quiet
    run "$python" "$ref_py" --glb "$work/builtin.glb" "$work/builtin_ref.txt"
    run "$check" "$work/builtin.xml" "$work/builtin_ref.txt" 1000
    n=$(grep -c "<motor " "$work/builtin.xml")
    [ "$n" = 69 ] || { echo "FAIL: $n motors, expected 23 x 3 = 69"; exit 1; }
    ;;
  smplx | smplx_ball)
    extra=()
    [ "$case" = smplx_ball ] && extra=(--mjcf-joints ball)
    run "$exe" --model "$model" --betas "$betas" --density 985 --out "$work/$case.xml" --quiet "${extra[@]}"
    run "$python" "$ref_py" --model "$model" --betas "$betas" "$work/${case}_ref.txt"
    run "$check" "$work/$case.xml" "$work/${case}_ref.txt" 985
    if [ "$case" = smplx_ball ]; then
      n=$(grep -c 'type="ball"' "$work/$case.xml")
      [ "$n" = 54 ] || { echo "FAIL: $n ball joints, expected 54"; exit 1; }
    fi
    ;;
  mesh | smplx_mesh)
    src_model=builtin shape=() extra=(--mjcf-motors)
    [ "$case" = smplx_mesh ] && src_model=$model shape=(--betas "$betas") extra=(--mjcf-joints ball)
    run "$exe" --model "$src_model" "${shape[@]}" --out "$work/$case.xml" --mjcf-geoms mesh --quiet "${extra[@]}"
    run "$exe" --model "$src_model" "${shape[@]}" --out "$work/$case.glb" --quiet
    run "$python" "$ref_py" --glb "$work/$case.glb" --hulls "$work/${case}_ref.txt"
    run "$check" "$work/$case.xml" "$work/${case}_ref.txt" 1000 --hulls
    run "$check" "$work/$case.xml" "$work/${case}_ref.txt" 1000 --hulls --wrong-frame
    n=$(grep -c '<mesh ' "$work/$case.xml")
    [ "$n" -ge 20 ] || { echo "FAIL: $n convex hull meshes, expected one per body part (>= 20)"; exit 1; }
    ;;
  motion | motion_ball)
    motion=$fixtures/motions/amass_smplx.npz
    extra=() first=0 step=1
    [ "$case" = motion_ball ] && extra=(--mjcf-joints ball --frames 10:50 --fps 30) first=10 step=2
    rm -f "$work/$case.xml" "$work/$case.qpos.npz"
    run "$exe" --model "$model" --motion "$motion" --out "$work/$case.xml" --quiet "${extra[@]}"
    [ -s "$work/$case.qpos.npz" ] || { echo "FAIL: no $case.qpos.npz beside the XML"; exit 1; }
    grep -q "\"$case.qpos.npz\"" "$work/$case.xml.smpl.json" ||
      { echo "FAIL: the sidecar does not record $case.qpos.npz"; exit 1; }
    run "$python" "$ref_py" --model "$model" --motion "$motion" --qpos "$work/$case.qpos.npz" \
      --first $first --step $step "$work/${case}_motion.txt"
    run "$check" --motion "$work/$case.xml" "$work/${case}_motion.txt"
    run "$check" --motion "$work/$case.xml" "$work/${case}_motion.txt" --quat-xyzw
    # Deterministic: the same XML and .npz bytes again.
    cp "$work/$case.xml" "$work/$case.first.xml" && cp "$work/$case.qpos.npz" "$work/$case.first.npz"
    run "$exe" --model "$model" --motion "$motion" --out "$work/$case.xml" --quiet "${extra[@]}"
    cmp "$work/$case.xml" "$work/$case.first.xml" && cmp "$work/$case.qpos.npz" "$work/$case.first.npz" ||
      { echo "FAIL: two exports with the motion differ"; exit 1; }
    if [ "$case" = motion ]; then
      run "$python" "$ref_py" --reorder-hinges "$work/$case.xml" "$work/${case}_zyx.xml"
      run "$check" --motion "$work/${case}_zyx.xml" "$work/${case}_motion.txt" --wrong-order
    fi
    ;;
  refusals)
    failed=0
    refuse() {  # expected stderr text, args...; exit status ${code:-1} (3: an export error)
      local text=$1; shift
      rm -f "$work/r.xml" "$work/r.qpos.npz"
      "$exe" "$@" >"$work/stdout" 2>"$work/stderr"
      local got=$?
      if [ "$got" != "${code:-1}" ] || ! grep -qF -- "$text" "$work/stderr" ||
        [ "$(wc -l <"$work/stderr")" != 1 ] || [ -e "$work/r.xml" ] || [ -e "$work/r.qpos.npz" ]; then
        echo "FAIL: $* -> exit $got, stderr: $(cat "$work/stderr") (expected '$text')"
        failed=1
      else
        echo "ok: $* -> $(cat "$work/stderr")"
      fi
    }
    refuse "--density: expected kg/m^3 in (0, 100000], got '-1'" --model builtin --out "$work/r.xml" --density -1
    refuse "--density: expected kg/m^3 in (0, 100000], got '0'" --model builtin --out "$work/r.xml" --density 0
    refuse "--density:" --model builtin --out "$work/r.xml" --density nan
    refuse "--density:" --model builtin --out "$work/r.xml" --density inf
    refuse "--mjcf-joints: expected 'hinge' or 'ball', got 'foo'" --model builtin --out "$work/r.xml" --mjcf-joints foo
    refuse "--mjcf-motors drives hinge joints" --model builtin --out "$work/r.xml" --mjcf-joints ball --mjcf-motors
    refuse "--mjcf-geoms: expected 'capsule' or 'mesh', got 'hull'" --model builtin --out "$work/r.xml" --mjcf-geoms hull
    refuse "--mjcf-geoms applies only to .xml" --model builtin --out "$work/r.glb" --mjcf-geoms mesh
    refuse "--density" --model builtin --out "$work/r.glb" --density 900
    refuse "--mjcf-joints" --model builtin --out "$work/r.bvh" --mjcf-joints ball
    refuse "--draco" --model builtin --out "$work/r.xml" --draco
    refuse "--bvh-units" --model builtin --out "$work/r.xml" --bvh-units cm
    refuse "--motion: mjcf output holds one motion" --model builtin --out "$work/r.xml" \
      --motion "$fixtures/motions/smpl_72.npz" --motion "$fixtures/motions/smpl_72.npz"
    # --root-bone moves the pelvis up and down with the AMASS motion's height: no hinge holds that.
    code=3 refuse "MJCF writer: joint pelvis moves away from its rest offset" --model builtin \
      --out "$work/r.xml" --motion "$fixtures/motions/amass_smplh.npz" --root-bone
    # Deterministic: the same bytes twice.
    "$exe" --model builtin --out "$work/a.xml" --quiet && "$exe" --model builtin --out "$work/b.xml" --quiet &&
      cmp "$work/a.xml" "$work/b.xml" || { echo "FAIL: two exports differ"; failed=1; }
    exit $failed
    ;;
  *) echo "mjcf_test.sh: unknown case '$case'"; exit 2 ;;
esac
echo "mjcf_test.sh $case: OK"
