#!/usr/bin/env bash
# The static binary (SMPL_STATIC=ON) runs in an empty root filesystem that
# holds only itself, its inputs and an output folder (no /lib, no loader, no
# /dev, no /proc), and writes the same bytes as the Debian (dynamic) build:
# the built-in body as GLB and FBX, a synthetic SMPL model (.npz) with a
# motion baked, as GLB and FBX, and a Python 2 pickle of it as GLB; each
# output and its .smpl.json sidecar compared with cmp. chroot needs root; as
# another user the test runs it in a user namespace (unshare -r) and fails,
# naming both, when neither is possible.
#   static_chroot_test.sh STATIC_EXE DYNAMIC_EXE FIXTURES WORK
set -euo pipefail
static=$1 dynamic=$2 fixtures=$3 work=$4
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ -x $static ]] || fail "no static binary at '$static' (configure the tests with -DSMPL_STATIC_BUILD_DIR=<a SMPL_STATIC=ON build>; scripts/test.sh builds build-static)"

# No program interpreter, no shared library.
if readelf -lW "$static" | grep "Requesting program interpreter"; then
  fail "$static asks for a program interpreter (not static)"
fi
if readelf -dW "$static" 2>/dev/null | grep "(NEEDED)"; then
  fail "$static needs shared libraries: $(readelf -dW "$static" | grep NEEDED | tr -s ' ' | tr '\n' ';')"
fi

rm -rf "$work" && mkdir -p "$work/root/bin" "$work/root/in" "$work/root/out" "$work/host/in" "$work/host/out"
cp "$static" "$work/root/bin/smpl-export"
for f in "$fixtures/models/smpl_small.npz" "$fixtures/models/smpl_small_p2.pkl" "$fixtures/motions/smpl_72.npz"; do
  cp "$f" "$work/root/in/" && cp "$f" "$work/host/in/"
done

# The same relative command lines in both: chroot starts in its "/", the
# dynamic build in host/ (sidecars record the names given).
runs=(
  "--model builtin --out out/body.glb"
  "--model builtin --out out/body.fbx"
  "--model in/smpl_small.npz --betas 0.5,-1.2,0.3 --motion in/smpl_72.npz --out out/walk.glb"
  "--model in/smpl_small.npz --betas 0.5,-1.2,0.3 --motion in/smpl_72.npz --out out/walk.fbx"
  "--model in/smpl_small_p2.pkl --betas 0.5,-1.2,0.3 --out out/pickle.glb"
)
if [[ $(id -u) -eq 0 ]]; then
  chroot_cmd=(chroot "$work/root")
elif unshare -r true 2>/dev/null; then
  chroot_cmd=(unshare -r chroot "$work/root")
else
  fail "cannot chroot: not root (uid $(id -u)) and no user namespace (unshare -r failed)"
fi
found=$(cd "$work/root" && find . -mindepth 1 -not -path './in*' -not -path './out*' | sort | tr '\n' ' ')
[[ $found == "./bin ./bin/smpl-export " ]] || fail "the root holds more than the binary: $found"

for args in "${runs[@]}"; do
  # shellcheck disable=SC2086
  "${chroot_cmd[@]}" /bin/smpl-export $args --quiet || fail "in the empty root: smpl-export $args (exit $?)"
  # shellcheck disable=SC2086
  (cd "$work/host" && "$dynamic" $args --quiet) || fail "dynamic build: smpl-export $args (exit $?)"
done
compared=0
for f in body.glb body.fbx walk.glb walk.fbx pickle.glb; do
  for g in "$f" "$f.smpl.json"; do
    [[ -s $work/root/out/$g ]] || fail "the static run wrote no $g"
    cmp "$work/root/out/$g" "$work/host/out/$g" || fail "$g differs between the static and the dynamic build"
    compared=$((compared + 1))
  done
done
echo "static binary in an empty root: ${#runs[@]} exports, $compared files byte-identical to the dynamic build's"
