#!/usr/bin/env bash
# MJCF output (--out x.xml) read by MuJoCo: export, build the independent
# reference (mjcf_reference.py) and run mjcf_check (MuJoCo's mj_loadXML,
# mj_kinematics, mj_step; see mjcf_check.cpp for the checks).
# Usage: mjcf_test.sh SMPL_EXPORT MJCF_CHECK PYTHON SOURCE_DIR FIXTURE_DIR WORK CASE
#   CASE builtin       the built-in body, hinges, motors; reference from its GLB export
#        smplx         the SMPL-X fixture with betas, --density 985; reference: numpy on the model file
#        smplx_ball    the same with --mjcf-joints ball
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
  refusals)
    failed=0
    refuse() {  # expected stderr text, args...
      local text=$1; shift
      rm -f "$work/r.xml"
      "$exe" "$@" >"$work/stdout" 2>"$work/stderr"
      local got=$?
      if [ "$got" != 1 ] || ! grep -qF -- "$text" "$work/stderr" || [ "$(wc -l <"$work/stderr")" != 1 ] ||
        [ -e "$work/r.xml" ]; then
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
    refuse "--density" --model builtin --out "$work/r.glb" --density 900
    refuse "--mjcf-joints" --model builtin --out "$work/r.bvh" --mjcf-joints ball
    refuse "--draco" --model builtin --out "$work/r.xml" --draco
    refuse "--bvh-units" --model builtin --out "$work/r.xml" --bvh-units cm
    refuse "--motion: mjcf output holds no animation" --model builtin --out "$work/r.xml" \
      --motion "$fixtures/motions/smpl_72.npz"
    # Deterministic: the same bytes twice.
    "$exe" --model builtin --out "$work/a.xml" --quiet && "$exe" --model builtin --out "$work/b.xml" --quiet &&
      cmp "$work/a.xml" "$work/b.xml" || { echo "FAIL: two exports differ"; failed=1; }
    exit $failed
    ;;
  *) echo "mjcf_test.sh: unknown case '$case'"; exit 2 ;;
esac
echo "mjcf_test.sh $case: OK"
