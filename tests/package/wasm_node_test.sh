#!/usr/bin/env bash
# The WebAssembly build (scripts/build-wasm.sh: smpl-export.js + .wasm) run
# with node, against the native build, on the same relative command lines;
# every output and sidecar byte-identical (cmp): the built-in body's default
# export (the demo body's fits, the skin fit and the corrective refit) to GLB
# and FBX, and without fit and refit; an SMPL-H model with an AMASS motion
# baked to GLB (with and without fit and refit), FBX and BVH; a pickle model
# with betas; a batch of two motions; a full-size SMPL stand-in (6890
# vertices, tools/bench/make_standin.py), whose refit products are deep
# enough for Eigen to split them into blocks. Eigen runs its SSE2 code in
# both (emscripten's SSE emulation, x86-64's register count: CMakeLists.txt)
# with the same block depth (fixed cache sizes: core/math/eigen_blocking.h).
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
  mkdir -p "$work/$side/in/batch" "$work/$side/exact"
  cp "$fixtures/motions/smpl_72.npz" "$work/$side/in/batch/a.npz"
  cp "$fixtures/motions/amass_smplh.npz" "$work/$side/in/batch/b.npz"
done
/usr/bin/python3 "$here/../../tools/bench/make_standin.py" "$work/standin" >/dev/null
for side in wasm native; do cp "$work/standin/standin_smpl_stored.npz" "$work/$side/in/"; done
[[ $(node "$js" --version) == "$("$native" --version)" ]] || fail "--version differs"

plain="--skin-weights truncated --corrective-refit off"
exact=(
  "--model in/smplh_small.npz $plain --motion in/amass_smplh.npz --out exact/amass.glb"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --out exact/amass.bvh"
  "--model in/smpl_small_p2.pkl $plain --betas 0.5,-1.2,0.3 --out exact/pickle.glb"
  "--model in/smpl_small.npz $plain --motion-dir in/batch --out-dir exact/batch"
  "--model builtin --out exact/body.glb"
  "--model in/standin_smpl_stored.npz --out exact/standin.glb"
  "--model builtin $plain --out exact/plain.glb"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --out exact/fit.glb"
  "--model builtin --out exact/body.fbx"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --out exact/amass.fbx"
)
for args in "${exact[@]}"; do
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
[[ $compared -ge 22 ]] || fail "only $compared files compared"

msg=$(cd "$work/wasm" && { node "$js" --model in/nope.npz --out out/nope.glb 2>&1 >/dev/null || true; })
rc=$(cd "$work/wasm" && { node "$js" --model in/nope.npz --out out/nope.glb >/dev/null 2>&1; echo $?; })
[[ $rc -eq 2 && $msg == "Error loading in/nope.npz: cannot open: "* && $(wc -l <<<"$msg") -eq 1 ]] ||
  fail "a missing model: exit code $rc, '$msg'"
[[ ! -e $work/wasm/out/nope.glb ]] || fail "a failed export left out/nope.glb"
echo "PASS: $compared files byte-identical between smpl-export.js (node) and the native build; errors"
