#!/usr/bin/env bash
# The WebAssembly build (scripts/build-wasm.sh: smpl-export.js + .wasm) run
# with node, against the native build, on the same relative command lines:
#   byte-identical (cmp, output and sidecar): model-file exports without the
#     skin fit and the corrective refit (truncated weights, refit off: an
#     AMASS motion baked to GLB, a pickle model), the BVH of a default export,
#     and a batch of two motions;
#   equal to float rounding (tests/package/glb_float_diff.py, at most 1e-9 m
#     in any float32 of the buffer; sizes and JSON equal but for those
#     floats): the default export (fit + refit) of the built-in body and of an
#     SMPL-H model with an AMASS motion, and the built-in body without fit;
#   the same size, stored uncompressed: FBX (the built-in body; an AMASS
#     motion baked); how many bytes differ is printed.
# The last bits differ where Eigen's vectorised paths run (the fit, the
# refit, the demo body's own fits, the FBX writer's transforms): SSE2 on
# x86-64, scalar in wasm32 (Eigen 3.4 has no WebAssembly SIMD), so sums are
# taken in another order.
# Errors: a missing model gives the one-line error and exit code 2.
#   wasm_node_test.sh SMPL_EXPORT_JS NATIVE_EXE FIXTURES WORK
# (SMPL_EXPORT_JS: the npm package's bin/smpl-export.js, build-wasm/npm/, as npx runs it)
set -euo pipefail
js=$(realpath -m "$1") native=$(realpath -m "$2") fixtures=$(realpath -m "$3") work=$(realpath -m "$4")
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ -f $js ]] || fail "no WebAssembly build at '$js' (configure the tests with -DSMPL_WASM_BUILD_DIR=<build-wasm>; scripts/test.sh runs scripts/build-wasm.sh)"

rm -rf "$work" && mkdir -p "$work/wasm/in" "$work/native/in"
for side in wasm native; do
  for f in models/smpl_small.npz models/smpl_small_p2.pkl models/smplh_small.npz motions/smpl_72.npz \
    motions/amass_smplh.npz; do
    cp "$fixtures/$f" "$work/$side/in/"
  done
  mkdir -p "$work/$side/in/batch" "$work/$side/exact" "$work/$side/close"
  cp "$fixtures/motions/smpl_72.npz" "$work/$side/in/batch/a.npz"
  cp "$fixtures/motions/amass_smplh.npz" "$work/$side/in/batch/b.npz"
done
[[ $(node "$js" --version) == "$("$native" --version)" ]] || fail "--version differs"

plain="--skin-weights truncated --corrective-refit off"
exact=(
  "--model in/smplh_small.npz $plain --motion in/amass_smplh.npz --out exact/amass.glb"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --out exact/amass.bvh"
  "--model in/smpl_small_p2.pkl $plain --betas 0.5,-1.2,0.3 --out exact/pickle.glb"
  "--model in/smpl_small.npz $plain --motion-dir in/batch --out-dir exact/batch"
)
close=(
  "--model builtin --out close/body.glb"
  "--model builtin $plain --out close/plain.glb"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --out close/amass.glb"
  "--model builtin $plain --fbx-compress-level 0 --out close/body.fbx"
  "--model in/smplh_small.npz $plain --fbx-compress-level 0 --motion in/amass_smplh.npz --out close/amass.fbx"
)
for args in "${exact[@]}" "${close[@]}"; do
  # shellcheck disable=SC2086
  (cd "$work/wasm" && node "$js" $args --quiet) || fail "WebAssembly build: smpl-export $args (exit $?)"
  # shellcheck disable=SC2086
  (cd "$work/native" && "$native" $args --quiet) || fail "native build: smpl-export $args (exit $?)"
done
compared=0
while IFS= read -r f; do
  cmp "$work/wasm/exact/$f" "$work/native/exact/$f" || fail "$f differs between the WebAssembly and the native build"
  compared=$((compared + 1))
done < <(cd "$work/native/exact" && find . -type f | sed 's|^\./||' | sort)
[[ $compared -ge 10 ]] || fail "only $compared files compared"
for f in body.glb plain.glb amass.glb; do
  /usr/bin/python3 "$here/glb_float_diff.py" "$work/wasm/close/$f" "$work/native/close/$f" 1e-9 ||
    fail "close/$f: the WebAssembly and the native build differ beyond float rounding"
done
for f in body.fbx amass.fbx; do  # stored uncompressed: the same size, only the last bits of numbers
  a=$work/wasm/close/$f b=$work/native/close/$f
  [[ $(stat -c %s "$a") -eq $(stat -c %s "$b") ]] || fail "close/$f: sizes differ"
  echo "$f: $(cmp -l "$a" "$b" | wc -l) of $(stat -c %s "$a") bytes differ"
done

msg=$(cd "$work/wasm" && { node "$js" --model in/nope.npz --out out/nope.glb 2>&1 >/dev/null || true; })
rc=$(cd "$work/wasm" && { node "$js" --model in/nope.npz --out out/nope.glb >/dev/null 2>&1; echo $?; })
[[ $rc -eq 2 && $msg == "Error loading in/nope.npz: cannot open: "* && $(wc -l <<<"$msg") -eq 1 ]] ||
  fail "a missing model: exit code $rc, '$msg'"
[[ ! -e $work/wasm/out/nope.glb ]] || fail "a failed export left out/nope.glb"
echo "PASS: $compared files byte-identical between smpl-export.js (node) and the native build; 3 GLBs equal to float rounding, 2 FBX of the same size; errors"
