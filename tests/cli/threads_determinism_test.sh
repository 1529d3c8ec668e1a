#!/usr/bin/env bash
# The same bytes for any thread count: each export below is run with
# --threads 1, 2 and 3, and every file it writes (the output and its sidecar)
# must have the same SHA-256 across the three runs. The fit, the refit, the
# bake and the FBX compression split their work over the threads; the split
# must never change a sum's order. Cases: the built-in body (GLB, FBX, with a
# motion, --preset web with a motion), the SMPL-X fixture with an AMASS SMPL-X
# motion (GLB, FBX) and the SMPL fixture as BVH.
#   threads_determinism_test.sh SMPL_EXPORT FIXTURE_DIR WORK
set -uo pipefail
exe=$1 fixtures=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
models=$fixtures/models motions=$fixtures/motions
cases=(
  "builtin_glb|--model builtin --out body.glb"
  "builtin_fbx|--model builtin --out body.fbx"
  "builtin_motion_glb|--model builtin --motion $motions/smpl_72.npz --out body.glb"
  "builtin_web|--model builtin --motion $motions/smpl_72.npz --preset web --out body.glb"
  "smplx_motion_glb|--model $models/smplx_small.npz --motion $motions/amass_smplx.npz --out body.glb"
  "smplx_motion_fbx|--model $models/smplx_small.npz --motion $motions/amass_smplx.npz --out body.fbx"
  "smpl_bvh|--model $models/smpl_small.npz --motion $motions/smpl_72.npz --out body.bvh"
)
failed=0
for c in "${cases[@]}"; do
  name=${c%%|*} args=${c#*|}
  sums=()
  for n in 1 2 3; do
    dir=$work/$name/t$n
    mkdir -p "$dir"
    # shellcheck disable=SC2086  # the case's arguments are words
    if ! (cd "$dir" && "$exe" $args --threads "$n" -q) >"$dir.log" 2>&1; then
      echo "FAIL $name: --threads $n exited non-zero: $(tail -1 "$dir.log")"
      failed=1
      continue 2
    fi
    sums+=("$(cd "$dir" && find . -type f | LC_ALL=C sort | xargs sha256sum)")
  done
  if [[ ${sums[0]} == "${sums[1]}" && ${sums[0]} == "${sums[2]}" && -n ${sums[0]} ]]; then
    echo "ok   $name: $(wc -l <<<"${sums[0]}") files identical for --threads 1, 2, 3"
  else
    echo "FAIL $name: bytes differ between thread counts:"
    diff <(echo "${sums[0]}") <(echo "${sums[1]}") | sed 's/^/  1 vs 2: /'
    diff <(echo "${sums[0]}") <(echo "${sums[2]}") | sed 's/^/  1 vs 3: /'
    failed=1
  fi
done
exit $failed
