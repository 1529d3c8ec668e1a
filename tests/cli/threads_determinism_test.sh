#!/usr/bin/env bash
# The same bytes for any thread count and any SIMD target: each export below
# is run with --threads 1, 2 and 3 under every SMPL_EXPORT_SIMD target this
# CPU runs (scalar, sse4, avx2, avx512; at least scalar and one vector
# target, or the test fails), and every file it writes (the output and its
# sidecar) must have the same SHA-256 across all the runs. The fit, the
# refit, the bake and the FBX compression split their work over the threads,
# and the refit's products run on the target's vector width; neither may
# change a sum's order. Cases: the built-in body (GLB, FBX, with a motion,
# --preset web with a motion), the SMPL-X fixture with an AMASS SMPL-X motion
# (GLB, FBX), the SMPL fixture as BVH and the full-size SMPL stand-in
# (tools/bench/make_standin.py: 6890 vertices, every vertex refitted) as GLB
# and FBX. (The WebAssembly build's bytes: package.wasm_node.)
#   threads_determinism_test.sh SMPL_EXPORT FIXTURE_DIR WORK [SOURCE_DIR]
set -uo pipefail
exe=$1 fixtures=$2 work=$3 source=${4:-}
rm -rf "$work" && mkdir -p "$work"
models=$fixtures/models motions=$fixtures/motions
targets=()
for t in scalar sse4 avx2 avx512; do
  if msg=$(SMPL_EXPORT_SIMD=$t "$exe" --model builtin --out "$work/probe.bvh" -q 2>&1); then
    targets+=("$t")
  elif [[ $msg == *"not available on this CPU"* ]]; then
    echo "note: $t: not available on this CPU"
  else
    echo "FAIL SMPL_EXPORT_SIMD=$t: $msg"
    exit 1
  fi
done
if ((${#targets[@]} < 2)); then
  echo "FAIL only ${targets[*]} runs here: the test needs scalar and a vector target"
  exit 1
fi
echo "targets: ${targets[*]}"
cases=(
  "builtin_glb|--model builtin --out body.glb"
  "builtin_fbx|--model builtin --out body.fbx"
  "builtin_motion_glb|--model builtin --motion $motions/smpl_72.npz --out body.glb"
  "builtin_web|--model builtin --motion $motions/smpl_72.npz --preset web --out body.glb"
  "smplx_motion_glb|--model $models/smplx_small.npz --motion $motions/amass_smplx.npz --out body.glb"
  "smplx_motion_fbx|--model $models/smplx_small.npz --motion $motions/amass_smplx.npz --out body.fbx"
  "smpl_bvh|--model $models/smpl_small.npz --motion $motions/smpl_72.npz --out body.bvh"
)
if [[ -n $source ]]; then
  if ! /usr/bin/python3 "$source/tools/bench/make_standin.py" "$work/standin" >"$work/standin.log" 2>&1; then
    echo "FAIL make_standin.py: $(tail -1 "$work/standin.log")"
    exit 1
  fi
  cases+=("standin_glb|--model $work/standin/standin_smpl_py2.pkl --out body.glb"
          "standin_fbx|--model $work/standin/standin_smpl_py2.pkl --out body.fbx")
fi
failed=0
for c in "${cases[@]}"; do
  name=${c%%|*} args=${c#*|}
  first='' first_run='' same=1
  for t in "${targets[@]}"; do
    for n in 1 2 3; do
      dir=$work/$name/$t-t$n
      mkdir -p "$dir"
      # shellcheck disable=SC2086  # the case's arguments are words
      if ! (cd "$dir" && SMPL_EXPORT_SIMD=$t "$exe" $args --threads "$n" -q) >"$dir.log" 2>&1; then
        echo "FAIL $name: $t --threads $n exited non-zero: $(tail -1 "$dir.log")"
        failed=1
        continue 3
      fi
      sums=$(cd "$dir" && find . -type f | LC_ALL=C sort | xargs sha256sum)
      if [[ -z $first ]]; then
        first=$sums first_run="$t --threads $n"
      elif [[ $sums != "$first" ]]; then
        echo "FAIL $name: $t --threads $n differs from $first_run:"
        diff <(echo "$first") <(echo "$sums") | sed 's/^/  /'
        same=0
      fi
    done
  done
  if ((same)) && [[ -n $first ]]; then
    echo "ok   $name: $(wc -l <<<"$first") files identical for ${targets[*]} x --threads 1, 2, 3"
  else
    failed=1
  fi
done
exit $failed
