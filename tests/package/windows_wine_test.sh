#!/usr/bin/env bash
# The Windows build (scripts/build-windows.sh: smpl-export.exe, mingw-w64) run
# under Debian's wine writes the same bytes as the Linux build: the built-in
# body (GLB, FBX), an .npz and a pickle model, AMASS motions baked (GLB, FBX,
# BVH), a .gltf with its .bin and meshopt, a MANO hand, and a batch of three
# motions with its manifest; each output and its .smpl.json sidecar compared
# with cmp. Then what only Windows has: paths with a drive letter and
# backslashes, non-ASCII file and folder names (UTF-8 on the command line,
# UTF-16 on disk), and the executable's imports (Windows' own DLLs only).
# Errors: a missing model gives the one-line error and exit code 2 and writes
# nothing; --draco is refused (this build has no Draco) with exit code 1.
#   windows_wine_test.sh WINDOWS_EXE LINUX_EXE FIXTURES WORK WINEPREFIX
set -euo pipefail
exe=$(realpath -m "$1") linux=$(realpath -m "$2") fixtures=$(realpath -m "$3") work=$(realpath -m "$4")
export WINEPREFIX=$5 WINEDEBUG=-all
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ -f $exe ]] || fail "no Windows build at '$exe' (configure the tests with -DSMPL_WINDOWS_BUILD_DIR=<build-windows>; scripts/test.sh runs scripts/build-windows.sh)"
command -v wine >/dev/null || fail "wine not found (Debian packages wine wine64: scripts/setup-deps.sh)"

# Imports: Windows' own DLLs only (libgcc, libstdc++, winpthread, zlib, libdeflate linked in).
dlls=$(x86_64-w64-mingw32-objdump -p "$exe" | awk '/DLL Name:/ {print tolower($3)}' | sort -u | tr '\n' ' ')
for d in $dlls; do
  case $d in
    kernel32.dll | msvcrt.dll | bcrypt.dll | shell32.dll | advapi32.dll | user32.dll | ws2_32.dll) ;;
    *) fail "smpl-export.exe imports $d (not a Windows system DLL; all imports: $dlls)" ;;
  esac
done

rm -rf "$work" && mkdir -p "$work/win/in" "$work/win/out" "$work/lin/in" "$work/lin/out"
for f in models/smpl_small.npz models/smpl_small_p2.pkl models/smplh_small.npz models/smplx_small.npz \
  models/mano_small.npz motions/smpl_72.npz motions/amass_smplh.npz motions/amass_smplx.npz; do
  cp "$fixtures/$f" "$work/win/in/" && cp "$fixtures/$f" "$work/lin/in/"
done
mkdir -p "$work/win/in/batch" "$work/lin/in/batch"
for side in win lin; do
  cp "$fixtures/motions/amass_smplh.npz" "$work/$side/in/batch/walk_a.npz"
  cp "$fixtures/motions/amass_smplh.npz" "$work/$side/in/batch/walk_b.npz"
  cp "$fixtures/motions/smpl_72.npz" "$work/$side/in/batch/short.npz"
done
wine "$exe" --version >/dev/null 2>&1 || true  # the first start makes the prefix (seconds)
version=$(wine "$exe" --version 2>/dev/null | tr -d '\r')
[[ $version == "$("$linux" --version)" ]] || fail "smpl-export.exe --version says '$version'"

# The same relative command lines on both sides (sidecars record the names given).
runs=(
  "--model builtin --out out/body.glb"
  "--model builtin --out out/body.fbx"
  "--model in/smpl_small.npz --betas 0.5,-1.2,0.3 --motion in/smpl_72.npz --out out/walk.glb"
  "--model in/smplx_small.npz --motion in/amass_smplx.npz --out out/amass.fbx"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --out out/amass.bvh"
  "--model in/smpl_small_p2.pkl --betas 0.5,-1.2,0.3 --out out/pickle.glb"
  "--model in/smplh_small.npz --motion in/amass_smplh.npz --meshopt --out out/meshopt.gltf"
  "--model in/mano_small.npz --out out/hand.glb"
  "--model in/smplh_small.npz --motion-dir in/batch --out-dir out/batch --manifest out/manifest.jsonl"
)
for args in "${runs[@]}"; do
  # shellcheck disable=SC2086
  (cd "$work/win" && wine "$exe" $args --quiet) || fail "Windows build: smpl-export $args (exit $?)"
  # shellcheck disable=SC2086
  (cd "$work/lin" && "$linux" $args --quiet) || fail "Linux build: smpl-export $args (exit $?)"
done
# The manifest records each motion's time and the paths as each OS joins
# them: equal once the seconds are dropped and backslashes read as slashes.
norm() { sed -e 's/"seconds":[0-9.e+-]*,//' -e 's|\\\\|/|g' "$1"; }
cmp <(norm "$work/win/out/manifest.jsonl") <(norm "$work/lin/out/manifest.jsonl") ||
  fail "the batch manifests differ (beyond seconds and separators)"
rm "$work/win/out/manifest.jsonl" "$work/lin/out/manifest.jsonl"
compared=0
while IFS= read -r f; do
  [[ -f $work/win/out/$f ]] || fail "the Windows build wrote no $f"
  cmp "$work/win/out/$f" "$work/lin/out/$f" || fail "$f differs between the Windows and the Linux build"
  compared=$((compared + 1))
done < <(cd "$work/lin/out" && find . -type f | sed 's|^\./||' | sort)
extra=$(cd "$work/win/out" && find . -type f | wc -l)
[[ $extra -eq $compared ]] || fail "the Windows build wrote $extra files, the Linux build $compared"
[[ $compared -ge 23 ]] || fail "only $compared files compared"

# A drive letter, backslashes, non-ASCII folder and file names: the same body.
name="Jürgen 模型"
mkdir -p "$work/win/in/wö" "$work/win/out/動き" "$work/lin/out/u"
cp "$fixtures/models/smpl_small.npz" "$work/win/in/wö/$name.npz"
drive="Z:$(cd "$work/win" && pwd | tr '/' '\\')"
wine "$exe" --quiet --model "$drive\\in\\wö\\$name.npz" --out "$drive\\out\\動き\\$name.glb" ||
  fail "Windows build: a model and an output named '$name' under $drive (exit $?)"
"$linux" --quiet --model "$work/win/in/wö/$name.npz" --out "$work/lin/out/u/$name.glb"
[[ -f "$work/win/out/動き/$name.glb" && -f "$work/win/out/動き/$name.glb.smpl.json" ]] ||
  fail "no '動き/$name.glb' with its sidecar (found: $(ls "$work/win/out/動き" | tr '\n' ' '))"
cmp "$work/win/out/動き/$name.glb" "$work/lin/out/u/$name.glb" || fail "'$name.glb' differs"
grep -q "\"$name.glb\"" "$work/win/out/動き/$name.glb.smpl.json" || fail "the sidecar does not name '$name.glb'"
# A non-ASCII batch folder: its motions found and converted under their names.
mkdir -p "$work/win/in/bätch"
cp "$fixtures/motions/smpl_72.npz" "$work/win/in/bätch/läufer_走る.npz"
(cd "$work/win" && wine "$exe" --quiet --model in/smpl_small.npz --motion-dir "in\\bätch" --out-dir "out\\bätch") ||
  fail "Windows build: batch of a non-ASCII folder (exit $?)"
[[ -f "$work/win/out/bätch/läufer_走る.glb" ]] || fail "batch of 'bätch' wrote: $(ls "$work/win/out/bätch" 2>&1 | tr '\n' ' ')"

# Errors: one line naming the file, the loader's exit code, nothing written.
msg=$(cd "$work/win" && { wine "$exe" --model 'in\nope.npz' --out out/nope.glb 2>&1 >/dev/null || true; } | tr -d '\r')
rc=$(cd "$work/win" && { wine "$exe" --model 'in\nope.npz' --out out/nope.glb >/dev/null 2>&1; echo $?; })
[[ $rc -eq 2 ]] || fail "a missing model: exit code $rc, expected 2"
[[ $msg == "Error loading in\\nope.npz: cannot open: "* && $(wc -l <<<"$msg") -eq 1 ]] ||
  fail "a missing model: '$msg'"
[[ ! -e $work/win/out/nope.glb ]] || fail "a failed export left out/nope.glb"
msg=$(cd "$work/win" && wine "$exe" --model builtin --draco --out out/d.glb 2>&1 | tr -d '\r' || true)
rc=$(cd "$work/win" && { wine "$exe" --model builtin --draco --out out/d.glb >/dev/null 2>&1; echo $?; })
[[ $rc -eq 1 && $msg == *"--draco: this smpl-export was built without Draco"* ]] ||
  fail "--draco: exit code $rc, '$msg'"
echo "PASS: $compared files byte-identical between smpl-export.exe under wine and the Linux build; non-ASCII and drive-letter paths; errors"
